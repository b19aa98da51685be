#include "pirouette/io/map_file.h"

#include <fmt/format.h>

#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <stdexcept>
#include <string_view>
#include <system_error>
#include <utility>
#include <vector>

#include "pirouette/core/input_error.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/io/yaml_fields.h"
#include "pirouette/mapping/occupancy_grid.h"

namespace pirouette::io {
namespace {

namespace fs = std::filesystem;
using mapping::CellState;

// Larger images are refused rather than allocated: a side of 2^20 cells is
// 52 km at 5 cm a cell.
constexpr std::uint64_t kMaxSide = 1U << 20;
constexpr std::uint64_t kMaxPixels = 1U << 28;

// A picture as map_server sees it, row-major, the first row the top: each
// pixel's colour channels averaged (0..maxval), and its alpha (0 transparent,
// maxval opaque) where the picture has an alpha channel.
struct GreyImage {
  int width = 0;
  int height = 0;
  double maxval = 255.0;
  std::vector<double> values;
  std::vector<double> alpha;  // empty: no alpha channel
};

unsigned char PgmValue(CellState state) {
  switch (state) {
    case CellState::kFree:
      return kPgmFree;
    case CellState::kOccupied:
      return kPgmOccupied;
    case CellState::kUnknown:
      break;
  }
  return kPgmUnknown;
}

// `name` as a YAML scalar: plain when it is a simple file name, else quoted.
std::string YamlScalar(const std::string& name) {
  const auto plain_char = [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_' || c == '.' || c == '-' ||
           c == '/';
  };
  bool plain = !name.empty() && name.front() != '-';
  for (const char c : name) plain = plain && plain_char(c);
  if (plain) return name;
  std::string quoted = "\"";
  for (const char c : name) {
    if (c == '"' || c == '\\') quoted += '\\';
    quoted += c;
  }
  return quoted + "\"";
}

// The bytes of the file at `path`, or an InputError naming `file` at `line`
// and `field` (the YAML field that named the file, when there is one).
std::string ReadBytes(const std::string& path, const std::string& file, int line,
                      const std::string& field) {
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) throw core::InputError(file, line, field, "no such file: " + path);
  if (fs::is_directory(status)) {
    throw core::InputError(file, line, field, "is a folder, not a file: " + path);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) {
    throw core::InputError(file, line, field, "cannot open " + path + ": " + std::strerror(errno));
  }
  std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw core::InputError(file, line, field, "cannot read " + path);
  return bytes;
}

// Reads the header and pixels of a PGM (Netpbm: P5 binary, P2 plain). Errors
// name the image file and the part of it that is wrong.
class PgmParser {
 public:
  PgmParser(std::string_view bytes, std::string path) : bytes_(bytes), path_(std::move(path)) {}

  GreyImage Parse() {
    const bool binary = bytes_.substr(0, 2) == "P5";
    pos_ = 2;
    GreyImage image;
    image.width = static_cast<int>(ReadNumber("width", 1, kMaxSide));
    image.height = static_cast<int>(ReadNumber("height", 1, kMaxSide));
    const std::uint64_t pixels = static_cast<std::uint64_t>(image.width) * image.height;
    if (pixels > kMaxPixels) {
      Fail("height", fmt::format("{} x {} pixels is more than the {} allowed", image.width,
                                 image.height, kMaxPixels));
    }
    const std::uint64_t maxval = ReadNumber("maxval", 1, 65535);
    image.maxval = static_cast<double>(maxval);
    if (binary) {
      ReadBinaryPixels(image, pixels, maxval);
    } else {
      ReadPlainPixels(image, pixels, maxval);
    }
    return image;
  }

 private:
  [[noreturn]] void Fail(const std::string& field, const std::string& problem) const {
    throw core::InputError(path_, 0, field, "malformed PGM: " + problem);
  }

  void SkipSpaceAndComments() {
    while (pos_ < bytes_.size()) {
      if (bytes_[pos_] == '#') {
        while (pos_ < bytes_.size() && bytes_[pos_] != '\n') ++pos_;
      } else if (std::isspace(static_cast<unsigned char>(bytes_[pos_])) != 0) {
        ++pos_;
      } else {
        break;
      }
    }
  }

  // A decimal whole number in [low, high], after whitespace and comments.
  std::uint64_t ReadNumber(const std::string& field, std::uint64_t low, std::uint64_t high) {
    SkipSpaceAndComments();
    const std::size_t start = pos_;
    std::uint64_t value = 0;
    while (pos_ < bytes_.size() && std::isdigit(static_cast<unsigned char>(bytes_[pos_])) != 0) {
      if (value <= high) value = value * 10 + static_cast<std::uint64_t>(bytes_[pos_] - '0');
      ++pos_;
    }
    if (pos_ == start) {
      Fail(field, pos_ == bytes_.size() ? "expected a whole number, got the end of the file"
                                        : "expected a whole number");
    }
    if (value < low || value > high) {
      Fail(field,
           fmt::format("{} is not in {}..{}", bytes_.substr(start, pos_ - start), low, high));
    }
    return value;
  }

  void ReadBinaryPixels(GreyImage& image, std::uint64_t pixels, std::uint64_t maxval) {
    if (pos_ >= bytes_.size() || std::isspace(static_cast<unsigned char>(bytes_[pos_])) == 0) {
      Fail("maxval", "expected one whitespace character after maxval");
    }
    ++pos_;
    const std::uint64_t bytes_per_pixel = maxval < 256 ? 1 : 2;
    const std::uint64_t needed = pixels * bytes_per_pixel;
    const std::uint64_t available = bytes_.size() - pos_;
    if (available < needed) {
      Fail("pixels", fmt::format("truncated: {} bytes of pixels for {} x {}, got {}", needed,
                                 image.width, image.height, available));
    }
    image.values.resize(pixels);
    const auto* data = reinterpret_cast<const unsigned char*>(bytes_.data() + pos_);
    for (std::uint64_t i = 0; i < pixels; ++i) {
      const std::uint64_t v =
          bytes_per_pixel == 1 ? data[i]
                               : (static_cast<std::uint64_t>(data[2 * i]) << 8) | data[2 * i + 1];
      if (v > maxval) BadPixel(image, i, v, maxval);
      image.values[i] = static_cast<double>(v);
    }
  }

  void ReadPlainPixels(GreyImage& image, std::uint64_t pixels, std::uint64_t maxval) {
    image.values.reserve(std::min<std::uint64_t>(pixels, bytes_.size()));
    for (std::uint64_t i = 0; i < pixels; ++i) {
      SkipSpaceAndComments();
      if (pos_ == bytes_.size()) {
        Fail("pixels", fmt::format("truncated: {} pixel values for {} x {}, got {}", pixels,
                                   image.width, image.height, i));
      }
      const std::uint64_t v = ReadNumber("pixels", 0, 65535);
      if (v > maxval) BadPixel(image, i, v, maxval);
      image.values.push_back(static_cast<double>(v));
    }
  }

  [[noreturn]] void BadPixel(const GreyImage& image, std::uint64_t i, std::uint64_t v,
                             std::uint64_t maxval) const {
    const auto width = static_cast<std::uint64_t>(image.width);
    Fail("pixels", fmt::format("the pixel at row {}, column {} is {}, more than maxval {}",
                               i / width, i % width, v, maxval));
  }

  std::string_view bytes_;
  std::string path_;
  std::size_t pos_ = 0;
};

// Any other picture, through OpenCV: colour channels averaged, alpha kept apart.
GreyImage DecodeOtherImage(const std::string& bytes, const std::string& path) {
  CheckImageSize(path, bytes);
  const std::vector<unsigned char> buffer(bytes.begin(), bytes.end());
  const cv::Mat decoded = buffer.empty() ? cv::Mat() : cv::imdecode(buffer, cv::IMREAD_UNCHANGED);
  if (decoded.empty()) {
    throw core::InputError(path, 0, "",
                           "not an image that can be read (expected a PGM, a PNG or another "
                           "picture OpenCV reads)");
  }
  if (decoded.depth() != CV_8U && decoded.depth() != CV_16U) {
    throw core::InputError(path, 0, "", "expected 8 or 16 bits a channel");
  }
  if (static_cast<std::uint64_t>(decoded.total()) > kMaxPixels) {
    throw core::InputError(path, 0, "", "the image is too large");
  }
  cv::Mat values;
  decoded.convertTo(values, CV_64F);
  const int channels = values.channels();
  const int colours = (channels == 2 || channels == 4) ? channels - 1 : channels;
  GreyImage image;
  image.width = values.cols;
  image.height = values.rows;
  image.maxval = decoded.depth() == CV_8U ? 255.0 : 65535.0;
  image.values.reserve(values.total());
  if (colours < channels) image.alpha.reserve(values.total());
  for (int r = 0; r < values.rows; ++r) {
    const double* row = values.ptr<double>(r);
    for (int c = 0; c < values.cols; ++c) {
      double sum = 0.0;
      for (int k = 0; k < colours; ++k) sum += row[c * channels + k];
      image.values.push_back(sum / colours);
      if (colours < channels) image.alpha.push_back(row[c * channels + colours]);
    }
  }
  return image;
}

GreyImage DecodeImage(const std::string& bytes, const std::string& path) {
  const std::string_view magic = std::string_view(bytes).substr(0, 2);
  if (magic == "P5" || magic == "P2") return PgmParser(bytes, path).Parse();
  return DecodeOtherImage(bytes, path);
}

double ReadProbability(const std::string& file, const io::YamlField& field) {
  const double value = io::ReadNumber(file, field);
  if (value < 0.0 || value > 1.0) {
    io::ThrowInputError(file, field, fmt::format("expected a number in 0..1, got {}", value));
  }
  return value;
}

bool ReadNegate(const std::string& file, const io::YamlField& field) {
  if (field.node.IsScalar() && io::ScalarKindOf(field.node) == io::ScalarKind::kBool) {
    const std::string& s = field.node.Scalar();
    return s == "true" || s == "True" || s == "TRUE";
  }
  if (field.node.IsScalar() && io::ScalarKindOf(field.node) == io::ScalarKind::kNumber) {
    const double value = io::ReadNumber(file, field);
    if (value == 0.0 || value == 1.0) return value == 1.0;
  }
  io::ThrowInputError(file, field,
                      "expected 0 or 1 (or false or true), got " + io::DescribeNode(field.node));
}

}  // namespace

std::string RosMapYaml(const mapping::TrinaryMap& map, const std::string& image_name) {
  const core::GridGeometry& g = map.geometry;
  return fmt::format(
      "image: {}\nmode: trinary\nresolution: {}\norigin: [{}, {}, 0]\nnegate: 0\n"
      "occupied_thresh: {}\nfree_thresh: {}\n",
      YamlScalar(image_name), g.resolution(), g.origin().x(), g.origin().y(),
      mapping::kOccupiedThreshold, mapping::kFreeThreshold);
}

std::string RosMapPgm(const mapping::TrinaryMap& map) {
  const core::GridGeometry& g = map.geometry;
  if (map.cells.size() != g.CellCount()) {
    throw std::invalid_argument("RosMapPgm: the map's cells do not match its geometry");
  }
  std::string pgm = fmt::format("P5\n{} {}\n255\n", g.width(), g.height());
  const std::size_t header = pgm.size();
  pgm.resize(header + g.CellCount());
  std::size_t at = header;
  for (int y = g.height() - 1; y >= 0; --y) {
    for (int x = 0; x < g.width(); ++x) {
      pgm[at++] = static_cast<char>(PgmValue(map.At({x, y})));
    }
  }
  return pgm;
}

void WriteRosMap(const mapping::TrinaryMap& map, const std::string& yaml_path) {
  const fs::path yaml(yaml_path);
  if (!yaml.has_filename()) {
    throw std::invalid_argument("WriteRosMap: '" + yaml_path + "' names no file");
  }
  if (yaml.extension() == ".pgm") {
    throw std::invalid_argument("WriteRosMap: '" + yaml_path +
                                "' ends in .pgm, the name of the image beside it");
  }
  fs::path pgm = yaml;
  pgm.replace_extension(".pgm");
  WriteFileAtomically(pgm.string(), RosMapPgm(map));
  WriteFileAtomically(yaml.string(), RosMapYaml(map, pgm.filename().string()));
}

namespace {

MapMode ReadMode(const std::string& file, const io::YamlMap& fields) {
  const auto mode = fields.Optional("mode");
  if (!mode) return MapMode::kTrinary;
  const std::string name = io::ReadName(file, *mode);
  if (name == "trinary") return MapMode::kTrinary;
  if (name == "scale") return MapMode::kScale;
  if (name == "raw") return MapMode::kRaw;
  io::ThrowInputError(file, *mode,
                      "unknown mode '" + name + "' (map_server knows trinary, scale, raw)");
}

// One pixel's cell value, as nav2's map_io (loadMapFromFile) computes it.
std::int8_t CellValue(MapMode mode, double grey, const double* alpha, double maxval, bool negate,
                      double occupied_thresh, double free_thresh) {
  // Trinary mode averages the alpha in with the colour channels (3 of them,
  // a grey picture's being equal), as map_server does "to preserve existing
  // behaviour"; scale mode makes every pixel that is not opaque unknown.
  double shade = grey / maxval;
  if (mode == MapMode::kTrinary && alpha != nullptr) shade = (3.0 * grey + *alpha) / (4.0 * maxval);
  const double occ = negate ? shade : 1.0 - shade;
  switch (mode) {
    case MapMode::kTrinary:
      if (occupied_thresh < occ) return kMapOccupied;
      if (occ < free_thresh) return kMapFree;
      return kMapUnknown;
    case MapMode::kScale:
      if (alpha != nullptr && *alpha < maxval) return kMapUnknown;
      if (occupied_thresh < occ) return kMapOccupied;
      if (occ < free_thresh) return kMapFree;
      return static_cast<std::int8_t>(
          std::rint((occ - free_thresh) / (occupied_thresh - free_thresh) * 100.0));
    case MapMode::kRaw: {
      const double value = std::round(shade * 255.0);  // negate plays no part, as in map_server
      if (value >= 0.0 && value <= 100.0) return static_cast<std::int8_t>(value);
      return kMapUnknown;
    }
  }
  return kMapUnknown;
}

}  // namespace

MapServerMap ReadMapServerMap(const std::string& yaml_path) {
  const std::string& file = yaml_path;
  const YAML::Node root = io::LoadYamlFile(file);
  const io::YamlMap fields(file, io::YamlField{root, "", io::LineOf(root)});

  const io::YamlField image_field = fields.Required("image");
  const std::string image_name = io::ReadName(file, image_field);
  const MapMode mode = ReadMode(file, fields);

  const io::YamlField resolution_field = fields.Required("resolution");
  const double resolution = io::ReadNumber(file, resolution_field);
  if (!(resolution > 0.0) || !std::isfinite(resolution)) {
    io::ThrowInputError(file, resolution_field,
                        fmt::format("expected a positive number, got {}", resolution));
  }

  const io::YamlField origin_field = fields.Required("origin");
  const io::NumberList origin = io::ReadNumbers(file, origin_field, 3);
  if (origin.values[2] != 0.0) {
    io::ThrowInputError(
        file, origin.items[2],
        fmt::format("item 3 of 3: a rotated map (yaw {}) is not supported; expected 0",
                    origin.values[2]));
  }

  const bool negate = ReadNegate(file, fields.Required("negate"));
  const double occupied_thresh = ReadProbability(file, fields.Required("occupied_thresh"));
  const io::YamlField free_field = fields.Required("free_thresh");
  const double free_thresh = ReadProbability(file, free_field);
  if (free_thresh > occupied_thresh) {
    io::ThrowInputError(
        file, free_field,
        fmt::format("{} is more than occupied_thresh {}", free_thresh, occupied_thresh));
  }

  fs::path image_path(image_name);
  if (image_path.is_relative()) image_path = fs::path(file).parent_path() / image_path;
  const std::string image_file = image_path.string();
  const GreyImage image =
      DecodeImage(ReadBytes(image_file, file, image_field.line, image_field.path), image_file);

  MapServerMap map{core::GridGeometry(resolution, {origin.values[0], origin.values[1]}, image.width,
                                      image.height),
                   mode,
                   {}};
  map.cells.resize(map.geometry.CellCount(), kMapUnknown);
  const bool has_alpha = !image.alpha.empty();
  std::size_t i = 0;
  for (int y = image.height - 1; y >= 0; --y) {
    for (int x = 0; x < image.width; ++x, ++i) {
      map.cells[map.geometry.Flat({x, y})] =
          CellValue(mode, image.values[i], has_alpha ? &image.alpha[i] : nullptr, image.maxval,
                    negate, occupied_thresh, free_thresh);
    }
  }
  return map;
}

mapping::TrinaryMap ReadRosMap(const std::string& yaml_path) {
  {
    // The mode first, before the image is read: a scale map gets that said.
    const YAML::Node root = io::LoadYamlFile(yaml_path);
    const io::YamlMap fields(yaml_path, io::YamlField{root, "", io::LineOf(root)});
    const MapMode mode = ReadMode(yaml_path, fields);
    if (mode != MapMode::kTrinary) {
      io::ThrowInputError(yaml_path, *fields.Optional("mode"),
                          std::string("mode '") + (mode == MapMode::kScale ? "scale" : "raw") +
                              "' is not supported here: a pirouette map is trinary");
    }
  }
  const MapServerMap read = ReadMapServerMap(yaml_path);
  mapping::TrinaryMap map{read.geometry, {}};
  map.cells.resize(read.cells.size(), CellState::kUnknown);
  for (std::size_t k = 0; k < read.cells.size(); ++k) {
    if (read.cells[k] == kMapFree) map.cells[k] = CellState::kFree;
    if (read.cells[k] == kMapOccupied) map.cells[k] = CellState::kOccupied;
  }
  return map;
}

}  // namespace pirouette::io
