#include "pirouette/tools/ros2_sim_server.h"

#include <gtest/gtest.h>

#include <atomic>
#include <cmath>
#include <numbers>
#include <string>
#include <thread>
#include <vector>

#include "pirouette/io/camera_file.h"
#include "pirouette/io/world_file.h"
#include "pirouette/robot/ros2/ros2_robot.h"
#include "pirouette/run/explore_job.h"
#include "pirouette/run/ros2_camera.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::tools::ros2_sim_server_test {
namespace {

// Each test its own DDS domain, so that tests running at once never meet.
constexpr int kDomainMoves = 174;
constexpr int kDomainContact = 175;
constexpr int kDomainCameraInfo = 191;
constexpr int kDomainExploreMount = 192;

// The simulator served on a thread for the life of the object (built on it
// too: the renderer's OpenGL context belongs to the thread that made it).
class Serving {
 public:
  Serving(const sim::World& world, int domain) {
    Ros2SimServerOptions options;
    options.domain_id = domain;
    options.stop_requested = &stop_;
    thread_ = std::thread([this, &world, options] {
      server_.emplace(world, 1, core::OdometryNoise{}, options);
      ready_ = true;
      server_->Serve();
      server_.reset();
    });
    while (!ready_) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  ~Serving() {
    stop_ = true;
    thread_.join();
  }
  Serving(const Serving&) = delete;
  Serving& operator=(const Serving&) = delete;
  const Ros2SimServer& server() const { return *server_; }

 private:
  std::atomic<bool> stop_{false};
  std::atomic<bool> ready_{false};
  std::optional<Ros2SimServer> server_;
  std::thread thread_;
};

robot::ros2::Ros2RobotOptions RobotOptions(int domain, const sim::World& world) {
  robot::ros2::Ros2RobotOptions options;
  options.domain_id = domain;
  options.frame_width = world.robot().camera.width();
  options.frame_height = world.robot().camera.height();
  return options;
}

TEST(Ros2SimServerTest, ARobotOverDdsTurnsDrivesAndSeesAtRest) {
  const sim::World world =
      io::LoadWorldFile(std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml");
  Serving serving(world, kDomainMoves);
  robot::ros2::Ros2Robot robot(RobotOptions(kDomainMoves, world));
  const core::Pose2 start = robot.Odometry();
  EXPECT_NEAR(start.x(), world.robot().start.x(), 1e-9);

  const core::MoveOutcome turn = robot.Execute(core::Move::Turn(-std::numbers::pi / 4));
  EXPECT_NEAR(turn.achieved, -std::numbers::pi / 4, 0.01);
  EXPECT_NEAR(core::NormalizeAngle(turn.odometry.heading() - start.heading()), turn.achieved, 1e-9);
  EXPECT_FALSE(turn.stopped_at_contact);

  // Facing east from (0.2, 0.2) on the soccer field: 0.3 m of free floor ahead.
  const core::MoveOutcome drive = robot.Execute(core::Move::Straight(0.3));
  EXPECT_NEAR(drive.achieved, 0.3, 0.006);
  EXPECT_FALSE(drive.stopped_at_contact);

  const robot::Frame frame = robot.Capture();
  EXPECT_EQ(frame.image.width(), world.robot().camera.width());
  EXPECT_EQ(frame.image.height(), world.robot().camera.height());
  EXPECT_GT(frame.time_s, 0.0);
  // Without noise the simulator's truth is its odometry, which the robot read.
  const core::Pose2 truth = serving.server().robot().true_pose();
  EXPECT_NEAR(frame.odometry.x(), truth.x(), 1e-6);
  EXPECT_NEAR(frame.odometry.y(), truth.y(), 1e-6);
  EXPECT_GE(serving.server().frames_published(), 1);
  ASSERT_TRUE(robot.camera_info().has_value());
  EXPECT_EQ(robot.camera_info()->width, world.robot().camera.width());
  EXPECT_DOUBLE_EQ(robot.camera_info()->k[0], world.robot().camera.intrinsics().fx);
}

TEST(Ros2SimServerTest, ADriveIntoAWallEndsAtContact) {
  const sim::World world =
      io::LoadWorldFile(std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml");
  Serving serving(world, kDomainContact);
  robot::ros2::Ros2Robot robot(RobotOptions(kDomainContact, world));
  const double far = world.floor().size.norm() + 1.0;
  const core::MoveOutcome drive = robot.Execute(core::Move::Straight(far));
  EXPECT_TRUE(drive.stopped_at_contact);
  EXPECT_GT(drive.achieved, 0.05);
  EXPECT_LT(drive.achieved, far);
  EXPECT_TRUE(serving.server().robot().in_contact());
  // It can still turn away and drive off.
  robot.Execute(core::Move::Turn(std::numbers::pi));
  EXPECT_FALSE(robot.Execute(core::Move::Straight(0.2)).stopped_at_contact);
}

// A camera file with only the mount (what `calibrate mount` measures): the
// intrinsics come from the simulator's camera_info, and they are the world's.
TEST(Ros2SimServerTest, CameraInfoGivesTheWorldsIntrinsicsToAMountOnlyCameraFile) {
  const sim::World world =
      io::LoadWorldFile(std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml");
  const camera::CameraModel& truth = world.robot().camera;
  Serving serving(world, kDomainCameraInfo);
  robot::ros2::Ros2RobotOptions options = RobotOptions(kDomainCameraInfo, world);
  options.frame_width = options.frame_height = 0;  // the camera file gives no size
  robot::ros2::Ros2Robot robot(options);
  io::CameraMountFile file;
  file.name = "mount only";
  file.mount = truth.mount();
  file.vignetting = truth.vignetting();
  std::vector<std::string> notes;
  constexpr std::chrono::milliseconds kWait{10000};
  const camera::CameraModel camera =
      run::CameraOfRos2Robot(robot, file, "mount.yaml", kWait, kWait, notes);
  EXPECT_EQ(camera.name(), "mount only");
  EXPECT_EQ(camera.width(), truth.width());
  EXPECT_EQ(camera.height(), truth.height());
  EXPECT_EQ(camera.intrinsics().fx, truth.intrinsics().fx);
  EXPECT_EQ(camera.intrinsics().fy, truth.intrinsics().fy);
  EXPECT_EQ(camera.intrinsics().cx, truth.intrinsics().cx);
  EXPECT_EQ(camera.intrinsics().cy, truth.intrinsics().cy);
  EXPECT_EQ(camera.distortion(), truth.distortion());
  EXPECT_EQ(camera.mount().tilt_rad, truth.mount().tilt_rad);
  ASSERT_EQ(notes.size(), 1U);
  EXPECT_NE(notes[0].find("intrinsics from rt/camera_info"), std::string::npos) << notes[0];
  // Frames are now held to camera_info's size, and have it.
  const robot::Frame frame = robot.Capture();
  EXPECT_EQ(frame.image.width(), truth.width());
}

// `explore --robot ros2 --camera mount.yaml`: the run's camera has the
// intrinsics of the robot's camera_info and the file's mount.
TEST(Ros2SimServerTest, ExploreWithAMountOnlyCameraFileTakesCameraInfosIntrinsics) {
  const sim::World world =
      io::LoadWorldFile(std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml");
  Serving serving(world, kDomainExploreMount);
  const testing::TempDir dir;
  run::ExploreRequest request;
  request.robot_url = run::kRos2Robot;
  request.ros2_publish = run::Ros2PublishOptions{kDomainExploreMount, {}, ""};
  request.camera_path = dir.Write("mount.yaml",
                                  "mount: {height: 0.11, tilt: 30, forward: 0.03}\n"
                                  "vignetting: {k: [0.35, 0.30, 0.40]}\n");
  request.radius_m = world.robot().radius;
  request.out_dir = (dir.path() / "out").string();
  request.quiet = true;
  request.record_dir = (dir.path() / "log").string();
  request.options.max_steps = 1;
  const run::ExploreReport report = run::RunExplore(request);
  EXPECT_EQ(report.run["status"], "step-limit") << report.run.dump(2);
  // The run log records the run's camera: camera_info's intrinsics.
  const camera::CameraModel logged = io::LoadCameraFile((dir.path() / "log/camera.yaml").string());
  EXPECT_EQ(logged.intrinsics().fx, world.robot().camera.intrinsics().fx);
  EXPECT_EQ(logged.distortion(), world.robot().camera.distortion());
  EXPECT_EQ(logged.mount().height_m, 0.11);
}

}  // namespace
}  // namespace pirouette::tools::ros2_sim_server_test
