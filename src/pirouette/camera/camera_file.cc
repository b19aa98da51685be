#include "pirouette/camera/camera_file.h"

#include <fcntl.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <initializer_list>
#include <iterator>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <system_error>
#include <vector>

#include <fmt/format.h>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"

namespace pirouette::camera {
namespace {

// ---------------------------------------------------------------------------
// Reading checked values out of YAML. (sim/world_file.cc holds the same small
// toolkit; the two files are the only YAML readers of the input formats.)

// The 1-based line of a node, or 0 when yaml-cpp knows none.
int LineOf(const YAML::Node& node) {
  const YAML::Mark mark = node.Mark();
  return mark.is_null() ? 0 : mark.line + 1;
}

std::string JoinPath(const std::string& prefix, std::string_view key) {
  return prefix.empty() ? std::string(key) : prefix + "." + std::string(key);
}

// A value in a file: the node, its dotted path for messages ("mount.tilt")
// and the line to report problems with it at.
struct Field {
  YAML::Node node;
  std::string path;
  int line = 0;
};

[[noreturn]] void Fail(const std::string& file, int line, const std::string& path,
                       const std::string& problem) {
  throw core::InputError(file, line, path, problem);
}

[[noreturn]] void Fail(const std::string& file, const Field& field, const std::string& problem) {
  Fail(file, field.line, field.path, problem);
}

// What a plain (unquoted) scalar means under YAML 1.2's core schema.
enum class ScalarKind { kNull, kBool, kNumber, kString };

bool IsDecimal(std::string_view s) {
  std::size_t i = 0;
  const auto digits = [&] {
    const std::size_t start = i;
    while (i < s.size() && s[i] >= '0' && s[i] <= '9') ++i;
    return i - start;
  };
  if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
  std::size_t mantissa = digits();
  if (i < s.size() && s[i] == '.') {
    ++i;
    mantissa += digits();
  }
  if (mantissa == 0) return false;
  if (i < s.size() && (s[i] == 'e' || s[i] == 'E')) {
    ++i;
    if (i < s.size() && (s[i] == '+' || s[i] == '-')) ++i;
    if (digits() == 0) return false;
  }
  return i == s.size();
}

bool IsNonFinite(std::string_view s) {
  if (!s.empty() && (s[0] == '+' || s[0] == '-')) s.remove_prefix(1);
  return s == ".inf" || s == ".Inf" || s == ".INF" || s == ".nan" || s == ".NaN" || s == ".NAN";
}

ScalarKind KindOf(const YAML::Node& node) {
  if (node.IsNull()) return ScalarKind::kNull;
  if (node.Tag() == "!") return ScalarKind::kString;  // quoted: a string whatever it reads
  const std::string& s = node.Scalar();
  if (s.empty() || s == "~" || s == "null" || s == "Null" || s == "NULL") return ScalarKind::kNull;
  if (s == "true" || s == "True" || s == "TRUE" || s == "false" || s == "False" || s == "FALSE") {
    return ScalarKind::kBool;
  }
  if (IsDecimal(s) || IsNonFinite(s)) return ScalarKind::kNumber;
  return ScalarKind::kString;
}

// "a list", "the string 'abc'", ...: what a node is, for "expected X, got Y".
std::string Describe(const YAML::Node& node) {
  if (!node.IsDefined() || node.IsNull()) return "nothing";
  if (node.IsSequence()) return "a list";
  if (node.IsMap()) return "a map";
  switch (KindOf(node)) {
    case ScalarKind::kNull:
      return "nothing";
    case ScalarKind::kBool:
      return "the boolean " + node.Scalar();
    case ScalarKind::kNumber:
      return "the number " + node.Scalar();
    case ScalarKind::kString:
      break;
  }
  return "the string '" + node.Scalar() + "'";
}

// The keys of a map, checked: keys are plain strings, none twice.
class MapReader {
 public:
  MapReader(const std::string& file, const Field& field) : file_(file), field_(field) {
    if (!field.node.IsMap()) {
      Fail(file_, field_, "expected a map of fields, got " + Describe(field.node));
    }
    for (auto it = field.node.begin(); it != field.node.end(); ++it) {
      const YAML::Node key = it->first;
      const YAML::Node value = it->second;
      const int key_line = LineOf(key);
      if (!key.IsScalar()) {
        Fail(file_, key_line, field_.path, "a key must be a name, got " + Describe(key));
      }
      const std::string& name = key.Scalar();
      for (const Entry& entry : entries_) {
        if (entry.key == name) {
          Fail(file_, key_line, JoinPath(field_.path, name),
               fmt::format("duplicate key (first given on line {})", entry.key_line));
        }
      }
      entries_.push_back({name, value, key_line});
    }
  }

  // Refuses any key not in `allowed`.
  void AllowOnly(std::initializer_list<std::string_view> allowed) const {
    for (const Entry& entry : entries_) {
      if (std::find(allowed.begin(), allowed.end(), entry.key) == allowed.end()) {
        std::string known;
        for (const std::string_view key : allowed) {
          known += (known.empty() ? "" : ", ") + std::string(key);
        }
        Fail(file_, entry.key_line, JoinPath(field_.path, entry.key),
             "unknown key (known keys: " + known + ")");
      }
    }
  }

  std::optional<Field> Optional(std::string_view key) const {
    for (const Entry& entry : entries_) {
      if (entry.key == key) {
        // A null value's mark is where the next token starts: report the key's line.
        const int line = entry.value.IsNull() ? entry.key_line : LineOf(entry.value);
        return Field{entry.value, JoinPath(field_.path, key), line};
      }
    }
    return std::nullopt;
  }

  // A missing key is reported at the line of the map that lacks it.
  Field Required(std::string_view key) const {
    std::optional<Field> field = Optional(key);
    if (!field) Fail(file_, field_.line, JoinPath(field_.path, key), "missing required key");
    return *field;
  }

 private:
  struct Entry {
    std::string key;
    YAML::Node value;
    int key_line;
  };
  const std::string& file_;
  Field field_;
  std::vector<Entry> entries_;
};

MapReader ReadMap(const std::string& file, const Field& field,
                  std::initializer_list<std::string_view> allowed) {
  MapReader map(file, field);
  map.AllowOnly(allowed);
  return map;
}

// A finite number. `item` (e.g. "item 2 of 3: ") prefixes messages about one
// number of a list.
double ReadNumber(const std::string& file, const Field& field, const std::string& item = "") {
  const YAML::Node& node = field.node;
  if (!node.IsScalar() || KindOf(node) != ScalarKind::kNumber) {
    Fail(file, field, item + "expected a number, got " + Describe(node));
  }
  std::string_view text = node.Scalar();
  if (IsNonFinite(text)) Fail(file, field, item + "expected a finite number, got " + node.Scalar());
  if (text.front() == '+') text.remove_prefix(1);
  double value = 0.0;
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size() || !std::isfinite(value)) {
    Fail(file, field, item + "the number " + node.Scalar() + " is out of range");
  }
  return value;
}

// A whole number (written without a fractional part's worth: 3 and 3.0 pass, 3.5 does not).
int ReadWholeNumber(const std::string& file, const Field& field, const std::string& item = "") {
  const double value = ReadNumber(file, field, item);
  if (value != std::floor(value) || std::fabs(value) > 1e9) {
    Fail(file, field, item + "expected a whole number, got " + field.node.Scalar());
  }
  return static_cast<int>(value);
}

// The items of a list, each with its own line (the list's path is kept).
std::vector<Field> ReadList(const std::string& file, const Field& field, const std::string& what) {
  if (!field.node.IsSequence()) {
    Fail(file, field, "expected " + what + ", got " + Describe(field.node));
  }
  std::vector<Field> items;
  for (const YAML::Node& item : field.node) {
    const int line = LineOf(item);
    items.push_back({item, field.path, line > 0 ? line : field.line});
  }
  return items;
}

// A list of exactly `count` finite numbers, with the items they came from.
struct Numbers {
  std::vector<double> values;
  std::vector<Field> items;
};

Numbers ReadNumbers(const std::string& file, const Field& field, std::size_t count) {
  const std::string what = fmt::format("a list of {} numbers", count);
  Numbers numbers{{}, ReadList(file, field, what)};
  if (numbers.items.size() != count) {
    Fail(file, field, fmt::format("expected {}, got {} items", what, numbers.items.size()));
  }
  for (std::size_t i = 0; i < count; ++i) {
    numbers.values.push_back(
        ReadNumber(file, numbers.items[i], fmt::format("item {} of {}: ", i + 1, count)));
  }
  return numbers;
}

// Any scalar but null, as its text (ROS writes names unquoted; a name of
// digits is still a name).
std::string ReadName(const std::string& file, const Field& field) {
  if (!field.node.IsScalar() || KindOf(field.node) == ScalarKind::kNull) {
    Fail(file, field, "expected a string, got " + Describe(field.node));
  }
  return field.node.Scalar();
}

// ---------------------------------------------------------------------------
// The camera file.

constexpr std::string_view kSupportedDistortion = "plumb_bob";

// A ROS matrix {rows, cols, data} of `rows` × `cols` numbers (`cols` = 0:
// any number of columns, which the file's `cols` gives).
Numbers ReadMatrix(const std::string& file, const Field& field, int rows, int cols) {
  const MapReader map = ReadMap(file, field, {"rows", "cols", "data"});
  const Field rows_field = map.Required("rows");
  const Field cols_field = map.Required("cols");
  const Field data_field = map.Required("data");
  const int file_rows = ReadWholeNumber(file, rows_field);
  if (file_rows != rows) {
    Fail(file, rows_field, fmt::format("expected {}, got {}", rows, file_rows));
  }
  const int file_cols = ReadWholeNumber(file, cols_field);
  if ((cols > 0 && file_cols != cols) || file_cols <= 0) {
    Fail(file, cols_field,
         cols > 0 ? fmt::format("expected {}, got {}", cols, file_cols)
                  : fmt::format("must be > 0, got {}", file_cols));
  }
  const auto count = static_cast<std::size_t>(rows) * static_cast<std::size_t>(file_cols);
  const std::size_t items = ReadList(file, data_field, "a list of numbers").size();
  if (items != count) {
    Fail(file, data_field,
         fmt::format("rows × cols is {} × {} = {} but data holds {} numbers", rows, file_cols,
                     count, items));
  }
  return ReadNumbers(file, data_field, count);
}

CameraModel ParseCamera(const YAML::Node& node, const std::string& file,
                        const std::string& prefix) {
  const Field root{node, prefix, LineOf(node)};
  const MapReader map =
      ReadMap(file, root,
              {"image_width", "image_height", "camera_name", "camera_matrix", "distortion_model",
               "distortion_coefficients", "rectification_matrix", "projection_matrix", "mount",
               "vignetting"});

  int size[2] = {0, 0};
  const char* size_keys[2] = {"image_width", "image_height"};
  for (int i = 0; i < 2; ++i) {
    const Field field = map.Required(size_keys[i]);
    size[i] = ReadWholeNumber(file, field);
    if (size[i] <= 0) Fail(file, field, fmt::format("must be > 0, got {}", size[i]));
  }

  std::string name;
  if (const auto field = map.Optional("camera_name")) name = ReadName(file, *field);

  // camera_matrix: [fx 0 cx; 0 fy cy; 0 0 1], row-major.
  const Field k_field = map.Required("camera_matrix");
  const Numbers k_data = ReadMatrix(file, k_field, 3, 3);
  const std::vector<double>& k = k_data.values;
  const auto check_k = [&](int i, bool ok, std::string_view problem) {
    if (!ok) {
      const auto index = static_cast<std::size_t>(i);
      Fail(file, k_data.items[index],
           fmt::format("item {} of 9 is {}: {}", i + 1, k[index], problem));
    }
  };
  check_k(0, k[0] > 0.0, "fx must be > 0");
  check_k(1, k[1] == 0.0, "the skew must be 0 (pirouette's camera model has none)");
  check_k(3, k[3] == 0.0, "must be 0 (the matrix is [fx 0 cx; 0 fy cy; 0 0 1])");
  check_k(4, k[4] > 0.0, "fy must be > 0");
  check_k(6, k[6] == 0.0, "must be 0 (the matrix's last row is [0 0 1])");
  check_k(7, k[7] == 0.0, "must be 0 (the matrix's last row is [0 0 1])");
  check_k(8, k[8] == 1.0, "must be 1 (the matrix's last row is [0 0 1])");
  const Intrinsics intrinsics{k[0], k[4], k[2], k[5]};

  const Field model_field = map.Required("distortion_model");
  const std::string model = ReadName(file, model_field);
  if (model != kSupportedDistortion) {
    Fail(file, model_field,
         fmt::format("unsupported distortion model '{}'; pirouette reads {} only", model,
                     kSupportedDistortion));
  }
  const Field d_field = map.Required("distortion_coefficients");
  const Field d_data_field = ReadMap(file, d_field, {"rows", "cols", "data"}).Required("data");
  const std::size_t d_count = ReadList(file, d_data_field, "a list of numbers").size();
  if (d_count != 5) {
    Fail(file, d_data_field,
         fmt::format("plumb_bob takes 5 coefficients (k1, k2, p1, p2, k3), got {}", d_count));
  }
  const std::vector<double> d = ReadMatrix(file, d_field, 1, 5).values;
  const PlumbBob distortion{d[0], d[1], d[2], d[3], d[4]};

  const MapReader mount_map = ReadMap(file, map.Required("mount"), {"height", "tilt", "forward"});
  Mount mount;
  const Field height_field = mount_map.Required("height");
  mount.height_m = ReadNumber(file, height_field);
  if (!(mount.height_m > 0.0)) {
    Fail(file, height_field,
         fmt::format("must be > 0 (metres above the floor), got {}", mount.height_m));
  }
  const Field tilt_field = mount_map.Required("tilt");
  const double tilt_deg = ReadNumber(file, tilt_field);
  if (!(tilt_deg > -90.0 && tilt_deg < 90.0)) {
    Fail(file, tilt_field, fmt::format("must lie in (-90, 90) degrees, got {}", tilt_deg));
  }
  mount.tilt_rad = core::DegToRad(tilt_deg);
  if (const auto field = mount_map.Optional("forward")) mount.forward_m = ReadNumber(file, *field);

  Vignetting vignetting;
  if (const auto field = map.Optional("vignetting")) {
    const Field k_gain = ReadMap(file, *field, {"k"}).Required("k");
    const Numbers values = ReadNumbers(file, k_gain, 3);
    for (std::size_t i = 0; i < 3; ++i) {
      if (values.values[i] < 0.0) {
        Fail(file, values.items[i],
             fmt::format("item {} of 3: must be >= 0, got {}", i + 1, values.values[i]));
      }
      vignetting.k[i] = values.values[i];
    }
  }

  // rectification_matrix and projection_matrix are accepted and ignored (SPEC.md).
  return {name, size[0], size[1], intrinsics, distortion, mount, vignetting};
}

// The whole of a file, or an InputError naming it.
std::string ReadFileText(const std::string& path) {
  namespace fs = std::filesystem;
  std::error_code error;
  const fs::file_status status = fs::status(path, error);
  if (!fs::exists(status)) Fail(path, 0, "", "no such file");
  if (fs::is_directory(status)) Fail(path, 0, "", "is a folder, not a file");
  std::ifstream in(path, std::ios::binary);
  if (!in) Fail(path, 0, "", std::string("cannot open: ") + std::strerror(errno));
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) Fail(path, 0, "", "cannot read");
  return text;
}

// Parses YAML text; malformed YAML or an empty document is an InputError.
YAML::Node ParseYaml(const std::string& text, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::Load(text);
  } catch (const YAML::ParserException& e) {
    Fail(file, e.mark.is_null() ? 0 : e.mark.line + 1, "", "malformed YAML: " + e.msg);
  } catch (const YAML::Exception& e) {
    Fail(file, 0, "", std::string("malformed YAML: ") + e.what());
  }
  if (!root.IsDefined() || root.IsNull()) Fail(file, 0, "", "the file is empty");
  return root;
}

// The shortest decimal text that reads back as `value` exactly.
std::string NumberText(double value) { return fmt::format("{}", value); }

// The tilt in degrees, as the shortest decimal whose conversion to radians
// gives `tilt_rad` back exactly (when one exists; the nearest otherwise).
std::string TiltText(double tilt_rad) {
  const double degrees = core::RadToDeg(tilt_rad);
  for (int precision = 1; precision <= 17; ++precision) {
    const std::string text = fmt::format("{:.{}g}", degrees, precision);
    double parsed = 0.0;
    std::from_chars(text.data(), text.data() + text.size(), parsed);
    if (core::DegToRad(parsed) == tilt_rad) return NumberText(parsed);
  }
  return NumberText(degrees);
}

void EmitNumbers(YAML::Emitter& out, std::initializer_list<double> values) {
  out << YAML::Flow << YAML::BeginSeq;
  for (const double value : values) out << NumberText(value);
  out << YAML::EndSeq;
}

void EmitMatrix(YAML::Emitter& out, std::string_view key, int rows, int cols,
                std::initializer_list<double> data) {
  out << YAML::Key << std::string(key) << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "rows" << YAML::Value << rows;
  out << YAML::Key << "cols" << YAML::Value << cols;
  out << YAML::Key << "data" << YAML::Value;
  EmitNumbers(out, data);
  out << YAML::EndMap;
}

std::string CameraText(const CameraModel& camera) {
  const Intrinsics& in = camera.intrinsics();
  const PlumbBob& d = camera.distortion();
  const Mount& mount = camera.mount();
  const auto& k = camera.vignetting().k;

  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "image_width" << YAML::Value << camera.width();
  out << YAML::Key << "image_height" << YAML::Value << camera.height();
  out << YAML::Key << "camera_name" << YAML::Value;
  // A name that would read back as a number, boolean or nothing is quoted.
  const YAML::Node plain(camera.name());
  if (camera.name().empty() || KindOf(plain) == ScalarKind::kNull) out << YAML::DoubleQuoted;
  out << camera.name();
  EmitMatrix(out, "camera_matrix", 3, 3, {in.fx, 0.0, in.cx, 0.0, in.fy, in.cy, 0.0, 0.0, 1.0});
  out << YAML::Key << "distortion_model" << YAML::Value << std::string(kSupportedDistortion);
  EmitMatrix(out, "distortion_coefficients", 1, 5, {d.k1, d.k2, d.p1, d.p2, d.k3});
  // What ROS tools expect of a monocular camera; pirouette ignores both.
  EmitMatrix(out, "rectification_matrix", 3, 3, {1, 0, 0, 0, 1, 0, 0, 0, 1});
  EmitMatrix(out, "projection_matrix", 3, 4,
             {in.fx, 0.0, in.cx, 0.0, 0.0, in.fy, in.cy, 0.0, 0.0, 0.0, 1.0, 0.0});
  out << YAML::Key << "mount" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "height" << YAML::Value << NumberText(mount.height_m);
  out << YAML::Key << "tilt" << YAML::Value << TiltText(mount.tilt_rad);
  out << YAML::Key << "forward" << YAML::Value << NumberText(mount.forward_m);
  out << YAML::EndMap;
  out << YAML::Key << "vignetting" << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "k" << YAML::Value;
  EmitNumbers(out, {k[0], k[1], k[2]});
  out << YAML::EndMap;
  out << YAML::EndMap;
  if (!out.good()) throw std::logic_error("SaveCameraFile: YAML emitter: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

// Writes `text` to a temporary file beside `path`, flushed, then renamed over it.
void WriteAtomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp-" + std::to_string(::getpid());
  const auto fail = [&](const char* what) {
    const std::string reason = std::strerror(errno);
    ::unlink(tmp.c_str());
    throw std::runtime_error("cannot write " + path + ": " + what + ": " + reason);
  };
  const int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) fail("open");
  std::size_t done = 0;
  while (done < text.size()) {
    const ssize_t n = ::write(fd, text.data() + done, text.size() - done);
    if (n < 0) {
      if (errno == EINTR) continue;
      ::close(fd);
      fail("write");
    }
    done += static_cast<std::size_t>(n);
  }
  if (::fsync(fd) != 0) {
    ::close(fd);
    fail("fsync");
  }
  if (::close(fd) != 0) fail("close");
  if (std::rename(tmp.c_str(), path.c_str()) != 0) fail("rename");
}

}  // namespace

CameraModel LoadCameraFile(const std::string& path) {
  return ParseCamera(ParseYaml(ReadFileText(path), path), path, "");
}

CameraModel ParseCameraNode(const YAML::Node& node, const std::string& file,
                            const std::string& field_prefix) {
  return ParseCamera(node, file, field_prefix);
}

void SaveCameraFile(const CameraModel& camera, const std::string& path) {
  const std::string text = CameraText(camera);
  // A model holding what no camera file may hold (a tilt of 90°, a negative
  // vignetting k) is a bug in the caller: refuse it rather than write a file
  // that will not load.
  try {
    ParseCamera(ParseYaml(text, path), path, "");
  } catch (const core::InputError& e) {
    throw std::invalid_argument(std::string("SaveCameraFile: the camera cannot be written: ") +
                                e.what());
  }
  WriteAtomically(path, text);
}

}  // namespace pirouette::camera
