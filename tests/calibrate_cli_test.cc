// `pirouette calibrate` on chessboards and flat fields that the simulator
// renders in-process, where the truth is known: intrinsics, vignetting and
// mount within the bounds of docs/measurements.md, "Calibration", and exit
// code 2 with a message naming the file or option for bad input (SPEC.md,
// "Commands").

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <numbers>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <random>
#include <string>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/angle.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/sim/scene_mesh.h"
#include "pirouette/sim/world.h"
#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace {

namespace fs = std::filesystem;

using pirouette::camera::CameraModel;
using pirouette::core::DegToRad;
using pirouette::core::Pose2;
using pirouette::core::RadToDeg;
using pirouette::testing::RunPirouette;
using Result = pirouette::testing::RunResult;
namespace camera = pirouette::camera;
namespace sim = pirouette::sim;

// The paper's camera (worlds/yujin.yaml): 320×240, 60° across, barrel
// distortion, vignetting; the mount as given.
CameraModel TruthCamera(const camera::Mount& mount) {
  return {"truth",
          320,
          240,
          {277.128129211, 277.128129211, 159.5, 119.5},
          {-0.20, 0.05, 0.0, 0.0, 0.0},
          mount,
          {{0.35, 0.30, 0.40}}};
}

// A big grey floor, nothing standing on it, and the boards given.
sim::World FloorWorld(const std::vector<sim::Chessboard>& boards, pirouette::core::Rgb colour) {
  sim::Floor floor{{8.0, 8.0}, colour, 0.0};
  sim::RobotSpec robot{Pose2(4.0, 4.0, 0.0), 0.04, TruthCamera({0.11, DegToRad(30.0), 0.03}), {}};
  return {"calibrate-cli-test", floor, std::nullopt, {}, sim::Light{}, robot, boards};
}

sim::Chessboard Board(const Eigen::Vector2d& centre, int cols, int rows, double square,
                      double yaw_rad) {
  sim::Chessboard board;
  board.centre = centre;
  board.cols = cols;
  board.rows = rows;
  board.square = square;
  board.yaw_rad = yaw_rad;
  return board;
}

// The number at `key` of a report (NaN when absent).
double Number(const nlohmann::json& json, const std::string& key) {
  return json.contains(key) ? json.at(key).get<double>() : std::nan("");
}

// A report on standard output: one JSON object on one line.
nlohmann::json Report(const Result& r) {
  EXPECT_EQ(r.stdout_only.find('\n'), r.stdout_only.size() - 1) << r.stdout_only;
  return nlohmann::json::parse(r.stdout_only);
}

// True where every point of the board's outline (its margin included) is
// seen inside the image, `margin` pixels from its edge, and the inner corners
// are at least `spacing` pixels apart.
// The camera's pose on the robot, turned by `roll` about its axis as
// sim::RenderOptions::roll_rad turns it.
Eigen::Isometry3d RobotTCamera(const CameraModel& cam, double roll) {
  return cam.robot_T_camera() * Eigen::AngleAxisd(roll, Eigen::Vector3d::UnitZ());
}

bool WellInView(const sim::Chessboard& board, const CameraModel& cam, const Pose2& world_T_robot,
                double margin, double spacing, double roll = 0.0) {
  const Eigen::Isometry3d camera_T_robot = RobotTCamera(cam, roll).inverse();
  const auto pixel_of = [&](const Eigen::Vector2d& p_world) {
    const Eigen::Vector2d p = world_T_robot.Inverse() * p_world;
    return cam.Project(camera_T_robot * Eigen::Vector3d(p.x(), p.y(), 0.0));
  };
  const auto inside = [&](const std::optional<Eigen::Vector2d>& px) {
    return px && px->x() >= margin && px->x() <= cam.width() - 1 - margin && px->y() >= margin &&
           px->y() <= cam.height() - 1 - margin;
  };
  // The outline: inner-corner coordinates from -2 to cols + 1 (rows alike), in half steps.
  for (double i = -2.0; i <= board.cols + 1.0; i += 0.5) {
    for (double j = -2.0; j <= board.rows + 1.0; j += 0.5) {
      const bool edge = i == -2.0 || i == board.cols + 1.0 || j == -2.0 || j == board.rows + 1.0;
      if (!edge) continue;
      const Eigen::Vector2d p = board.InnerCorner(0, 0) +
                                i * (board.InnerCorner(1, 0) - board.InnerCorner(0, 0)) +
                                j * (board.InnerCorner(0, 1) - board.InnerCorner(0, 0));
      if (!inside(pixel_of(p))) return false;
    }
  }
  for (int r = 0; r < board.rows; ++r) {
    for (int c = 0; c + 1 < board.cols; ++c) {
      const auto a = pixel_of(board.InnerCorner(c, r));
      const auto b = pixel_of(board.InnerCorner(c + 1, r));
      const auto d = r + 1 < board.rows ? pixel_of(board.InnerCorner(c, r + 1)) : a;
      if (!a || !b || !d || (*a - *b).norm() < spacing ||
          (r + 1 < board.rows && (*a - *d).norm() < spacing)) {
        return false;
      }
    }
  }
  return true;
}

class CalibrateCliTest : public ::testing::Test {
 protected:
  // PIROUETTE_KEEP_TEST_FILES=1 keeps a copy of the rendered views and camera
  // files to look at, in the temporary folder's pirouette_calibrate_kept_TEST.
  void TearDown() override {
    if (std::getenv("PIROUETTE_KEEP_TEST_FILES") == nullptr) return;
    const fs::path kept =
        fs::temp_directory_path() /
        ("pirouette_calibrate_kept_" +
         std::string(::testing::UnitTest::GetInstance()->current_test_info()->name()));
    fs::remove_all(kept);
    fs::copy(dir_.path(), kept, fs::copy_options::recursive);
  }

  std::string Path(const std::string& name) const { return dir_ / name; }

  void WriteCamera(const std::string& path, const CameraModel& cam) const {
    std::ofstream(path) << pirouette::io::CameraFileText(cam);
  }

  pirouette::testing::TempDir dir_{"pirouette_calibrate_cli_test"};
};

TEST_F(CalibrateCliTest, IntrinsicsFromRenderedBoardsWithinOnePercent) {
  // Views at twelve tilts from 35° to 80° and rolls from -30° to 30°, each at
  // a random height, distance, turn and place in the image, the whole board in
  // view. (A board flat on the floor seen at one tilt is degenerate for
  // Zhang's method; at several tilts but no roll, every board plane contains
  // the camera's x axis, which leaves cy and the tilts barely separable.)
  const Eigen::Vector2d centre(4.0, 4.0);
  const sim::Chessboard board = Board(centre, 9, 6, 0.025, 0.0);
  const sim::World world = FloorWorld({board}, {110, 105, 100});
  fs::create_directories(Path("views"));
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int rendered = 0;
  for (int i = 0; i < 12; ++i) {
    const double tilt = DegToRad(35.0 + 45.0 * i / 11.0);
    const double roll = DegToRad(i % 2 == 0 ? 30.0 - 5.0 * i : -25.0 + 5.0 * i);
    bool placed = false;
    for (int attempt = 0; attempt < 400 && !placed; ++attempt) {
      const double slant = 0.24 + 0.2 * unit(rng);
      const CameraModel cam = TruthCamera({slant * std::sin(tilt), tilt, 0.0});
      const Eigen::Vector2d target(159.5 + 160.0 * (unit(rng) - 0.5),
                                   119.5 + 120.0 * (unit(rng) - 0.5));
      const Eigen::Isometry3d robot_T_camera = RobotTCamera(cam, roll);
      const Eigen::Vector3d ray = robot_T_camera.linear() * cam.Backproject(target);
      if (!(ray.z() < -0.05)) continue;
      const Eigen::Vector3d origin = robot_T_camera.translation();
      const Eigen::Vector2d seen = (origin - origin.z() / ray.z() * ray).head<2>();
      const double heading = 2.0 * std::numbers::pi * unit(rng);
      const Eigen::Vector2d xy = centre - Eigen::Rotation2Dd(heading).toRotationMatrix() * seen;
      const Pose2 pose(xy.x(), xy.y(), heading);
      if (!WellInView(board, cam, pose, 3.0, 7.0, roll)) continue;
      sim::RenderOptions options;
      options.seed = 100 + i;
      options.roll_rad = roll;
      sim::Renderer renderer(world, cam, options);
      pirouette::io::WritePng(Path("views/view" + std::to_string(i) + ".png"),
                              renderer.Render(pose));
      placed = true;
      ++rendered;
    }
  }
  ASSERT_GE(rendered, 10);
  // A photo without the board: reported and skipped.
  cv::imwrite(Path("views/zz_blank.png"), cv::Mat3b(240, 320, cv::Vec3b(100, 100, 100)));

  const Result r = RunPirouette("calibrate intrinsics --images " + Path("views") +
                                " --board 9x6 --square 0.025 --out " + Path("camera.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.stderr_only;
  const nlohmann::json json = Report(r);
  EXPECT_NE(r.stderr_only.find("zz_blank.png"), std::string::npos);
  EXPECT_EQ(json.at("views_skipped"), nlohmann::json::array({"zz_blank.png"})) << json;
  EXPECT_GE(Number(json, "views_used"), rendered - 1);
  EXPECT_LT(Number(json, "reprojection_error_px"), 0.3);
  const double fx_error = Number(json, "fx") / 277.128129211 - 1.0;
  const double fy_error = Number(json, "fy") / 277.128129211 - 1.0;
  EXPECT_LT(std::abs(fx_error), 0.01) << json;
  EXPECT_LT(std::abs(fy_error), 0.01) << json;
  EXPECT_NEAR(Number(json, "cx"), 159.5, 3.0);
  EXPECT_NEAR(Number(json, "cy"), 119.5, 3.0);
  std::printf(
      "measured: intrinsics from %d views: fx error %+.3f%%, fy error %+.3f%%, "
      "cx %+.2f px, cy %+.2f px, reprojection %.3f px\n",
      rendered, 100.0 * fx_error, 100.0 * fy_error, Number(json, "cx") - 159.5,
      Number(json, "cy") - 119.5, Number(json, "reprojection_error_px"));

  // The camera file holds what was printed, and a placeholder mount.
  const CameraModel written = pirouette::io::LoadCameraFile(Path("camera.yaml"));
  EXPECT_EQ(written.width(), 320);
  EXPECT_EQ(written.height(), 240);
  EXPECT_NEAR(written.intrinsics().fx, Number(json, "fx"), 1e-3);
  EXPECT_NEAR(written.distortion().k1, -0.20, 0.03);
  // Distortion as the image sees it: a pixel's ray, through the true camera,
  // lands within a pixel of it, over the image but its outermost band (which
  // few corners reach).
  const CameraModel truth = TruthCamera({0.11, 0.5, 0.03});
  double worst_px = 0.0;
  for (double v = 20.0; v <= 220.0; v += 20.0) {
    for (double u = 20.0; u <= 300.0; u += 20.0) {
      const auto back = truth.Project(written.Backproject({u, v}));
      ASSERT_TRUE(back.has_value());
      worst_px = std::max(worst_px, (*back - Eigen::Vector2d(u, v)).norm());
    }
  }
  EXPECT_LT(worst_px, 2.5);  // measured 1.9: the periphery is the least constrained
  std::printf(
      "measured: a pixel's ray through the true camera lands within %.2f px of it "
      "(20 px in from the edges)\n",
      worst_px);
}

TEST_F(CalibrateCliTest, FisheyeIntrinsicsFromRenderedBoardsWithModelEquidistant) {
  // A fisheye about 120° across, rendered; views as above, nearer so that
  // the board reaches far out into the lens's periphery.
  const std::vector<double> k = {0.04, -0.012, 0.003, -0.0005};
  const auto fisheye = [&k](const camera::Mount& mount) {
    return CameraModel(
        "fisheye", 320, 240, {150.0, 150.0, 159.5, 119.5},
        *camera::Distortion::FromCoefficients(camera::Distortion::Model::kEquidistant, k), mount,
        {});
  };
  const Eigen::Vector2d centre(4.0, 4.0);
  const sim::Chessboard board = Board(centre, 9, 6, 0.025, 0.0);
  const sim::World world = FloorWorld({board}, {110, 105, 100});
  fs::create_directories(Path("views"));
  std::mt19937 rng(13);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int rendered = 0;
  for (int i = 0; i < 14; ++i) {
    const double tilt = DegToRad(35.0 + 45.0 * i / 13.0);
    const double roll = DegToRad(i % 2 == 0 ? 30.0 - 5.0 * i : -25.0 + 5.0 * i);
    bool placed = false;
    for (int attempt = 0; attempt < 400 && !placed; ++attempt) {
      const double slant = 0.12 + 0.1 * unit(rng);
      const CameraModel cam = fisheye({slant * std::sin(tilt), tilt, 0.0});
      const Eigen::Vector2d target(159.5 + 200.0 * (unit(rng) - 0.5),
                                   119.5 + 150.0 * (unit(rng) - 0.5));
      const Eigen::Isometry3d robot_T_camera = RobotTCamera(cam, roll);
      const Eigen::Vector3d ray = robot_T_camera.linear() * cam.Backproject(target);
      if (!(ray.z() < -0.05)) continue;
      const Eigen::Vector3d origin = robot_T_camera.translation();
      const Eigen::Vector2d seen = (origin - origin.z() / ray.z() * ray).head<2>();
      const double heading = 2.0 * std::numbers::pi * unit(rng);
      const Eigen::Vector2d xy = centre - Eigen::Rotation2Dd(heading).toRotationMatrix() * seen;
      const Pose2 pose(xy.x(), xy.y(), heading);
      if (!WellInView(board, cam, pose, 3.0, 6.0, roll)) continue;
      sim::RenderOptions options;
      options.seed = 200 + i;
      options.roll_rad = roll;
      sim::Renderer renderer(world, cam, options);
      pirouette::io::WritePng(Path("views/view" + std::to_string(i) + ".png"),
                              renderer.Render(pose));
      placed = true;
      ++rendered;
    }
  }
  ASSERT_GE(rendered, 10);

  const Result r =
      RunPirouette("calibrate intrinsics --model equidistant --images " + Path("views") +
                   " --board 9x6 --square 0.025 --out " + Path("camera.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.stderr_only;
  const nlohmann::json json = Report(r);
  EXPECT_EQ(json.at("distortion_model"), "equidistant") << json;
  EXPECT_EQ(json.at("distortion").size(), 4u) << json;
  EXPECT_GE(Number(json, "views_used"), 8) << json;
  EXPECT_LT(Number(json, "reprojection_error_px"), 0.5) << json;
  EXPECT_NEAR(Number(json, "fx") / 150.0, 1.0, 0.02) << json;
  EXPECT_NEAR(Number(json, "fy") / 150.0, 1.0, 0.02) << json;
  const CameraModel written = pirouette::io::LoadCameraFile(Path("camera.yaml"));
  EXPECT_EQ(written.distortion().model, camera::Distortion::Model::kEquidistant);
  EXPECT_NEAR(written.distortion().k1, 0.04, 0.01) << json;  // measured 0.037
  std::printf(
      "measured: fisheye intrinsics from %d views: fx %.2f (150), k1 %.4f (0.04), "
      "reprojection %.3f px\n",
      rendered, Number(json, "fx"), written.distortion().k1, Number(json, "reprojection_error_px"));
}

TEST_F(CalibrateCliTest, VignettingFromARenderedFlatFloor) {
  // Looking steeply down at a big untextured floor: uniform light fills the view.
  const CameraModel truth = TruthCamera({0.30, DegToRad(70.0), 0.03});
  const sim::World world = FloorWorld({}, {170, 160, 140});
  sim::Renderer renderer(world, truth, sim::RenderOptions{});
  pirouette::io::WritePng(Path("flat.png"), renderer.Render(Pose2(4.0, 4.0, 0.3)));
  const CameraModel without(truth.name(), truth.width(), truth.height(), truth.intrinsics(),
                            truth.distortion(), truth.mount(), camera::Vignetting{});
  WriteCamera(Path("camera.yaml"), without);

  const Result r = RunPirouette("calibrate vignetting --image " + Path("flat.png") + " --camera " +
                                Path("camera.yaml"));
  ASSERT_EQ(r.exit_code, 0) << r.stderr_only;
  const nlohmann::json json = Report(r);
  const CameraModel fitted = pirouette::io::LoadCameraFile(Path("camera.yaml"));
  EXPECT_EQ(json.at("k"), nlohmann::json(fitted.vignetting().k)) << json;
  double worst = 0.0;
  for (std::size_t c = 0; c < 3; ++c) {
    const double error = fitted.vignetting().k[c] - truth.vignetting().k[c];
    EXPECT_LT(std::abs(error), 0.03) << "channel " << c << "\n" << r.stdout_only;
    worst = std::max(worst, std::abs(error));
  }
  std::printf(
      "measured: vignetting k fitted [%.4f, %.4f, %.4f] for [0.35, 0.30, 0.40]: worst "
      "error %.4f\n",
      fitted.vignetting().k[0], fitted.vignetting().k[1], fitted.vignetting().k[2], worst);
  // Everything else is kept.
  EXPECT_EQ(fitted.intrinsics().fx, truth.intrinsics().fx);
  EXPECT_EQ(fitted.mount().height_m, truth.mount().height_m);
  EXPECT_EQ(fitted.name(), truth.name());
}

TEST_F(CalibrateCliTest, MountFromOneRenderedBoardOnTheFloor) {
  struct Case {
    camera::Mount mount;
    double distance;
    int cols, rows;
    double square;
  };
  for (const Case& c : {Case{{0.11, DegToRad(30.0), 0.03}, 0.30, 7, 5, 0.02},
                        Case{{0.25, DegToRad(45.0), -0.05}, 0.32, 9, 6, 0.025}}) {
    SCOPED_TRACE(c.mount.height_m);
    const CameraModel truth = TruthCamera(c.mount);
    const Pose2 pose(4.0, 4.0, DegToRad(10.0));
    // Rows across the robot's forward axis, the board's centre on it.
    const Eigen::Vector2d centre = pose * Eigen::Vector2d(c.distance, 0.0);
    const sim::Chessboard board =
        Board(centre, c.cols, c.rows, c.square, pose.heading() + DegToRad(90.0));
    ASSERT_TRUE(WellInView(board, truth, pose, 2.0, 4.0));
    sim::Renderer renderer(FloorWorld({board}, {110, 105, 100}), truth, sim::RenderOptions{});
    pirouette::io::WritePng(Path("board.png"), renderer.Render(pose));
    WriteCamera(Path("camera.yaml"), TruthCamera({0.5, 0.1, 0.0}));  // a wrong mount

    const Result r = RunPirouette("calibrate mount --image " + Path("board.png") + " --board " +
                                  std::to_string(c.cols) + "x" + std::to_string(c.rows) +
                                  " --square " + std::to_string(c.square) + " --board-distance " +
                                  std::to_string(c.distance) + " --camera " + Path("camera.yaml"));
    ASSERT_EQ(r.exit_code, 0) << r.stderr_only;
    const nlohmann::json json = Report(r);
    const camera::Mount fitted = pirouette::io::LoadCameraFile(Path("camera.yaml")).mount();
    // The board is drawn sim::kChessboardLift above the floor.
    const double height_error = fitted.height_m - (c.mount.height_m - sim::kChessboardLift);
    const double tilt_error = RadToDeg(fitted.tilt_rad - c.mount.tilt_rad);
    const double forward_error = fitted.forward_m - c.mount.forward_m;
    EXPECT_LT(std::abs(height_error), 0.002) << r.stdout_only;
    EXPECT_LT(std::abs(tilt_error), 0.3) << r.stdout_only;
    EXPECT_LT(std::abs(forward_error), 0.005) << r.stdout_only;
    EXPECT_EQ(Number(json, "height"), fitted.height_m) << json;
    EXPECT_LT(std::abs(Number(json, "roll_deg")), 0.3);
    std::printf(
        "measured: mount at %.2f m, %.0f deg: height error %+.2f mm, tilt error %+.3f "
        "deg, forward error %+.2f mm, roll %+.3f deg\n",
        c.mount.height_m, RadToDeg(c.mount.tilt_rad), 1000.0 * height_error, tilt_error,
        1000.0 * forward_error, Number(json, "roll_deg"));
  }
}

TEST_F(CalibrateCliTest, BadInputIsRefusedWithExitCodeTwo) {
  const auto expect_refused = [](const std::string& args, const std::string& named) {
    SCOPED_TRACE(args);
    const Result r = RunPirouette(args);
    EXPECT_EQ(r.exit_code, 2) << r.output();
    EXPECT_NE(r.stderr_only.find(named), std::string::npos) << r.stderr_only;
    EXPECT_TRUE(r.stdout_only.empty()) << r.stdout_only;
  };
  fs::create_directories(Path("blank"));
  for (int i = 0; i < 3; ++i) {
    cv::imwrite(Path("blank/b" + std::to_string(i) + ".png"),
                cv::Mat3b(240, 320, cv::Vec3b(90, 90, 90)));
  }
  fs::create_directories(Path("empty"));
  fs::create_directories(Path("broken"));
  std::ofstream(Path("broken/not_an_image.png")) << "not a PNG";
  WriteCamera(Path("camera.yaml"), TruthCamera({0.11, DegToRad(30.0), 0.03}));
  cv::imwrite(Path("small.png"), cv::Mat3b(120, 160, cv::Vec3b(90, 90, 90)));

  const std::string in = "calibrate intrinsics --square 0.025 --out " + Path("out.yaml");
  expect_refused(in + " --board 9x6 --images " + Path("missing"), Path("missing"));
  expect_refused(in + " --board 9x6 --images " + Path("empty"), Path("empty"));
  expect_refused(in + " --board 9by6 --images " + Path("blank"), "--board");
  expect_refused(in + " --board 1x6 --images " + Path("blank"), "--board");
  expect_refused(in + " --board 9x6 --model fisheye --images " + Path("blank"), "--model");
  expect_refused(in + " --board 9x6 --images " + Path("blank"), "no 9x6 board found");
  expect_refused(in + " --board 9x6 --images " + Path("broken"), "not_an_image.png");
  expect_refused(
      "calibrate intrinsics --square -1 --board 9x6 --out x.yaml --images " + Path("blank"),
      "--square");
  EXPECT_FALSE(fs::exists(Path("out.yaml")));

  expect_refused(
      "calibrate vignetting --image " + Path("missing.png") + " --camera " + Path("camera.yaml"),
      "missing.png");
  expect_refused(
      "calibrate vignetting --image " + Path("small.png") + " --camera " + Path("camera.yaml"),
      "small.png");
  expect_refused("calibrate vignetting --image " + Path("blank/b0.png") + " --camera " +
                     Path("no_camera.yaml"),
                 "no_camera.yaml");
  const std::string mount = "calibrate mount --board 9x6 --square 0.025 --camera " +
                            Path("camera.yaml") + " --image " + Path("blank/b0.png");
  expect_refused(mount + " --board-distance 0.3", "no 9x6 board found");
  expect_refused(mount + " --board-distance -0.3", "--board-distance");
  EXPECT_EQ(RunPirouette("calibrate").exit_code, 2);
}

}  // namespace
