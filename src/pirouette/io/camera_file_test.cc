#include "pirouette/io/camera_file.h"

#include <gtest/gtest.h>
#include <unistd.h>
#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <stdexcept>
#include <string>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/testing/input_error.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::io {
namespace {

namespace fs = std::filesystem;

using testing::TempDir;

using testing::ExpectInputError;

// A valid camera file; the tests below refer to its line numbers.
constexpr char kCamera[] =
    "image_width: 320\n"                                                // 1
    "image_height: 240\n"                                               // 2
    "camera_name: yujin\n"                                              // 3
    "camera_matrix:\n"                                                  // 4
    "  rows: 3\n"                                                       // 5
    "  cols: 3\n"                                                       // 6
    "  data: [277.13, 0, 159.5, 0, 276.5, 119.25, 0, 0, 1]\n"           // 7
    "distortion_model: plumb_bob\n"                                     // 8
    "distortion_coefficients:\n"                                        // 9
    "  rows: 1\n"                                                       // 10
    "  cols: 5\n"                                                       // 11
    "  data: [-0.2, 0.05, 0.001, -0.002, 0.01]\n"                       // 12
    "rectification_matrix:\n"                                           // 13
    "  rows: 3\n"                                                       // 14
    "  cols: 3\n"                                                       // 15
    "  data: [1, 0, 0, 0, 1, 0, 0, 0, 1]\n"                             // 16
    "projection_matrix:\n"                                              // 17
    "  rows: 3\n"                                                       // 18
    "  cols: 4\n"                                                       // 19
    "  data: [277.13, 0, 159.5, 0, 0, 276.5, 119.25, 0, 0, 0, 1, 0]\n"  // 20
    "mount:\n"                                                          // 21
    "  height: 0.11\n"                                                  // 22
    "  tilt: 30\n"                                                      // 23
    "  forward: 0.03\n"                                                 // 24
    "vignetting:\n"                                                     // 25
    "  k: [0.35, 0.3, 0.4]\n";                                          // 26

// kCamera with the one occurrence of `from` replaced by `to`.
std::string Edited(const std::string& from, const std::string& to) {
  std::string text = kCamera;
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the camera file";
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "'" << from << "' is there twice";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

void ExpectSameCamera(const camera::CameraModel& a, const camera::CameraModel& b) {
  EXPECT_EQ(a.name(), b.name());
  EXPECT_EQ(a.width(), b.width());
  EXPECT_EQ(a.height(), b.height());
  EXPECT_EQ(a.intrinsics().fx, b.intrinsics().fx);
  EXPECT_EQ(a.intrinsics().fy, b.intrinsics().fy);
  EXPECT_EQ(a.intrinsics().cx, b.intrinsics().cx);
  EXPECT_EQ(a.intrinsics().cy, b.intrinsics().cy);
  EXPECT_EQ(a.distortion().k1, b.distortion().k1);
  EXPECT_EQ(a.distortion().k2, b.distortion().k2);
  EXPECT_EQ(a.distortion().p1, b.distortion().p1);
  EXPECT_EQ(a.distortion().p2, b.distortion().p2);
  EXPECT_EQ(a.distortion().k3, b.distortion().k3);
  EXPECT_EQ(a.mount().height_m, b.mount().height_m);
  EXPECT_DOUBLE_EQ(a.mount().tilt_rad, b.mount().tilt_rad);
  EXPECT_EQ(a.mount().forward_m, b.mount().forward_m);
  EXPECT_EQ(a.vignetting().k, b.vignetting().k);
}

TEST(CameraFileTest, LoadsEveryField) {
  const TempDir dir;
  const camera::CameraModel camera = LoadCameraFile(dir.Write("camera.yaml", kCamera));
  EXPECT_EQ(camera.name(), "yujin");
  EXPECT_EQ(camera.width(), 320);
  EXPECT_EQ(camera.height(), 240);
  EXPECT_EQ(camera.intrinsics().fx, 277.13);
  EXPECT_EQ(camera.intrinsics().fy, 276.5);
  EXPECT_EQ(camera.intrinsics().cx, 159.5);
  EXPECT_EQ(camera.intrinsics().cy, 119.25);
  EXPECT_EQ(camera.distortion().k1, -0.2);
  EXPECT_EQ(camera.distortion().k2, 0.05);
  EXPECT_EQ(camera.distortion().p1, 0.001);
  EXPECT_EQ(camera.distortion().p2, -0.002);
  EXPECT_EQ(camera.distortion().k3, 0.01);
  EXPECT_EQ(camera.mount().height_m, 0.11);
  EXPECT_EQ(camera.mount().tilt_rad, core::DegToRad(30.0));
  EXPECT_EQ(camera.mount().forward_m, 0.03);
  EXPECT_EQ(camera.vignetting().k, (std::array<double, 3>{0.35, 0.3, 0.4}));
}

TEST(CameraFileTest, OptionalFieldsTakeTheirDefaults) {
  const TempDir dir;
  const std::string text =
      "image_width: 640\n"
      "image_height: 480\n"
      "camera_matrix: {rows: 3, cols: 3, data: [500, 0, 319.5, 0, 500, 239.5, 0, 0, 1]}\n"
      "distortion_model: plumb_bob\n"
      "distortion_coefficients: {rows: 1, cols: 5, data: [0, 0, 0, 0, 0]}\n"
      "mount: {height: 0.3, tilt: -10}\n";
  const camera::CameraModel camera = LoadCameraFile(dir.Write("camera.yaml", text));
  EXPECT_EQ(camera.name(), "");
  EXPECT_EQ(camera.mount().forward_m, 0.0);
  EXPECT_EQ(camera.mount().tilt_rad, core::DegToRad(-10.0));
  EXPECT_EQ(camera.vignetting().k, (std::array<double, 3>{0.0, 0.0, 0.0}));
}

// What ROS's camera_calibration writes, plus the mount pirouette needs.
TEST(CameraFileTest, ReadsRosCalibrationOutputAsIs) {
  const TempDir dir;
  const std::string text =
      "image_width: 640\n"
      "image_height: 480\n"
      "camera_name: narrow_stereo\n"
      "camera_matrix:\n"
      "  rows: 3\n"
      "  cols: 3\n"
      "  data: [ 476.7030836014194, 0.0, 400.5, 0.0, 476.7030836014194, 400.5, 0.0, 0.0, 1.0 ]\n"
      "distortion_model: plumb_bob\n"
      "distortion_coefficients:\n"
      "  rows: 1\n"
      "  cols: 5\n"
      "  data: [ -0.001, 1.2e-03, 0.0, -0.0, 0.0 ]\n"
      "rectification_matrix:\n"
      "  rows: 3\n"
      "  cols: 3\n"
      "  data: [ 1.0, 0.0, 0.0, 0.0, 1.0, 0.0, 0.0, 0.0, 1.0 ]\n"
      "projection_matrix:\n"
      "  rows: 3\n"
      "  cols: 4\n"
      "  data: [ 476.7030836014194, 0.0, 400.5, -33.36921585209936, 0.0, 476.7030836014194, "
      "400.5, 0.0, 0.0, 0.0, 1.0, 0.0 ]\n"
      "mount:\n"
      "  height: 0.3\n"
      "  tilt: 25\n";
  const camera::CameraModel camera = LoadCameraFile(dir.Write("ost.yaml", text));
  EXPECT_EQ(camera.name(), "narrow_stereo");
  EXPECT_EQ(camera.intrinsics().fx, 476.7030836014194);
  EXPECT_EQ(camera.intrinsics().cy, 400.5);
  EXPECT_EQ(camera.distortion().k2, 1.2e-3);
}

TEST(CameraFileTest, ParseCameraNodeReadsAnInlineCamera) {
  const camera::CameraModel camera =
      ParseCameraNode(YAML::Load(kCamera), "world.yaml", "robot.camera");
  EXPECT_EQ(camera.width(), 320);
  EXPECT_EQ(camera.mount().height_m, 0.11);
}

TEST(CameraFileTest, ParseCameraNodePrefixesFieldsAndNamesTheFile) {
  const core::InputError error = ExpectInputError([] {
    ParseCameraNode(YAML::Load(Edited("tilt: 30", "tilt: 95")), "world.yaml", "robot.camera");
  });
  EXPECT_EQ(error.file(), "world.yaml");
  EXPECT_EQ(error.field(), "robot.camera.mount.tilt");
  EXPECT_EQ(error.line(), 23);
}

TEST(CameraFileTest, RefusesAMissingFile) {
  const TempDir dir;
  const std::string path = (dir.path() / "nosuch.yaml").string();
  const core::InputError error = ExpectInputError([&] { LoadCameraFile(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.line(), 0);
  EXPECT_EQ(error.field(), "");
  EXPECT_NE(std::string(error.what()).find(path), std::string::npos) << error.what();
}

TEST(CameraFileTest, RefusesAFolder) {
  const TempDir dir;
  const core::InputError error = ExpectInputError([&] { LoadCameraFile(dir.path().string()); });
  EXPECT_EQ(error.file(), dir.path().string());
}

TEST(CameraFileTest, RefusesAnEmptyFile) {
  const TempDir dir;
  for (const std::string text : {"", "\n\n", "# only a comment\n"}) {
    const std::string path = dir.Write("empty.yaml", text);
    const core::InputError error = ExpectInputError([&] { LoadCameraFile(path); });
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.line(), 0);
    EXPECT_NE(std::string(error.what()).find("empty"), std::string::npos) << error.what();
  }
}

TEST(CameraFileTest, RefusesMalformedYamlAtItsLine) {
  const TempDir dir;
  const std::string path =
      dir.Write("bad.yaml", Edited("  tilt: 30\n", "  tilt: 30\n   bad: : :\n"));
  const core::InputError error = ExpectInputError([&] { LoadCameraFile(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.line(), 24);
  EXPECT_NE(std::string(error.what()).find("malformed YAML"), std::string::npos) << error.what();
}

TEST(CameraFileTest, RefusesATopLevelThatIsNotAMap) {
  const TempDir dir;
  const core::InputError error =
      ExpectInputError([&] { LoadCameraFile(dir.Write("list.yaml", "\n- 1\n- 2\n")); });
  EXPECT_EQ(error.line(), 2);
  EXPECT_EQ(error.field(), "");
}

struct BadCase {
  const char* name;
  const char* from;  // text of kCamera...
  const char* to;    // ...replaced by this
  const char* field;
  int line;
  const char* message;  // a part of the message
};

class CameraFileBadInputTest : public ::testing::TestWithParam<BadCase> {};

TEST_P(CameraFileBadInputTest, IsRefusedWithFieldAndLine) {
  const BadCase& c = GetParam();
  const TempDir dir;
  const std::string path = dir.Write("camera.yaml", Edited(c.from, c.to));
  const core::InputError error = ExpectInputError([&] { LoadCameraFile(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.field(), c.field) << error.what();
  EXPECT_EQ(error.line(), c.line) << error.what();
  EXPECT_NE(std::string(error.what()).find(c.message), std::string::npos) << error.what();
}

const BadCase kBadCases[] = {
    // Unknown and duplicate keys.
    {"UnknownKey", "  k: [0.35, 0.3, 0.4]\n", "  k: [0.35, 0.3, 0.4]\nlens: wide\n", "lens", 27,
     "unknown key"},
    {"UnknownNestedKey", "  forward: 0.03", "  forwards: 0.03", "mount.forwards", 24,
     "unknown key"},
    {"UnknownMatrixKey", "  cols: 5\n", "  cols: 5\n  step: 1\n", "distortion_coefficients.step",
     12, "unknown key"},
    {"DuplicateKey", "camera_name: yujin\n", "camera_name: yujin\nimage_width: 640\n",
     "image_width", 4, "duplicate key"},
    // Missing required keys: reported at the map that lacks them.
    {"MissingWidth", "image_width: 320\n", "", "image_width", 1, "missing required key"},
    {"MissingCameraMatrix",
     "camera_matrix:\n  rows: 3\n  cols: 3\n  data: [277.13, 0, 159.5, 0, 276.5, 119.25, 0, 0, "
     "1]\n",
     "", "camera_matrix", 1, "missing required key"},
    {"MissingMatrixData", "  data: [277.13, 0, 159.5, 0, 276.5, 119.25, 0, 0, 1]\n", "",
     "camera_matrix.data", 5, "missing required key"},
    {"MissingMount", "mount:\n  height: 0.11\n  tilt: 30\n  forward: 0.03\n", "", "mount", 1,
     "missing required key"},
    {"MissingMountHeight", "  height: 0.11\n", "", "mount.height", 22, "missing required key"},
    {"MissingTilt", "  tilt: 30\n", "", "mount.tilt", 22, "missing required key"},
    {"MissingVignettingK", "  k: [0.35, 0.3, 0.4]\n", "  {}\n", "vignetting.k", 26,
     "missing required key"},
    // Wrong types.
    {"WidthNotANumber", "image_width: 320", "image_width: wide", "image_width", 1,
     "expected a number, got the string 'wide'"},
    {"WidthQuoted", "image_width: 320", "image_width: \"320\"", "image_width", 1,
     "expected a number, got the string '320'"},
    {"WidthAList", "image_width: 320", "image_width: [320]", "image_width", 1,
     "expected a number, got a list"},
    {"WidthNotWhole", "image_width: 320", "image_width: 320.5", "image_width", 1,
     "expected a whole number"},
    {"HeightEmpty", "image_height: 240", "image_height:", "image_height", 2,
     "expected a number, got nothing"},
    {"NameEmpty", "camera_name: yujin", "camera_name:", "camera_name", 3,
     "expected a string, got nothing"},
    {"MountNotAMap", "mount:\n  height: 0.11\n  tilt: 30\n  forward: 0.03\n", "mount: 0.11\n",
     "mount", 21, "expected a map"},
    {"VignettingNotAMap", "vignetting:\n  k: [0.35, 0.3, 0.4]\n", "vignetting: [0.35, 0.3, 0.4]\n",
     "vignetting", 25, "expected a map"},
    {"MatrixItemNotANumber", "159.5, 0, 276.5, 119.25", "159.5, 0, x, 119.25", "camera_matrix.data",
     7, "item 5 of 9: expected a number"},
    {"CoefficientNotANumber", "[-0.2, 0.05", "[-0.2, true", "distortion_coefficients.data", 12,
     "item 2 of 5: expected a number, got the boolean true"},
    {"ForwardInfinite", "forward: 0.03", "forward: .inf", "mount.forward", 24,
     "expected a finite number"},
    {"TiltNaN", "tilt: 30", "tilt: .nan", "mount.tilt", 23, "expected a finite number"},
    // Out of range.
    {"WidthZero", "image_width: 320", "image_width: 0", "image_width", 1, "must be > 0"},
    {"HeightNegative", "image_height: 240", "image_height: -240", "image_height", 2, "must be > 0"},
    {"FxZero", "[277.13, 0, 159.5, 0, 276.5", "[0, 0, 159.5, 0, 276.5", "camera_matrix.data", 7,
     "fx must be > 0"},
    {"FyNegative", "159.5, 0, 276.5, 119.25", "159.5, 0, -276.5, 119.25", "camera_matrix.data", 7,
     "fy must be > 0"},
    {"Skew", "[277.13, 0, 159.5, 0, 276.5", "[277.13, 0.5, 159.5, 0, 276.5", "camera_matrix.data",
     7, "skew"},
    {"MatrixLastRow", "119.25, 0, 0, 1]\n", "119.25, 0, 0, 2]\n", "camera_matrix.data", 7,
     "must be 1"},
    {"MatrixRowZero", "159.5, 0, 276.5", "159.5, 3, 276.5", "camera_matrix.data", 7, "must be 0"},
    {"MatrixTooShort", "119.25, 0, 0, 1]\n", "119.25, 0, 0]\n", "camera_matrix.data", 7,
     "data holds 8 numbers"},
    {"MatrixRows", "camera_matrix:\n  rows: 3", "camera_matrix:\n  rows: 4", "camera_matrix.rows",
     5, "expected 3, got 4"},
    {"UnsupportedModel", "distortion_model: plumb_bob", "distortion_model: fisheye",
     "distortion_model", 8, "unsupported distortion model 'fisheye'"},
    {"RationalPolynomialOfFive", "distortion_model: plumb_bob",
     "distortion_model: rational_polynomial", "distortion_coefficients.data", 12,
     "rational_polynomial takes 8 coefficients (k1, k2, p1, p2, k3, k4, k5, k6), got 5"},
    {"EquidistantOfFive", "distortion_model: plumb_bob", "distortion_model: equidistant",
     "distortion_coefficients.data", 12,
     "equidistant takes 4 coefficients (k1, k2, k3, k4), got 5"},
    {"FourCoefficients", "[-0.2, 0.05, 0.001, -0.002, 0.01]", "[-0.2, 0.05, 0.001, -0.002]",
     "distortion_coefficients.data", 12, "plumb_bob takes 5 coefficients"},
    {"EightCoefficients", "[-0.2, 0.05, 0.001, -0.002, 0.01]", "[-0.2, 0.05, 0, 0, 0, 0, 0, 0]",
     "distortion_coefficients.data", 12, "plumb_bob takes 5 coefficients"},
    {"CoefficientColsMismatch", "  cols: 5", "  cols: 4", "distortion_coefficients.cols", 11,
     "expected 5, got 4"},
    {"MountHeightZero", "height: 0.11", "height: 0", "mount.height", 22, "must be > 0"},
    {"TiltNinety", "tilt: 30", "tilt: 90", "mount.tilt", 23, "(-90, 90)"},
    {"TiltBelowMinusNinety", "tilt: 30", "tilt: -95", "mount.tilt", 23, "(-90, 90)"},
    {"VignettingNegative", "k: [0.35, 0.3, 0.4]", "k: [0.35, -0.3, 0.4]", "vignetting.k", 26,
     "item 2 of 3: must be >= 0"},
    {"VignettingTwoValues", "k: [0.35, 0.3, 0.4]", "k: [0.35, 0.3]", "vignetting.k", 26,
     "expected a list of 3 numbers, got 2 items"},
};

INSTANTIATE_TEST_SUITE_P(AllCases, CameraFileBadInputTest, ::testing::ValuesIn(kBadCases),
                         [](const ::testing::TestParamInfo<BadCase>& info) {
                           return std::string(info.param.name);
                         });

TEST(CameraFileTest, VignettingSpreadOverLinesIsReportedAtTheItem) {
  const TempDir dir;
  const std::string path = dir.Write(
      "camera.yaml", Edited("  k: [0.35, 0.3, 0.4]\n", "  k:\n    - 0.35\n    - -1\n    - 0.4\n"));
  const core::InputError error = ExpectInputError([&] { LoadCameraFile(path); });
  EXPECT_EQ(error.field(), "vignetting.k");
  EXPECT_EQ(error.line(), 28);
}

TEST(CameraFileTest, TextThenLoadGivesTheSameCamera) {
  const TempDir dir;
  const camera::CameraModel camera = LoadCameraFile(dir.Write("camera.yaml", kCamera));
  const camera::CameraModel loaded =
      LoadCameraFile(dir.Write("saved.yaml", CameraFileText(camera)));
  ExpectSameCamera(loaded, camera);
  // A tilt read in degrees is written back in the same degrees, exactly.
  EXPECT_EQ(loaded.mount().tilt_rad, camera.mount().tilt_rad);
}

TEST(CameraFileTest, TextThenLoadKeepsAwkwardValues) {
  const TempDir dir;
  for (const std::string name : {"", "null", "true", "42", "two words", "a: b", "#hash", " pad "}) {
    const camera::CameraModel camera(
        name, 17, 9, camera::Intrinsics{1.0 / 3.0, 1e-7 + 1, -2.5e-3, 1e10},
        camera::PlumbBob{-1.0 / 7.0, 1e-300, 0.0, -0.0, 123456789.123},
        camera::Mount{0.1 + 0.2, 0.5, -1.0 / 9.0}, camera::Vignetting{{0.0, 1e-9, 7.0}});
    ExpectSameCamera(LoadCameraFile(dir.Write("saved.yaml", CameraFileText(camera))), camera);
  }
}

TEST(CameraFileTest, TextHasTheRosFields) {
  const TempDir dir;
  const std::string text = CameraFileText(LoadCameraFile(dir.Write("camera.yaml", kCamera)));
  EXPECT_NE(text.find("distortion_model: plumb_bob"), std::string::npos) << text;
  EXPECT_NE(text.find("rectification_matrix:"), std::string::npos) << text;
  EXPECT_NE(text.find("projection_matrix:"), std::string::npos) << text;
  EXPECT_NE(text.find("tilt: 30\n"), std::string::npos) << text;
  EXPECT_NE(text.find("data: [-0.2, 0.05, 0.001, -0.002, 0.01]"), std::string::npos) << text;
}

TEST(CameraFileTest, NoCameraModelHoldsWhatNoFileMayHold) {
  // The model itself refuses a tilt no camera file may hold, so Save never meets one.
  EXPECT_THROW(camera::CameraModel(
                   "steep", 320, 240, camera::Intrinsics{200, 200, 160, 120}, camera::PlumbBob{},
                   camera::Mount{0.1, core::DegToRad(100.0), 0.0}, camera::Vignetting{}),
               std::invalid_argument);
}

TEST(CameraFileTest, MissingDistortionModelReadsAsPlumbBob) {
  const TempDir dir;
  const camera::CameraModel camera =
      LoadCameraFile(dir.Write("camera.yaml", Edited("distortion_model: plumb_bob\n", "")));
  EXPECT_EQ(camera.distortion().model, camera::Distortion::Model::kPlumbBob);
  EXPECT_EQ(camera.distortion().k3, 0.01);
}

TEST(CameraFileTest, ReadsRationalPolynomialAndEquidistant) {
  const TempDir dir;
  const camera::CameraModel wide = LoadCameraFile(dir.Write(
      "wide.yaml",
      Edited("distortion_model: plumb_bob\ndistortion_coefficients:\n  rows: 1\n  cols: 5\n  "
             "data: [-0.2, 0.05, 0.001, -0.002, 0.01]\n",
             "distortion_model: rational_polynomial\ndistortion_coefficients:\n  rows: 1\n  cols: "
             "8\n  data: [0.2, -0.05, 0.001, -0.0008, 0.001, 0.55, 0.05, 0.002]\n")));
  EXPECT_EQ(wide.distortion().model, camera::Distortion::Model::kRationalPolynomial);
  EXPECT_EQ(wide.distortion().Coefficients(),
            (std::vector<double>{0.2, -0.05, 0.001, -0.0008, 0.001, 0.55, 0.05, 0.002}));
  const camera::CameraModel fisheye = LoadCameraFile(dir.Write(
      "fisheye.yaml",
      Edited("distortion_model: plumb_bob\ndistortion_coefficients:\n  rows: 1\n  cols: 5\n  "
             "data: [-0.2, 0.05, 0.001, -0.002, 0.01]\n",
             "distortion_model: equidistant\ndistortion_coefficients:\n  rows: 1\n  cols: 4\n  "
             "data: [0.04, -0.012, 0.003, -0.0005]\n")));
  EXPECT_EQ(fisheye.distortion().model, camera::Distortion::Model::kEquidistant);
  EXPECT_EQ(fisheye.distortion().Coefficients(),
            (std::vector<double>{0.04, -0.012, 0.003, -0.0005}));
}

TEST(CameraFileTest, EveryModelTextThenLoadGivesTheSameDistortion) {
  const TempDir dir;
  using Model = camera::Distortion::Model;
  const std::vector<camera::Distortion> distortions = {
      camera::PlumbBob{-0.2, 0.05, 0.001, -0.002, 0.01},
      *camera::Distortion::FromCoefficients(
          Model::kRationalPolynomial,
          std::vector{1.0 / 3.0, -0.05, 1e-300, -0.0, 0.001, 0.55, 0.05, 123456789.123}),
      *camera::Distortion::FromCoefficients(Model::kEquidistant,
                                            std::vector{0.04, -1.0 / 7.0, 0.003, -0.0005}),
  };
  for (const camera::Distortion& d : distortions) {
    const camera::CameraModel camera("lens", 640, 480, camera::Intrinsics{300, 301, 319.5, 239.5},
                                     d, camera::Mount{0.2, 0.4, 0.05}, camera::Vignetting{});
    const std::string text = CameraFileText(camera);
    EXPECT_NE(
        text.find(std::string("distortion_model: ") + std::string(camera::ModelName(d.model))),
        std::string::npos)
        << text;
    const camera::CameraModel loaded = LoadCameraFile(dir.Write("saved.yaml", text));
    EXPECT_EQ(loaded.distortion(), d) << text;
    ExpectSameCamera(loaded, camera);
  }
}

// The camera files shipped in worlds/ are the YAML files without a `format:` key.
TEST(CameraFileTest, ShippedCameraFilesLoad) {
  std::vector<std::string> loaded;
  for (const auto& entry : fs::directory_iterator(PIROUETTE_WORLDS_DIR)) {
    if (entry.path().extension() != ".yaml") continue;
    if (YAML::LoadFile(entry.path().string())["format"]) continue;
    SCOPED_TRACE(entry.path().string());
    EXPECT_NO_THROW(LoadCameraFile(entry.path().string()));
    loaded.push_back(entry.path().filename().string());
  }
  std::sort(loaded.begin(), loaded.end());
  EXPECT_EQ(loaded, (std::vector<std::string>{"webcam640.yaml", "yujin.yaml"}));
}

// The paper's camera: 320 × 240, a 60° horizontal field of view.
TEST(CameraFileTest, ShippedYujinCameraIsThePapers) {
  const camera::CameraModel camera =
      LoadCameraFile(std::string(PIROUETTE_WORLDS_DIR) + "/yujin.yaml");
  EXPECT_EQ(camera.width(), 320);
  EXPECT_EQ(camera.height(), 240);
  EXPECT_NEAR(2.0 * std::atan(160.0 / camera.intrinsics().fx), core::DegToRad(60.0), 1e-4);
  EXPECT_EQ(camera.intrinsics().cx, 159.5);
  EXPECT_EQ(camera.intrinsics().cy, 119.5);
  EXPECT_LT(camera.distortion().k1, 0.0);  // barrel
  EXPECT_EQ(camera.mount().height_m, 0.11);
  EXPECT_EQ(camera.mount().tilt_rad, core::DegToRad(30.0));
  EXPECT_EQ(camera.mount().forward_m, 0.03);
  EXPECT_EQ(camera.vignetting().k, (std::array<double, 3>{0.35, 0.30, 0.40}));
}

}  // namespace
}  // namespace pirouette::io
