// The command line as a user meets it: exit codes, messages naming the file,
// line and field, and the files it writes (SPEC.md, "Commands").

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>
#include <string>

#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace {

namespace fs = std::filesystem;

using pirouette::testing::RunPirouette;
using Result = pirouette::testing::RunResult;

class CliTest : public ::testing::Test {
 protected:
  std::string Write(const std::string& name, const std::string& text) {
    return dir_.Write(name, text);
  }
  std::string Path(const std::string& name) const { return dir_ / name; }

  pirouette::testing::TempDir dir_{"pirouette_cli_test"};
};

const std::string kWorlds = PIROUETTE_WORLDS_DIR;

TEST_F(CliTest, HelpTeachesAndExitsZero) {
  const Result r = RunPirouette("--help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output().find("render"), std::string::npos);
  const Result sub = RunPirouette("render --help");
  EXPECT_EQ(sub.exit_code, 0);
  EXPECT_NE(sub.output().find("--pose"), std::string::npos);
}

TEST_F(CliTest, RenderWritesTheCamerasImage) {
  const std::string out = Path("view.png");
  const Result r = RunPirouette("render --world " + kWorlds +
                                "/soccer_field.yaml --pose 0.2,0.2,45 --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output();
  EXPECT_TRUE(r.stdout_only.empty()) << "render prints nothing on standard output";
  const cv::Mat image = cv::imread(out, cv::IMREAD_COLOR);
  ASSERT_FALSE(image.empty());
  EXPECT_EQ(image.cols, 320);
  EXPECT_EQ(image.rows, 240);
}

TEST_F(CliTest, RenderIsDeterministic) {
  const std::string world = kWorlds + "/cluttered_room.yaml";
  const std::string a = Path("a.png");
  const std::string b = Path("b.png");
  ASSERT_EQ(RunPirouette("render --world " + world + " --pose 1.0,1.0,30 --out " + a).exit_code, 0);
  ASSERT_EQ(RunPirouette("render --world " + world + " --pose 1.0,1.0,30 --out " + b).exit_code, 0);
  const cv::Mat ia = cv::imread(a);
  const cv::Mat ib = cv::imread(b);
  ASSERT_FALSE(ia.empty());
  EXPECT_EQ(cv::norm(ia, ib, cv::NORM_INF), 0.0);
}

TEST_F(CliTest, BadUsageExitsTwo) {
  EXPECT_EQ(RunPirouette("").exit_code, 2);
  EXPECT_EQ(RunPirouette("render --world " + kWorlds + "/soccer_field.yaml").exit_code, 2);
  EXPECT_EQ(RunPirouette("no-such-command").exit_code, 2);
  const Result pose = RunPirouette("render --world " + kWorlds +
                                   "/soccer_field.yaml --pose 1,2 --out " + Path("x.png"));
  EXPECT_EQ(pose.exit_code, 2);
  EXPECT_NE(pose.output().find("--pose"), std::string::npos) << pose.output();
  const Result off = RunPirouette("render --world " + kWorlds +
                                  "/soccer_field.yaml --pose 5,5,0 --out " + Path("x.png"));
  EXPECT_EQ(off.exit_code, 2);
  EXPECT_NE(off.output().find("off the floor"), std::string::npos) << off.output();
  EXPECT_FALSE(fs::exists(Path("x.png")));
}

struct BadWorld {
  const char* what;
  const char* yaml;
  const char* field;
  int line;
};

// A valid world with one thing wrong at a time.
const BadWorld kBadWorlds[] = {
    {"unknown key", R"(format: pirouette-world/1
name: t
floor: {size: [1, 1], colour: [20, 20, 20], shine: 3}
robot: {start: [0.5, 0.5, 0], radius: 0.04, camera: CAMERA}
)",
     "floor.shine", 3},
    {"missing key", R"(format: pirouette-world/1
name: t
floor: {size: [1, 1]}
robot: {start: [0.5, 0.5, 0], radius: 0.04, camera: CAMERA}
)",
     "floor.colour", 3},
    {"wrong type", R"(format: pirouette-world/1
name: t
floor: {size: [1, 1], colour: [20, 20, 20]}
robot: {start: [0.5, 0.5, 0], radius: big, camera: CAMERA}
)",
     "robot.radius", 4},
    {"negative size", R"(format: pirouette-world/1
name: t
floor: {size: [1, 1], colour: [20, 20, 20]}
obstacles:
  - box: {centre: [0.2, 0.2], size: [-0.1, 0.1], height: 0.1, colour: [200, 0, 0]}
robot: {start: [0.5, 0.5, 0], radius: 0.04, camera: CAMERA}
)",
     "obstacles[0].box.size", 5},
    {"colour out of range", R"(format: pirouette-world/1
name: t
floor: {size: [1, 1], colour: [20, 300, 20]}
robot: {start: [0.5, 0.5, 0], radius: 0.04, camera: CAMERA}
)",
     "floor.colour", 3},
    {"start on an obstacle", R"(format: pirouette-world/1
name: t
floor: {size: [1, 1], colour: [20, 20, 20]}
obstacles:
  - cylinder: {centre: [0.5, 0.5], radius: 0.1, height: 0.1, colour: [0, 200, 0]}
robot: {start: [0.5, 0.5, 0], radius: 0.04, camera: CAMERA}
)",
     "robot.start", 6},
    {"start off the floor", R"(format: pirouette-world/1
name: t
floor: {size: [1, 1], colour: [20, 20, 20]}
robot: {start: [1.5, 0.5, 0], radius: 0.04, camera: CAMERA}
)",
     "robot.start", 4},
    {"bad format", R"(format: pirouette-world/9
name: t
floor: {size: [1, 1], colour: [20, 20, 20]}
robot: {start: [0.5, 0.5, 0], radius: 0.04, camera: CAMERA}
)",
     "format", 1},
};

TEST_F(CliTest, EveryKindOfBadWorldExitsTwoNamingFileLineAndField) {
  for (const BadWorld& bad : kBadWorlds) {
    std::string yaml = bad.yaml;
    yaml.replace(yaml.find("CAMERA"), 6, kWorlds + "/yujin.yaml");
    const std::string world = Write("bad.yaml", yaml);
    const Result r =
        RunPirouette("render --world " + world + " --pose 0.5,0.5,0 --out " + Path("x.png"));
    EXPECT_EQ(r.exit_code, 2) << bad.what << ": " << r.output();
    EXPECT_NE(r.output().find(world + ":" + std::to_string(bad.line)), std::string::npos)
        << bad.what << ": " << r.output();
    EXPECT_NE(r.output().find(bad.field), std::string::npos) << bad.what << ": " << r.output();
  }
}

TEST_F(CliTest, BadCameraFileExitsTwoNamingIt) {
  const std::string camera = Write("camera.yaml", R"(image_width: 320
image_height: 240
camera_matrix: {rows: 3, cols: 3, data: [277, 0, 159.5, 0, 277, 119.5, 0, 0, 1]}
distortion_model: plumb_bob
distortion_coefficients: {rows: 1, cols: 5, data: [0, 0, 0, 0, 0]}
mount: {height: -0.11, tilt: 30}
)");
  const std::string world = Write("w.yaml", R"(format: pirouette-world/1
name: t
floor: {size: [1, 1], colour: [20, 20, 20]}
robot: {start: [0.5, 0.5, 0], radius: 0.04, camera: camera.yaml}
)");
  const Result r =
      RunPirouette("render --world " + world + " --pose 0.5,0.5,0 --out " + Path("x.png"));
  EXPECT_EQ(r.exit_code, 2) << r.output();
  EXPECT_NE(r.output().find(camera + ":6"), std::string::npos) << r.output();
  EXPECT_NE(r.output().find("mount.height"), std::string::npos) << r.output();
  const Result missing = RunPirouette("render --world " + Path("none.yaml") +
                                      " --pose 0.5,0.5,0 --out " + Path("x.png"));
  EXPECT_EQ(missing.exit_code, 2);
  EXPECT_NE(missing.output().find("none.yaml"), std::string::npos) << missing.output();
}

TEST_F(CliTest, IpmReportPrintsThePapersFigure) {
  const Result r = RunPirouette("ipm-report --camera " + kWorlds + "/yujin.yaml --json");
  ASSERT_EQ(r.exit_code, 0) << r.output();
  const nlohmann::json json = nlohmann::json::parse(r.stdout_only);
  EXPECT_GE(json.at("max_range_m").get<double>(), 0.4) << r.stdout_only;
  EXPECT_LT(json.at("max_range_m").get<double>(), 0.5) << r.stdout_only;
  const Result bad = RunPirouette("ipm-report --camera " + kWorlds + "/yujin.yaml --cell 0");
  EXPECT_EQ(bad.exit_code, 2) << bad.output();
  EXPECT_NE(bad.output().find("--cell"), std::string::npos) << bad.output();
}

TEST_F(CliTest, RopWritesThePolarPlot) {
  const std::string out = Path("rop.png");
  const Result r =
      RunPirouette("rop --world " + kWorlds +
                   "/soccer_field.yaml --pose 0.75,0.65,0 --method truth --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output();
  EXPECT_TRUE(r.stdout_only.empty());
  const cv::Mat image = cv::imread(out);
  EXPECT_FALSE(image.empty());
  const Result bad =
      RunPirouette("rop --world " + kWorlds +
                   "/soccer_field.yaml --pose 0.75,0.65,0 --method magic --out " + out);
  EXPECT_EQ(bad.exit_code, 2) << bad.output();
  EXPECT_NE(bad.output().find("--method"), std::string::npos) << bad.output();
}

TEST_F(CliTest, PerceptionEvalRefusesAMissingWorld) {
  const Result r = RunPirouette("perception-eval --world " + Path("none.yaml"));
  EXPECT_EQ(r.exit_code, 2) << r.output();
  EXPECT_NE(r.output().find("none.yaml"), std::string::npos) << r.output();
}

}  // namespace
