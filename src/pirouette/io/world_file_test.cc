#include "pirouette/io/world_file.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <deque>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/testing/input_error.h"
#include "pirouette/testing/same_world.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::io {
namespace {

namespace fs = std::filesystem;

using testing::TempDir;

using testing::ExpectInputError;

// A valid camera file (camera_file_test.cc checks it field by field).
constexpr char kWorldCamera[] =
    "image_width: 320\n"
    "image_height: 240\n"
    "camera_name: test\n"
    "camera_matrix: {rows: 3, cols: 3, data: [277.13, 0, 159.5, 0, 276.5, 119.25, 0, 0, 1]}\n"
    "distortion_model: plumb_bob\n"
    "distortion_coefficients: {rows: 1, cols: 5, data: [-0.2, 0.05, 0, 0, 0]}\n"
    "mount:\n"
    "  height: 0.11\n"
    "  tilt: 30\n"  // line 9
    "  forward: 0.03\n";

// A valid world using every field. The tests below refer to its lines: 1 format, 2 name,
// 3-6 floor (4 size, 5 colour, 6 texture), 7-10 walls (8 height, 9 thickness, 10 colour),
// 11 obstacles (12 box, 13 cylinder, 14 wall, 15 prism), 16-19 light (17 ambient,
// 18 direction, 19 intensity), 20-26 robot (21 start, 22 radius, 23 camera, 24-26 odometry_noise).
constexpr char kWorld[] = R"(format: pirouette-world/1
name: test-world
floor:
  size: [2.0, 1.5]
  colour: [25, 30, 35]
  texture: 0.03
walls:
  height: 0.10
  thickness: 0.02
  colour: [235, 236, 237]
obstacles:
  - box: {centre: [0.40, 0.90], size: [0.10, 0.20], yaw: 30, height: 0.08, colour: [200, 40, 40]}
  - cylinder: {centre: [1.10, 0.30], radius: 0.05, height: 0.10, colour: [40, 160, 40]}
  - wall: {from: [0.00, 0.65], to: [0.80, 0.65], thickness: 0.02, height: 0.12, colour: [230, 230, 230]}
  - prism: {points: [[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]], height: 0.06, colour: [40, 40, 200]}
light:
  ambient: 0.5
  direction: [0.1, 0.2, -1.0]
  intensity: 0.7
robot:
  start: [0.20, 0.20, 45]
  radius: 0.04
  camera: cam.yaml
  odometry_noise:
    translation: 0.01
    rotation: 0.02
)";

// `text` with the one occurrence of `from` replaced by `to`.
std::string Edited(std::string text, const std::string& from, const std::string& to) {
  const std::size_t at = text.find(from);
  EXPECT_NE(at, std::string::npos) << "'" << from << "' is not in the file";
  EXPECT_EQ(text.find(from, at + 1), std::string::npos) << "'" << from << "' is there twice";
  if (at != std::string::npos) text.replace(at, from.size(), to);
  return text;
}

std::string EditedWorld(const std::string& from, const std::string& to) {
  return Edited(kWorld, from, to);
}

// `text` with every line indented by `spaces`.
std::string Indented(const std::string& text, int spaces) {
  std::istringstream in(text);
  std::string out;
  for (std::string line; std::getline(in, line);) out += std::string(spaces, ' ') + line + "\n";
  return out;
}

// True where the polygons hold the same points, in any order.
::testing::AssertionResult SamePoints(const std::vector<Eigen::Vector2d>& actual,
                                      const std::vector<Eigen::Vector2d>& expected) {
  if (actual.size() != expected.size()) {
    return ::testing::AssertionFailure()
           << actual.size() << " points, expected " << expected.size();
  }
  for (const Eigen::Vector2d& p : expected) {
    const bool found = std::any_of(actual.begin(), actual.end(), [&p](const Eigen::Vector2d& q) {
      return (p - q).norm() < 1e-12;
    });
    if (!found) return ::testing::AssertionFailure() << "no point (" << p.transpose() << ")";
  }
  return ::testing::AssertionSuccess();
}

// Twice the signed area: positive for a counter-clockwise polygon.
double TwiceArea(const std::vector<Eigen::Vector2d>& points) {
  double sum = 0.0;
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d& a = points[i];
    const Eigen::Vector2d& b = points[(i + 1) % points.size()];
    sum += a.x() * b.y() - a.y() * b.x();
  }
  return sum;
}

TEST(WorldFileTest, LoadsEveryValue) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const sim::World world = LoadWorldFile(dir.Write("world.yaml", kWorld));

  EXPECT_EQ(world.name(), "test-world");
  EXPECT_EQ(world.floor().size, Eigen::Vector2d(2.0, 1.5));
  EXPECT_EQ(world.floor().colour, (core::Rgb{25, 30, 35}));
  EXPECT_EQ(world.floor().texture, 0.03);
  ASSERT_TRUE(world.walls().has_value());
  EXPECT_EQ(world.walls()->height, 0.10);
  EXPECT_EQ(world.walls()->thickness, 0.02);
  EXPECT_EQ(world.walls()->colour, (core::Rgb{235, 236, 237}));

  ASSERT_EQ(world.obstacles().size(), 4u);
  const sim::Solid& box = world.obstacles()[0];
  EXPECT_EQ(box.kind, sim::Solid::Kind::kBox);
  EXPECT_EQ(box.height, 0.08);
  EXPECT_EQ(box.colour, (core::Rgb{200, 40, 40}));
  const double yaw = core::DegToRad(30.0);
  const Eigen::Vector2d along(std::cos(yaw), std::sin(yaw));  // size.x lies along the yaw
  const Eigen::Vector2d across(-std::sin(yaw), std::cos(yaw));
  const Eigen::Vector2d centre(0.40, 0.90);
  std::vector<Eigen::Vector2d> corners;
  for (const double a : {-0.05, 0.05}) {
    for (const double b : {-0.10, 0.10}) corners.emplace_back(centre + a * along + b * across);
  }
  EXPECT_TRUE(SamePoints(box.footprint, corners));

  const sim::Solid& cylinder = world.obstacles()[1];
  EXPECT_EQ(cylinder.kind, sim::Solid::Kind::kCylinder);
  ASSERT_TRUE(cylinder.circle.has_value());
  EXPECT_EQ(cylinder.circle->centre, Eigen::Vector2d(1.10, 0.30));
  EXPECT_EQ(cylinder.circle->radius, 0.05);
  EXPECT_EQ(cylinder.height, 0.10);
  EXPECT_EQ(cylinder.colour, (core::Rgb{40, 160, 40}));

  const sim::Solid& wall = world.obstacles()[2];
  EXPECT_EQ(wall.kind, sim::Solid::Kind::kWall);
  EXPECT_TRUE(SamePoints(wall.footprint, {{0.0, 0.64}, {0.8, 0.64}, {0.8, 0.66}, {0.0, 0.66}}));
  EXPECT_EQ(wall.height, 0.12);
  EXPECT_EQ(wall.colour, (core::Rgb{230, 230, 230}));

  const sim::Solid& prism = world.obstacles()[3];
  EXPECT_EQ(prism.kind, sim::Solid::Kind::kPrism);
  EXPECT_EQ(prism.footprint, (std::vector<Eigen::Vector2d>{{1.0, 1.0}, {1.2, 1.0}, {1.1, 1.2}}));
  EXPECT_EQ(prism.height, 0.06);
  EXPECT_EQ(prism.colour, (core::Rgb{40, 40, 200}));

  EXPECT_EQ(world.light().ambient, 0.5);
  EXPECT_EQ(world.light().direction, Eigen::Vector3d(0.1, 0.2, -1.0));
  EXPECT_EQ(world.light().intensity, 0.7);

  const sim::RobotSpec& robot = world.robot();
  EXPECT_EQ(robot.start.x(), 0.20);
  EXPECT_EQ(robot.start.y(), 0.20);
  EXPECT_DOUBLE_EQ(robot.start.heading(), core::DegToRad(45.0));
  EXPECT_EQ(robot.radius, 0.04);
  EXPECT_EQ(robot.camera.name(), "test");
  EXPECT_EQ(robot.camera.width(), 320);
  EXPECT_EQ(robot.camera.intrinsics().fy, 276.5);
  EXPECT_EQ(robot.camera.mount().tilt_rad, core::DegToRad(30.0));
  EXPECT_EQ(robot.odometry_noise.translation, 0.01);
  EXPECT_EQ(robot.odometry_noise.rotation, 0.02);
}

TEST(WorldFileTest, TextReadsAsItsFileWouldAtThatPath) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  // Not written (yet): the camera is found beside the path all the same.
  const std::string path = dir / "world.yaml";
  const sim::World world = ParseWorldText(kWorld, path);
  EXPECT_TRUE(testing::SameWorld(world, LoadWorldFile(dir.Write("world.yaml", kWorld))));
  const core::InputError error =
      ExpectInputError([&] { ParseWorldText(EditedWorld("radius: 0.04", "radius: -1"), path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.field(), "robot.radius");
  EXPECT_EQ(error.line(), 22);
}

TEST(WorldFileTest, OptionalFieldsTakeTheirDefaults) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const std::string text =
      "format: pirouette-world/1\n"
      "name: bare\n"
      "floor: {size: [1.0, 1.0], colour: [0, 0, 0]}\n"
      "robot: {start: [0.5, 0.5, -90], radius: 0.1, camera: cam.yaml}\n";
  const sim::World world = LoadWorldFile(dir.Write("world.yaml", text));
  EXPECT_EQ(world.floor().texture, 0.0);
  EXPECT_FALSE(world.walls().has_value());
  EXPECT_TRUE(world.obstacles().empty());
  const sim::Light defaults;
  EXPECT_EQ(world.light().ambient, defaults.ambient);
  EXPECT_EQ(world.light().direction, defaults.direction);
  EXPECT_EQ(world.light().intensity, defaults.intensity);
  EXPECT_EQ(world.robot().odometry_noise.translation, 0.0);
  EXPECT_EQ(world.robot().odometry_noise.rotation, 0.0);
  EXPECT_DOUBLE_EQ(world.robot().start.heading(), core::DegToRad(-90.0));
}

TEST(WorldFileTest, PartialLightKeepsTheOtherDefaults) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const sim::World world = LoadWorldFile(dir.Write(
      "world.yaml", EditedWorld("  direction: [0.1, 0.2, -1.0]\n  intensity: 0.7\n", "")));
  EXPECT_EQ(world.light().ambient, 0.5);
  EXPECT_EQ(world.light().direction, sim::Light().direction);
  EXPECT_EQ(world.light().intensity, sim::Light().intensity);
}

TEST(WorldFileTest, BoxWithoutYawIsAxisAligned) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const sim::World world = LoadWorldFile(dir.Write("world.yaml", EditedWorld("yaw: 30, ", "")));
  EXPECT_TRUE(SamePoints(world.obstacles()[0].footprint,
                         {{0.35, 0.80}, {0.45, 0.80}, {0.45, 1.00}, {0.35, 1.00}}));
}

TEST(WorldFileTest, PrismMayBeClockwiseOrAClosedRing) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const sim::World world = LoadWorldFile(
      dir.Write("world.yaml", EditedWorld("[[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]]",
                                          "[[1.0, 1.0], [1.1, 1.2], [1.2, 1.0], [1.0, 1.0]]")));
  const std::vector<Eigen::Vector2d>& footprint = world.obstacles()[3].footprint;
  EXPECT_TRUE(SamePoints(footprint, {{1.0, 1.0}, {1.2, 1.0}, {1.1, 1.2}}));
  EXPECT_GT(TwiceArea(footprint), 0.0);
}

TEST(WorldFileTest, CameraPathIsRelativeToTheWorldFilesFolder) {
  const TempDir dir;
  dir.Write("cams/other.yaml", kWorldCamera);
  const std::string path =
      dir.Write("worlds/world.yaml", EditedWorld("camera: cam.yaml", "camera: ../cams/other.yaml"));
  const fs::path cwd = fs::current_path();
  fs::current_path(fs::temp_directory_path());
  const sim::World world = LoadWorldFile(fs::relative(path).string());
  fs::current_path(cwd);
  EXPECT_EQ(world.robot().camera.name(), "test");
}

TEST(WorldFileTest, CameraPathMayBeAbsolute) {
  const TempDir dir;
  const std::string camera = dir.Write("elsewhere/cam.yaml", kWorldCamera);
  const sim::World world =
      LoadWorldFile(dir.Write("world.yaml", EditedWorld("camera: cam.yaml", "camera: " + camera)));
  EXPECT_EQ(world.robot().camera.name(), "test");
}

TEST(WorldFileTest, ReadsOdometryBiasesAndRefusesLargeOnes) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const sim::World world = LoadWorldFile(
      dir.Write("world.yaml", EditedWorld("    rotation: 0.02\n",
                                          "    rotation: 0.02\n    translation_bias: 0.03\n"
                                          "    rotation_bias: -0.01\n")));
  EXPECT_EQ(world.robot().odometry_noise.translation_bias, 0.03);
  EXPECT_EQ(world.robot().odometry_noise.rotation_bias, -0.01);
  EXPECT_THROW(LoadWorldFile(dir.Write("bad.yaml", EditedWorld("    rotation: 0.02\n",
                                                               "    rotation: 0.02\n"
                                                               "    rotation_bias: 0.7\n"))),
               core::InputError);
}

TEST(WorldFileTest, CameraMayBeInline) {
  const TempDir dir;
  const sim::World world = LoadWorldFile(
      dir.Write("world.yaml",
                EditedWorld("  camera: cam.yaml\n", "  camera:\n" + Indented(kWorldCamera, 4))));
  EXPECT_EQ(world.robot().camera.name(), "test");
  EXPECT_EQ(world.robot().camera.mount().height_m, 0.11);
  EXPECT_EQ(world.robot().odometry_noise.rotation, 0.02);
}

TEST(WorldFileTest, RefusesABadInlineCameraFieldAtItsLineInTheWorldFile) {
  const TempDir dir;
  const std::string camera = Edited(kWorldCamera, "tilt: 30", "tilt: 95");
  const std::string path = dir.Write(
      "world.yaml", EditedWorld("  camera: cam.yaml\n", "  camera:\n" + Indented(camera, 4)));
  const core::InputError error = ExpectInputError([&] { LoadWorldFile(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.field(), "robot.camera.mount.tilt");
  EXPECT_EQ(error.line(), 23 + 9);
}

TEST(WorldFileTest, RefusesAnUnknownInlineCameraKey) {
  const TempDir dir;
  const std::string path = dir.Write(
      "world.yaml", EditedWorld("  camera: cam.yaml\n",
                                "  camera:\n" + Indented(kWorldCamera, 4) + "    zoom: 2\n"));
  const core::InputError error = ExpectInputError([&] { LoadWorldFile(path); });
  EXPECT_EQ(error.field(), "robot.camera.zoom");
  EXPECT_EQ(error.line(), 23 + 11);
}

TEST(WorldFileTest, ABadCameraFileIsReportedInTheCameraFile) {
  const TempDir dir;
  const std::string camera = dir.Write("cam.yaml", Edited(kWorldCamera, "tilt: 30", "tilt: 95"));
  const core::InputError error =
      ExpectInputError([&] { LoadWorldFile(dir.Write("world.yaml", kWorld)); });
  EXPECT_EQ(error.file(), camera);
  EXPECT_EQ(error.field(), "mount.tilt");
  EXPECT_EQ(error.line(), 9);
}

TEST(WorldFileTest, RefusesAMissingCameraFile) {
  const TempDir dir;
  const std::string path = dir.Write("world.yaml", kWorld);
  const core::InputError error = ExpectInputError([&] { LoadWorldFile(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.field(), "robot.camera");
  EXPECT_EQ(error.line(), 23);
  EXPECT_NE(std::string(error.what()).find("cam.yaml' not found"), std::string::npos)
      << error.what();
}

TEST(WorldFileTest, RefusesAMissingFile) {
  const TempDir dir;
  const std::string path = (dir.path() / "nosuch.yaml").string();
  const core::InputError error = ExpectInputError([&] { LoadWorldFile(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.line(), 0);
  EXPECT_EQ(error.field(), "");
}

TEST(WorldFileTest, RefusesAnEmptyFile) {
  const TempDir dir;
  for (const std::string text : {"", "# nothing but a comment\n"}) {
    const std::string path = dir.Write("world.yaml", text);
    const core::InputError error = ExpectInputError([&] { LoadWorldFile(path); });
    EXPECT_EQ(error.file(), path);
    EXPECT_EQ(error.line(), 0);
    EXPECT_NE(std::string(error.what()).find("empty"), std::string::npos) << error.what();
  }
}

TEST(WorldFileTest, RefusesMalformedYamlAtItsLine) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const std::string path =
      dir.Write("world.yaml", EditedWorld("  ambient: 0.5\n", "  ambient: 0.5\n   x: : :\n"));
  const core::InputError error = ExpectInputError([&] { LoadWorldFile(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.line(), 18);
  EXPECT_NE(std::string(error.what()).find("malformed YAML"), std::string::npos) << error.what();
}

TEST(WorldFileTest, RefusesObstaclesThatAreNotAList) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  std::string text = kWorld;
  const std::size_t begin = text.find("obstacles:\n");
  text.replace(begin, text.find("light:\n") - begin, "obstacles: 3\n");
  const core::InputError error =
      ExpectInputError([&] { LoadWorldFile(dir.Write("world.yaml", text)); });
  EXPECT_EQ(error.field(), "obstacles");
  EXPECT_EQ(error.line(), 11);
  EXPECT_NE(std::string(error.what()).find("expected a list of obstacles, got the number 3"),
            std::string::npos)
      << error.what();
}

TEST(WorldFileTest, RefusesATopLevelThatIsNotAMap) {
  const TempDir dir;
  const core::InputError error =
      ExpectInputError([&] { LoadWorldFile(dir.Write("world.yaml", "just words\n")); });
  EXPECT_EQ(error.field(), "");
  EXPECT_EQ(error.line(), 1);
}

struct WorldBadCase {
  const char* name;
  const char* from;  // text of kWorld...
  const char* to;    // ...replaced by this
  const char* field;
  int line;
  const char* message;  // a part of the message
};

class WorldFileBadInputTest : public ::testing::TestWithParam<WorldBadCase> {};

TEST_P(WorldFileBadInputTest, IsRefusedWithFieldAndLine) {
  const WorldBadCase& c = GetParam();
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const std::string path = dir.Write("world.yaml", EditedWorld(c.from, c.to));
  const core::InputError error = ExpectInputError([&] { LoadWorldFile(path); });
  EXPECT_EQ(error.file(), path);
  EXPECT_EQ(error.field(), c.field) << error.what();
  EXPECT_EQ(error.line(), c.line) << error.what();
  EXPECT_NE(std::string(error.what()).find(c.message), std::string::npos) << error.what();
}

const WorldBadCase kWorldBadCases[] = {
    // The format.
    {"MissingFormat", "format: pirouette-world/1\n", "", "format", 1, "missing required key"},
    {"WrongFormat", "format: pirouette-world/1", "format: pirouette-world/2", "format", 1,
     "expected 'pirouette-world/1', got 'pirouette-world/2'"},
    {"FormatNotAString", "format: pirouette-world/1", "format: 1", "format", 1,
     "expected a string, got the number 1"},
    // Unknown and duplicate keys.
    {"UnknownKey", "    rotation: 0.02\n", "    rotation: 0.02\ngravity: 9.8\n", "gravity", 27,
     "unknown key"},
    {"UnknownFloorKey", "  texture: 0.03", "  textur: 0.03", "floor.textur", 6, "unknown key"},
    {"UnknownObstacleKey", "yaw: 30, ", "yaw: 30, tilt: 5, ", "obstacles[0].box.tilt", 12,
     "unknown key"},
    {"UnknownRobotKey", "  radius: 0.04\n", "  radius: 0.04\n  speed: 1\n", "robot.speed", 23,
     "unknown key"},
    {"DuplicateKey", "name: test-world\n", "name: test-world\nname: again\n", "name", 3,
     "duplicate key (first given on line 2)"},
    // Missing required keys: reported at the map that lacks them.
    {"MissingName", "name: test-world\n", "", "name", 1, "missing required key"},
    {"MissingFloor", "floor:\n  size: [2.0, 1.5]\n  colour: [25, 30, 35]\n  texture: 0.03\n", "",
     "floor", 1, "missing required key"},
    {"MissingFloorColour", "  colour: [25, 30, 35]\n", "", "floor.colour", 4,
     "missing required key"},
    {"MissingWallThickness", "  thickness: 0.02\n", "", "walls.thickness", 8,
     "missing required key"},
    {"MissingCylinderRadius", "radius: 0.05, ", "", "obstacles[1].cylinder.radius", 13,
     "missing required key"},
    {"MissingPrismColour", ", height: 0.06, colour: [40, 40, 200]}", ", height: 0.06}",
     "obstacles[3].prism.colour", 15, "missing required key"},
    {"MissingRobotRadius", "  radius: 0.04\n", "", "robot.radius", 21, "missing required key"},
    {"MissingCamera", "  camera: cam.yaml\n", "", "robot.camera", 21, "missing required key"},
    {"MissingRobot",
     "robot:\n  start: [0.20, 0.20, 45]\n  radius: 0.04\n  camera: cam.yaml\n  odometry_noise:\n"
     "    translation: 0.01\n    rotation: 0.02\n",
     "", "robot", 1, "missing required key"},
    // Wrong types.
    {"NameNotAString", "name: test-world", "name: 42", "name", 2,
     "expected a string, got the number 42"},
    {"SizeNotAList", "  size: [2.0, 1.5]", "  size: big", "floor.size", 4,
     "expected a list of 2 numbers, got the string 'big'"},
    {"SizeItemNotANumber", "  size: [2.0, 1.5]", "  size: [2.0, wide]", "floor.size", 4,
     "item 2 of 2: expected a number, got the string 'wide'"},
    {"SizeThreeItems", "  size: [2.0, 1.5]", "  size: [2.0, 1.5, 1]", "floor.size", 4,
     "expected a list of 2 numbers, got 3 items"},
    {"FloorNotAMap", "floor:\n  size: [2.0, 1.5]\n  colour: [25, 30, 35]\n  texture: 0.03\n",
     "floor: [2.0, 1.5]\n", "floor", 3, "expected a map of fields, got a list"},
    {"ObstacleNotAMap",
     "  - cylinder: {centre: [1.10, 0.30], radius: 0.05, height: 0.10, colour: "
     "[40, 160, 40]}\n",
     "  - cylinder\n", "obstacles[1]", 13, "expected a map of fields"},
    {"HeightQuoted", "height: 0.08", "height: '0.08'", "obstacles[0].box.height", 12,
     "expected a number, got the string '0.08'"},
    {"TextureEmpty", "  texture: 0.03", "  texture:", "floor.texture", 6,
     "expected a number, got nothing"},
    {"StartTwoNumbers", "start: [0.20, 0.20, 45]", "start: [0.20, 0.20]", "robot.start", 21,
     "expected a list of 3 numbers, got 2 items"},
    {"CameraNotAString", "camera: cam.yaml", "camera: 5", "robot.camera", 23,
     "expected a camera file's name or the camera's fields (a map), got the number 5"},
    {"CameraEmpty", "camera: cam.yaml", "camera: ''", "robot.camera", 23, "empty string"},
    {"CameraFolder", "camera: cam.yaml", "camera: .", "robot.camera", 23, "is a folder"},
    // Sizes.
    {"FloorSizeNegative", "  size: [2.0, 1.5]", "  size: [-2.0, 1.5]", "floor.size", 4,
     "item 1 of 2: must be > 0, got -2"},
    {"BoxSizeNegative", "size: [0.10, 0.20]", "size: [0.10, -0.20]", "obstacles[0].box.size", 12,
     "item 2 of 2: must be > 0"},
    {"BoxHeightZero", "height: 0.08", "height: 0", "obstacles[0].box.height", 12, "must be > 0"},
    {"CylinderRadiusNegative", "radius: 0.05", "radius: -0.05", "obstacles[1].cylinder.radius", 13,
     "must be > 0"},
    {"WallThicknessZero", "thickness: 0.02, height: 0.12", "thickness: 0, height: 0.12",
     "obstacles[2].wall.thickness", 14, "must be > 0"},
    {"WallWithoutLength", "to: [0.80, 0.65]", "to: [0.00, 0.65]", "obstacles[2].wall.to", 14,
     "no length"},
    {"BoundaryWallHeightZero", "  height: 0.10\n", "  height: 0\n", "walls.height", 8,
     "must be > 0"},
    {"RobotRadiusZero", "  radius: 0.04", "  radius: 0", "robot.radius", 22, "must be > 0"},
    {"TextureAboveOne", "texture: 0.03", "texture: 1.5", "floor.texture", 6, "must lie in [0, 1]"},
    {"AmbientNegative", "ambient: 0.5", "ambient: -0.1", "light.ambient", 17, "must lie in [0, 1]"},
    {"IntensityAboveOne", "intensity: 0.7", "intensity: 2", "light.intensity", 19,
     "must lie in [0, 1]"},
    {"LightGoingUp", "direction: [0.1, 0.2, -1.0]", "direction: [0.1, 0.2, 1.0]", "light.direction",
     18, "downward"},
    {"LightTwoNumbers", "direction: [0.1, 0.2, -1.0]", "direction: [0.1, -1.0]", "light.direction",
     18, "expected a list of 3 numbers"},
    {"NoiseNegative", "rotation: 0.02", "rotation: -0.02", "robot.odometry_noise.rotation", 26,
     "must be >= 0"},
    // Colours.
    {"ColourAbove255", "colour: [25, 30, 35]", "colour: [25, 300, 35]", "floor.colour", 5,
     "item 2 of 3: expected a whole number 0..255, got 300"},
    {"ColourNegative", "colour: [25, 30, 35]", "colour: [-1, 30, 35]", "floor.colour", 5,
     "item 1 of 3: expected a whole number 0..255, got -1"},
    {"ColourNotWhole", "colour: [25, 30, 35]", "colour: [25, 30, 12.5]", "floor.colour", 5,
     "item 3 of 3: expected a whole number 0..255, got 12.5"},
    {"ColourTwoItems", "colour: [25, 30, 35]", "colour: [25, 30]", "floor.colour", 5,
     "got 2 items"},
    {"ColourAName", "colour: [25, 30, 35]", "colour: red", "floor.colour", 5,
     "expected a colour [r, g, b] of whole numbers 0..255, got the string 'red'"},
    {"ObstacleColourOutOfRange", "colour: [40, 160, 40]", "colour: [40, 256, 40]",
     "obstacles[1].cylinder.colour", 13, "0..255"},
    {"WallColourOnItsOwnLine", "  colour: [235, 236, 237]\n",
     "  colour:\n    - 235\n    - 236\n    - 237.5\n", "walls.colour", 13, "item 3 of 3"},
    // Obstacle items.
    {"ObstacleWithTwoShapes",
     "  - cylinder: {centre: [1.10, 0.30], radius: 0.05, height: 0.10, colour: [40, 160, 40]}\n",
     "  - cylinder: {centre: [1.10, 0.30], radius: 0.05, height: 0.10, colour: [40, 160, 40]}\n"
     "    box: {centre: [1.5, 1.0], size: [0.1, 0.1], height: 0.1, colour: [1, 2, 3]}\n",
     "obstacles[1]", 13,
     "exactly one key, its shape (box, cylinder, wall, prism, grid or chessboard); got 2 "
     "(cylinder, box)"},
    {"ObstacleWithNoShape",
     "  - prism: {points: [[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]], height: "
     "0.06, colour: [40, 40, 200]}\n",
     "  - {}\n", "obstacles[3]", 15, "got 0"},
    {"UnknownShape", "  - prism:", "  - pyramid:", "obstacles[3].pyramid", 15, "unknown shape"},
    // Prisms.
    {"PrismTwoPoints", "[[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]]", "[[1.0, 1.0], [1.2, 1.0]]",
     "obstacles[3].prism.points", 15, "at least 3 points, got 2"},
    {"PrismSelfIntersecting", "[[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]]",
     "[[1.0, 1.0], [1.2, 1.2], [1.2, 1.0], [1.0, 1.2]]", "obstacles[3].prism.points", 15,
     "the edge from point 1 to point 2 meets the edge from point 3 to point 4"},
    {"PrismTouchingItself", "[[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]]",
     "[[1.0, 1.0], [1.4, 1.0], [1.4, 1.4], [1.2, 1.0], [1.0, 1.4]]", "obstacles[3].prism.points",
     15, "not simple"},
    {"PrismCollinear", "[[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]]",
     "[[1.0, 1.0], [1.1, 1.0], [1.2, 1.0]]", "obstacles[3].prism.points", 15, "no area"},
    {"PrismFoldsBack", "[[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]]",
     "[[1.0, 1.0], [1.2, 1.0], [1.1, 1.0], [1.1, 1.2]]", "obstacles[3].prism.points", 15,
     "folds back"},
    {"PrismRepeatedPoint", "[[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]]",
     "[[1.0, 1.0], [1.2, 1.0], [1.2, 1.0], [1.1, 1.2]]", "obstacles[3].prism.points", 15,
     "points 2 and 3 are the same point"},
    {"PrismPointWithThreeNumbers", "[[1.0, 1.0], [1.2, 1.0], [1.1, 1.2]]",
     "[[1.0, 1.0], [1.2, 1.0, 0.0], [1.1, 1.2]]", "obstacles[3].prism.points[1]", 15,
     "expected a list of 2 numbers, got 3 items"},
    // The start.
    {"StartOnAnObstacle", "start: [0.20, 0.20, 45]", "start: [1.10, 0.30, 45]", "robot.start", 21,
     "overlaps obstacles[1] (the cylinder on line 13)"},
    {"StartTouchingAnObstacle", "start: [0.20, 0.20, 45]", "start: [1.10, 0.36, 0]", "robot.start",
     21, "overlaps obstacles[1]"},
    {"StartOnAWall", "start: [0.20, 0.20, 45]", "start: [0.40, 0.68, 0]", "robot.start", 21,
     "overlaps obstacles[2] (the wall on line 14)"},
    {"StartOffTheFloor", "start: [0.20, 0.20, 45]", "start: [2.50, 0.20, 45]", "robot.start", 21,
     "does not lie on the floor"},
    {"StartDiscLeavesTheFloor", "start: [0.20, 0.20, 45]", "start: [0.03, 0.50, 45]", "robot.start",
     21, "does not lie on the floor"},
};

INSTANTIATE_TEST_SUITE_P(AllCases, WorldFileBadInputTest, ::testing::ValuesIn(kWorldBadCases),
                         [](const ::testing::TestParamInfo<WorldBadCase>& info) {
                           return std::string(info.param.name);
                         });

// ---------------------------------------------------------------------------
// The worlds shipped in worlds/.

const char* const kShippedWorlds[] = {"soccer_field", "maze", "two_rooms", "cluttered_room",
                                      "apartment"};

std::string ShippedWorldPath(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml";
}

// The fraction of the free floor, sampled on a grid of `cell` metres, whose
// cells the robot's disc can reach from the start (4-connected moves between
// cell centres where the disc fits).
double ReachableFraction(const sim::World& world, double cell) {
  const double radius = world.robot().radius;
  const int nx = static_cast<int>(std::floor(world.floor().size.x() / cell));
  const int ny = static_cast<int>(std::floor(world.floor().size.y() / cell));
  const auto centre = [&](int i, int j) {
    return Eigen::Vector2d((i + 0.5) * cell, (j + 0.5) * cell);
  };
  std::vector<char> fits(static_cast<std::size_t>(nx) * ny);
  int free = 0;
  for (int j = 0; j < ny; ++j) {
    for (int i = 0; i < nx; ++i) {
      fits[j * nx + i] = world.DiscFits(centre(i, j), radius);
      free += fits[j * nx + i];
    }
  }
  // Start from the cell nearest the start pose where the disc fits.
  int start = -1;
  double best = 1e9;
  for (int k = 0; k < nx * ny; ++k) {
    const double d = (centre(k % nx, k / nx) - world.robot().start.translation()).norm();
    if (fits[k] && d < best) {
      best = d;
      start = k;
    }
  }
  if (start < 0 || best > cell) return 0.0;
  std::vector<char> seen(fits.size(), 0);
  std::deque<int> queue{start};
  seen[start] = 1;
  int reached = 0;
  while (!queue.empty()) {
    const int k = queue.front();
    queue.pop_front();
    ++reached;
    const int i = k % nx;
    const int j = k / nx;
    const int neighbours[4][2] = {{i - 1, j}, {i + 1, j}, {i, j - 1}, {i, j + 1}};
    for (const auto& n : neighbours) {
      if (n[0] < 0 || n[0] >= nx || n[1] < 0 || n[1] >= ny) continue;
      const int m = n[1] * nx + n[0];
      if (fits[m] && !seen[m]) {
        seen[m] = 1;
        queue.push_back(m);
      }
    }
  }
  return static_cast<double>(reached) / free;
}

int ColourDistance(core::Rgb a, core::Rgb b) {
  return std::abs(a.r - b.r) + std::abs(a.g - b.g) + std::abs(a.b - b.b);
}

class ShippedWorldTest : public ::testing::TestWithParam<const char*> {};

TEST_P(ShippedWorldTest, LoadsWithEveryFreeCellReachable) {
  const sim::World world = LoadWorldFile(ShippedWorldPath(GetParam()));
  EXPECT_FALSE(world.obstacles().empty());
  EXPECT_TRUE(world.DiscFits(world.robot().start.translation(), world.robot().radius));
  for (const sim::Solid& solid : world.solids()) {
    EXPECT_GE(ColourDistance(solid.colour, world.floor().colour), 90)
        << "a solid's colour is too close to the floor's";
  }
  EXPECT_EQ(ReachableFraction(world, 0.01), 1.0);
}

INSTANTIATE_TEST_SUITE_P(Worlds, ShippedWorldTest, ::testing::ValuesIn(kShippedWorlds),
                         [](const ::testing::TestParamInfo<const char*>& info) {
                           return std::string(info.param);
                         });

// Every world file in worlds/ (the YAML files with a `format:` line) is in kShippedWorlds.
TEST(WorldFileTest, EveryShippedWorldIsTested) {
  std::vector<std::string> found;
  for (const auto& entry : fs::directory_iterator(PIROUETTE_WORLDS_DIR)) {
    if (entry.path().extension() != ".yaml") continue;
    std::ifstream in(entry.path());
    const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    if (text.rfind("format:", 0) == 0 || text.find("\nformat:") != std::string::npos) {
      found.push_back(entry.path().stem().string());
    }
  }
  std::vector<std::string> expected(std::begin(kShippedWorlds), std::end(kShippedWorlds));
  std::sort(found.begin(), found.end());
  std::sort(expected.begin(), expected.end());
  EXPECT_EQ(found, expected);
}

TEST(WorldFileTest, SoccerFieldIsThePapersEnvironment) {
  const sim::World world = LoadWorldFile(ShippedWorldPath("soccer_field"));
  EXPECT_EQ(world.floor().size, Eigen::Vector2d(1.50, 1.30));
  EXPECT_EQ(world.robot().radius, 0.04);
  EXPECT_EQ(world.robot().camera.name(), "yujin");
  ASSERT_TRUE(world.walls().has_value());
  EXPECT_EQ(world.walls()->height, 0.10);
}

TEST(WorldFileTest, ChessboardIsDrawnButNoObstacle) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const sim::World world = LoadWorldFile(dir.Write(
      "world.yaml", EditedWorld("obstacles:\n",
                                "obstacles:\n  - chessboard: {centre: [1.5, 1.0], cols: 9, "
                                "rows: 6, square: 0.025, yaw: 90}\n")));
  ASSERT_EQ(world.chessboards().size(), 1u);
  const sim::Chessboard& board = world.chessboards()[0];
  EXPECT_EQ(board.cols, 9);
  EXPECT_EQ(board.rows, 6);
  EXPECT_DOUBLE_EQ(board.square, 0.025);
  EXPECT_NEAR(board.yaw_rad, core::DegToRad(90.0), 1e-12);
  // Cols run along the yaw (+y here), rows across it (-x).
  EXPECT_TRUE(board.InnerCorner(0, 0).isApprox(Eigen::Vector2d(1.5 + 0.0625, 1.0 - 0.1), 1e-12));
  EXPECT_TRUE(board.InnerCorner(8, 5).isApprox(Eigen::Vector2d(1.5 - 0.0625, 1.0 + 0.1), 1e-12));
  EXPECT_EQ(world.obstacles().size(), 4u);  // the board is none of them
  EXPECT_FALSE(world.IsOccupied(board.centre));
  // A start on the board is fine, and the obstacles' indices in messages skip nothing.
  dir.Write("world2.yaml", EditedWorld("obstacles:\n",
                                       "obstacles:\n  - chessboard: {centre: "
                                       "[0.2, 0.2], cols: 3, rows: 2, square: 0.1}\n"));
  EXPECT_EQ(LoadWorldFile((dir.path() / "world2.yaml").string()).chessboards().size(), 1u);
}

TEST(WorldFileTest, RefusesBadChessboards) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const auto error_for = [&dir](const std::string& board) {
    const std::string path = dir.Write(
        "world.yaml", EditedWorld("obstacles:\n", "obstacles:\n  - chessboard: " + board + "\n"));
    return ExpectInputError([&path] { LoadWorldFile(path); });
  };
  const auto bad_rows = error_for("{centre: [1, 1], cols: 9, rows: 1, square: 0.02}");
  EXPECT_EQ(bad_rows.line(), 12);
  EXPECT_EQ(bad_rows.field(), "obstacles[0].chessboard.rows");
  EXPECT_EQ(error_for("{centre: [1, 1], cols: 9.5, rows: 6, square: 0.02}").field(),
            "obstacles[0].chessboard.cols");
  EXPECT_EQ(error_for("{centre: [1, 1], cols: 9, rows: 6, square: -0.02}").field(),
            "obstacles[0].chessboard.square");
  EXPECT_EQ(error_for("{centre: [1, 1], cols: 9, rows: 6}").field(),
            "obstacles[0].chessboard.square");
  EXPECT_EQ(error_for("{centre: [1, 1], cols: 9, rows: 6, square: 0.02, size: 3}").field(),
            "obstacles[0].chessboard.size");
}

// A grid obstacle: a 4 x 3 map at 0.5 m beside the world file, its occupied
// and unknown cells standing as blocks from the world's (0, 0).
TEST(WorldFileTest, AGridStandsTheMapsCellsUpAsBlocks) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  // Top row first: the top row occupied, unknown, free, free.
  dir.Write("maps/m.pgm", "P2\n4 3\n255\n0 205 254 254\n254 254 254 254\n254 254 254 0\n");
  dir.Write("maps/m.yaml",
            "image: m.pgm\nresolution: 0.5\norigin: [-7, 3, 0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  const std::string grid =
      "obstacles:\n  - grid: {map: maps/m.yaml, height: 0.3, colour: [1, 2, 3]}\n";
  std::string world = kWorld;
  const std::size_t from = world.find("obstacles:");
  const std::size_t to = world.find("light:");
  world.replace(from, to - from, grid);
  world = Edited(world, "start: [0.20, 0.20, 45]", "start: [0.75, 0.75, 45]");
  const sim::World w = LoadWorldFile(dir.Write("world.yaml", world));
  EXPECT_TRUE(w.IsOccupied({0.25, 1.25}));   // occupied, top left
  EXPECT_TRUE(w.IsOccupied({0.75, 1.25}));   // unknown
  EXPECT_FALSE(w.IsOccupied({1.25, 1.25}));  // free
  EXPECT_TRUE(w.IsOccupied({1.75, 0.25}));   // occupied, bottom right
  EXPECT_FALSE(w.IsOccupied({1.25, 0.25}));
  std::size_t grid_solids = 0;
  for (const sim::Solid& solid : w.obstacles()) {
    if (solid.kind == sim::Solid::Kind::kGridBlock) {
      ++grid_solids;
      EXPECT_EQ(solid.height, 0.3);
      EXPECT_EQ(solid.colour, (core::Rgb{1, 2, 3}));
    }
  }
  EXPECT_EQ(grid_solids, 2U);  // the top row's run and the lone cell

  // A start on a block is named with the grid's line.
  const std::string on_block = Edited(world, "start: [0.75, 0.75, 45]", "start: [1.6, 0.4, 0]");
  const core::InputError error =
      ExpectInputError([&] { LoadWorldFile(dir.Write("world.yaml", on_block)); });
  EXPECT_EQ(error.field(), "robot.start");
  EXPECT_NE(std::string(error.what()).find("the grid on line 12"), std::string::npos)
      << error.what();

  // A missing map, a missing height, a seal that is not a boolean.
  for (const auto& [edit, field] : std::vector<std::pair<std::string, std::string>>{
           {"map: maps/none.yaml", "obstacles[0].grid.map"},
           {"height: 0.3, ", "obstacles[0].grid.height"},
           {"colour: [1, 2, 3]", "obstacles[0].grid"}}) {
    std::string bad = world;
    if (field == "obstacles[0].grid") {
      bad = Edited(world, "colour: [1, 2, 3]}", "colour: [1, 2, 3], seal: 3}");
    } else if (field == "obstacles[0].grid.map") {
      bad = Edited(world, "map: maps/m.yaml", edit);
    } else {
      bad = Edited(world, edit, "");
    }
    const core::InputError e = ExpectInputError([&] { LoadWorldFile(dir.Write("bad.yaml", bad)); });
    EXPECT_EQ(e.field().substr(0, field.size()), field) << edit << ": " << e.what();
  }
}

// Worlds too large for the machine's memory are refused, naming the field:
// a floor of kilometres; a map whose cells make more blocks than any world
// needs (a checkerboard of 700 x 700 cells: 245,000 blocks no run merges).
TEST(WorldFileTest, RefusesWorldsTooLargeForMemory) {
  const TempDir dir;
  dir.Write("cam.yaml", kWorldCamera);
  const core::InputError floor = ExpectInputError([&] {
    LoadWorldFile(dir.Write("floor.yaml", EditedWorld("size: [2.0, 1.5]", "size: [2000, 1.5]")));
  });
  EXPECT_EQ(floor.field().substr(0, 5), "floor");
  EXPECT_NE(std::string(floor.what()).find("at most 1000 m"), std::string::npos) << floor.what();

  constexpr int kSide = 700;
  std::string pgm = "P5\n" + std::to_string(kSide) + " " + std::to_string(kSide) + "\n255\n";
  for (int y = 0; y < kSide; ++y) {
    for (int x = 0; x < kSide; ++x) pgm += static_cast<char>((x + y) % 2 == 0 ? 0 : 254);
  }
  dir.Write("maps/checker.pgm", pgm);
  dir.Write("maps/checker.yaml",
            "image: checker.pgm\nresolution: 0.002\norigin: [0, 0, 0]\nnegate: 0\n"
            "occupied_thresh: 0.65\nfree_thresh: 0.196\n");
  std::string world = kWorld;
  const std::size_t from = world.find("obstacles:");
  world.replace(from, world.find("light:") - from,
                "obstacles:\n  - grid: {map: maps/checker.yaml, height: 0.3, colour: [1, 2, 3]}\n");
  const core::InputError blocks =
      ExpectInputError([&] { LoadWorldFile(dir.Write("blocks.yaml", world)); });
  EXPECT_EQ(blocks.field(), "obstacles[0]");
  EXPECT_NE(std::string(blocks.what()).find("more than 200000 blocks"), std::string::npos)
      << blocks.what();
}

}  // namespace
}  // namespace pirouette::io
