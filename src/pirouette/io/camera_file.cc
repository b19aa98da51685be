#include "pirouette/io/camera_file.h"

#include <yaml-cpp/yaml.h>

#include <array>
#include <charconv>
#include <cstddef>
#include <cstdio>
#include <initializer_list>
#include <optional>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include <fmt/format.h>

#include "pirouette/core/angle.h"
#include "pirouette/io/yaml_fields.h"

namespace pirouette::io {
namespace {

constexpr std::string_view kSupportedDistortion = "plumb_bob, rational_polynomial and equidistant";

// A ROS matrix {rows, cols, data} of `rows` × `cols` numbers (`cols` = 0:
// any number of columns, which the file's `cols` gives).
NumberList ReadMatrix(const std::string& file, const YamlField& field, int rows, int cols) {
  const YamlMap map = ReadMap(file, field, {"rows", "cols", "data"});
  const YamlField rows_field = map.Required("rows");
  const YamlField cols_field = map.Required("cols");
  const YamlField data_field = map.Required("data");
  const int file_rows = ReadWholeNumber(file, rows_field);
  if (file_rows != rows) {
    ThrowInputError(file, rows_field, fmt::format("expected {}, got {}", rows, file_rows));
  }
  const int file_cols = ReadWholeNumber(file, cols_field);
  if ((cols > 0 && file_cols != cols) || file_cols <= 0) {
    ThrowInputError(file, cols_field,
                    cols > 0 ? fmt::format("expected {}, got {}", cols, file_cols)
                             : fmt::format("must be > 0, got {}", file_cols));
  }
  const auto count = static_cast<std::size_t>(rows) * static_cast<std::size_t>(file_cols);
  const std::size_t items = ReadList(file, data_field, "a list of numbers").size();
  if (items != count) {
    ThrowInputError(file, data_field,
                    fmt::format("rows × cols is {} × {} = {} but data holds {} numbers", rows,
                                file_cols, count, items));
  }
  return ReadNumbers(file, data_field, count);
}

// image_width and image_height, each > 0.
std::array<int, 2> ReadImageSize(const std::string& file, const YamlMap& map) {
  std::array<int, 2> size = {0, 0};
  const char* size_keys[2] = {"image_width", "image_height"};
  for (std::size_t i = 0; i < 2; ++i) {
    const YamlField field = map.Required(size_keys[i]);
    size[i] = ReadWholeNumber(file, field);
    if (size[i] <= 0) ThrowInputError(file, field, fmt::format("must be > 0, got {}", size[i]));
  }
  return size;
}

// camera_matrix: [fx 0 cx; 0 fy cy; 0 0 1], row-major.
camera::Intrinsics ReadIntrinsics(const std::string& file, const YamlMap& map) {
  const YamlField k_field = map.Required("camera_matrix");
  const NumberList k_data = ReadMatrix(file, k_field, 3, 3);
  const std::vector<double>& k = k_data.values;
  const auto check_k = [&](int i, bool ok, std::string_view problem) {
    if (!ok) {
      const auto index = static_cast<std::size_t>(i);
      ThrowInputError(file, k_data.items[index],
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
  return {k[0], k[4], k[2], k[5]};
}

// What each model's coefficients are, in ROS's order, for messages.
std::string_view CoefficientNames(camera::Distortion::Model model) {
  switch (model) {
    case camera::Distortion::Model::kPlumbBob:
      return "k1, k2, p1, p2, k3";
    case camera::Distortion::Model::kRationalPolynomial:
      return "k1, k2, p1, p2, k3, k4, k5, k6";
    case camera::Distortion::Model::kEquidistant:
      return "k1, k2, k3, k4";
  }
  return "";
}

// distortion_model (plumb_bob, rational_polynomial or equidistant; missing:
// plumb_bob, with a warning, as ROS's camera_calibration_parsers read it) and
// its distortion_coefficients, 1 row of as many as the model has (5, 8, 4).
camera::Distortion ReadDistortion(const std::string& file, const YamlMap& map) {
  camera::Distortion::Model model = camera::Distortion::Model::kPlumbBob;
  if (const auto model_field = map.Optional("distortion_model")) {
    const std::string name = ReadName(file, *model_field);
    const std::optional<camera::Distortion::Model> named = camera::ModelNamed(name);
    if (!named) {
      ThrowInputError(file, *model_field,
                      fmt::format("unsupported distortion model '{}'; pirouette reads {}", name,
                                  kSupportedDistortion));
    }
    model = *named;
  } else {
    // The one message this layer prints: the file loads, but the user should know.
    std::fprintf(stderr, "%s: warning: no distortion_model; read as plumb_bob, as ROS does\n",
                 file.c_str());
  }
  const std::string_view model_name = camera::ModelName(model);
  const YamlField d_field = map.Required("distortion_coefficients");
  const YamlField d_data_field = ReadMap(file, d_field, {"rows", "cols", "data"}).Required("data");
  const std::size_t d_count = ReadList(file, d_data_field, "a list of numbers").size();
  camera::Distortion of_model;
  of_model.model = model;
  const std::size_t expected = of_model.Coefficients().size();
  if (d_count != expected) {
    ThrowInputError(file, d_data_field,
                    fmt::format("{} takes {} coefficients ({}), got {}", model_name, expected,
                                CoefficientNames(model), d_count));
  }
  const std::vector<double> d = ReadMatrix(file, d_field, 1, static_cast<int>(expected)).values;
  return *camera::Distortion::FromCoefficients(model, d);
}

// mount: height (> 0), tilt (degrees in (-90, 90)), forward (optional).
camera::Mount ReadMount(const std::string& file, const YamlMap& map) {
  const YamlMap mount_map = ReadMap(file, map.Required("mount"), {"height", "tilt", "forward"});
  camera::Mount mount;
  const YamlField height_field = mount_map.Required("height");
  mount.height_m = ReadNumber(file, height_field);
  if (!(mount.height_m > 0.0)) {
    ThrowInputError(file, height_field,
                    fmt::format("must be > 0 (metres above the floor), got {}", mount.height_m));
  }
  const YamlField tilt_field = mount_map.Required("tilt");
  const double tilt_deg = ReadNumber(file, tilt_field);
  if (!(tilt_deg > -90.0 && tilt_deg < 90.0)) {
    ThrowInputError(file, tilt_field,
                    fmt::format("must lie in (-90, 90) degrees, got {}", tilt_deg));
  }
  mount.tilt_rad = core::DegToRad(tilt_deg);
  if (const auto field = mount_map.Optional("forward")) mount.forward_m = ReadNumber(file, *field);
  return mount;
}

// vignetting (optional): k, three gains >= 0.
camera::Vignetting ReadVignetting(const std::string& file, const YamlMap& map) {
  camera::Vignetting vignetting;
  if (const auto field = map.Optional("vignetting")) {
    const YamlField k_gain = ReadMap(file, *field, {"k"}).Required("k");
    const NumberList values = ReadNumbers(file, k_gain, 3);
    for (std::size_t i = 0; i < 3; ++i) {
      if (values.values[i] < 0.0) {
        ThrowInputError(file, values.items[i],
                        fmt::format("item {} of 3: must be >= 0, got {}", i + 1, values.values[i]));
      }
      vignetting.k[i] = values.values[i];
    }
  }
  return vignetting;
}

// The keys a camera file may have.
const std::initializer_list<std::string_view> kCameraKeys = {"image_width",
                                                             "image_height",
                                                             "camera_name",
                                                             "camera_matrix",
                                                             "distortion_model",
                                                             "distortion_coefficients",
                                                             "rectification_matrix",
                                                             "projection_matrix",
                                                             "mount",
                                                             "vignetting"};

camera::CameraModel ParseCamera(const YAML::Node& node, const std::string& file,
                                const std::string& prefix) {
  const YamlField root{node, prefix, LineOf(node)};
  const YamlMap map = ReadMap(file, root, kCameraKeys);
  const std::array<int, 2> size = ReadImageSize(file, map);
  std::string name;
  if (const auto field = map.Optional("camera_name")) name = ReadName(file, *field);
  const camera::Intrinsics intrinsics = ReadIntrinsics(file, map);
  const camera::Distortion distortion = ReadDistortion(file, map);
  const camera::Mount mount = ReadMount(file, map);
  const camera::Vignetting vignetting = ReadVignetting(file, map);
  // rectification_matrix and projection_matrix are accepted and ignored (SPEC.md).
  return {name, size[0], size[1], intrinsics, distortion, mount, vignetting};
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

void EmitNumbers(YAML::Emitter& out, const std::vector<double>& values) {
  out << YAML::Flow << YAML::BeginSeq;
  for (const double value : values) out << NumberText(value);
  out << YAML::EndSeq;
}

void EmitMatrix(YAML::Emitter& out, std::string_view key, int rows, int cols,
                const std::vector<double>& data) {
  out << YAML::Key << std::string(key) << YAML::Value << YAML::BeginMap;
  out << YAML::Key << "rows" << YAML::Value << rows;
  out << YAML::Key << "cols" << YAML::Value << cols;
  out << YAML::Key << "data" << YAML::Value;
  EmitNumbers(out, data);
  out << YAML::EndMap;
}

std::string CameraText(const camera::CameraModel& camera) {
  const camera::Intrinsics& in = camera.intrinsics();
  const camera::Distortion& d = camera.distortion();
  const camera::Mount& mount = camera.mount();
  const auto& k = camera.vignetting().k;

  YAML::Emitter out;
  out << YAML::BeginMap;
  out << YAML::Key << "image_width" << YAML::Value << camera.width();
  out << YAML::Key << "image_height" << YAML::Value << camera.height();
  out << YAML::Key << "camera_name" << YAML::Value;
  // A name that would read back as nothing is quoted (ReadName takes any other
  // scalar, a number or a boolean too, as its text).
  const YAML::Node plain(camera.name());
  if (camera.name().empty() || ScalarKindOf(plain) == ScalarKind::kNull) out << YAML::DoubleQuoted;
  out << camera.name();
  EmitMatrix(out, "camera_matrix", 3, 3, {in.fx, 0.0, in.cx, 0.0, in.fy, in.cy, 0.0, 0.0, 1.0});
  out << YAML::Key << "distortion_model" << YAML::Value << std::string(camera::ModelName(d.model));
  const std::vector<double> coefficients = d.Coefficients();
  EmitMatrix(out, "distortion_coefficients", 1, static_cast<int>(coefficients.size()),
             coefficients);
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
  if (!out.good()) throw std::logic_error("CameraFileText: YAML emitter: " + out.GetLastError());
  return std::string(out.c_str()) + "\n";
}

}  // namespace

camera::CameraModel LoadCameraFile(const std::string& path) {
  return ParseCamera(LoadYamlFile(path), path, "");
}

CameraMountFile LoadCameraMount(const std::string& path) {
  const YAML::Node node = LoadYamlFile(path);
  const YamlMap map = ReadMap(path, YamlField{node, "", LineOf(node)}, kCameraKeys);
  CameraMountFile result;
  if (map.Optional("camera_matrix")) {
    result.camera = ParseCamera(node, path, "");
    result.name = result.camera->name();
    result.mount = result.camera->mount();
    result.vignetting = result.camera->vignetting();
    result.width = result.camera->width();
    result.height = result.camera->height();
    return result;
  }
  for (const char* key : {"distortion_model", "distortion_coefficients"}) {
    if (const auto field = map.Optional(key)) {
      ThrowInputError(path, *field,
                      "given without camera_matrix: give the whole calibration, or neither and "
                      "let the robot's camera_info give the intrinsics");
    }
  }
  if (map.Optional("image_width") || map.Optional("image_height")) {
    const std::array<int, 2> size = ReadImageSize(path, map);
    result.width = size[0];
    result.height = size[1];
  }
  if (const auto field = map.Optional("camera_name")) result.name = ReadName(path, *field);
  result.mount = ReadMount(path, map);
  result.vignetting = ReadVignetting(path, map);
  return result;
}

camera::CameraModel ParseCameraNode(const YAML::Node& node, const std::string& file,
                                    const std::string& field_prefix) {
  return ParseCamera(node, file, field_prefix);
}

// No check that the text loads back is needed: CameraModel's constructor
// refuses what no camera file may hold (a tilt outside (-90°, 90°), values
// that are not finite, a negative vignetting k), and TiltText writes a tilt
// inside (-90°, 90°) as degrees inside (-90, 90).
std::string CameraFileText(const camera::CameraModel& camera) { return CameraText(camera); }

}  // namespace pirouette::io
