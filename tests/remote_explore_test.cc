// Exploring through the robot line protocol: a shipped world
// explored through `pirouette sim-serve` on 127.0.0.1 gives the same map as
// in-process; a robot that stops answering or refuses ends the run "stuck"
// with a clear reason, and the map so far is written.

#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <condition_variable>
#include <filesystem>
#include <fstream>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "pirouette/robot/robot_error.h"
#include "pirouette/robot/robot_server.h"
#include "pirouette/run/explore_job.h"
#include "pirouette/testing/fake_robot.h"
#include "pirouette/testing/temp_dir.h"

extern char** environ;  // NOLINT(readability-redundant-declaration): for posix_spawn

namespace pirouette::run {
namespace {

namespace fs = std::filesystem;

std::string World(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name;
}

class RemoteExploreTest : public ::testing::Test {
 protected:
  void TearDown() override {
    if (server_pid_ > 0) {
      kill(server_pid_, SIGTERM);
      int status = 0;
      waitpid(server_pid_, &status, 0);
    }
  }

  // Starts `pirouette sim-serve` on a free port; returns the port.
  int StartSimServe(const std::string& world) {
    const std::string port_file = dir_ / "port";
    std::vector<std::string> args = {PIROUETTE_BINARY, "sim-serve", "--world",     world,
                                     "--port",         "0",         "--port-file", port_file};
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (posix_spawn(&server_pid_, PIROUETTE_BINARY, nullptr, nullptr, argv.data(), environ) != 0) {
      return 0;
    }
    for (int i = 0; i < 600 && !fs::exists(port_file); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    int port = 0;
    std::ifstream(port_file) >> port;
    return port;
  }

  testing::TempDir dir_{"pirouette_remote"};
  pid_t server_pid_ = 0;
};

TEST_F(RemoteExploreTest, SimServeGivesTheSameMapAsInProcess) {
  const int port = StartSimServe(World("soccer_field.yaml"));
  ASSERT_GT(port, 0) << "sim-serve did not start";

  ExploreRequest local;
  local.world_path = World("soccer_field.yaml");
  local.out_dir = dir_ / "local";
  local.quiet = true;
  const ExploreReport in_process = RunExplore(local);

  ExploreRequest remote = local;
  remote.out_dir = dir_ / "remote";
  remote.robot_url = "tcp://127.0.0.1:" + std::to_string(port);
  const ExploreReport over_tcp = RunExplore(remote);

  EXPECT_EQ(over_tcp.result.status, "complete") << over_tcp.result.reason;
  EXPECT_EQ(over_tcp.result.frames, in_process.result.frames);
  EXPECT_EQ(over_tcp.result.moves, in_process.result.moves);
  EXPECT_EQ(dir_.Read("remote/map.pgm"), dir_.Read("local/map.pgm"));
  EXPECT_EQ(dir_.Read("remote/map.yaml"), dir_.Read("local/map.yaml"));
  EXPECT_EQ(over_tcp.run["eval"], in_process.run["eval"]);
  EXPECT_EQ(over_tcp.run["robot"], remote.robot_url);
}

// Serves a robot on a thread for the life of the object: stopped and joined
// however the test ends.
class Serving {
 public:
  explicit Serving(robot::Robot& robot) : server_(robot, Options()) {
    thread_ = std::thread([this] { server_.Serve(); });
  }
  ~Serving() {
    server_.Stop();
    thread_.join();
  }
  Serving(const Serving&) = delete;
  Serving& operator=(const Serving&) = delete;

  std::string Url() const { return "tcp://127.0.0.1:" + std::to_string(server_.port()); }

 private:
  static robot::RobotServerOptions Options() {
    robot::RobotServerOptions options;
    options.port = 0;
    options.write_timeout = std::chrono::milliseconds(2000);
    return options;
  }

  robot::RobotServer server_;
  std::thread thread_;
};

// A fake robot that stops answering after a number of frames, until released.
class HangingRobot : public testing::FakeRobot {
 public:
  HangingRobot(int width, int height, int frames_before_hang)
      : FakeRobot(width, height), left_(frames_before_hang) {}

  robot::Frame Capture() override {
    if (left_-- <= 0) {
      std::unique_lock<std::mutex> lock(mutex_);
      released_.wait(lock, [this] { return release_; });
    }
    return FakeRobot::Capture();
  }

  void Release() {
    {
      std::lock_guard<std::mutex> lock(mutex_);
      release_ = true;
    }
    released_.notify_all();
  }

 private:
  int left_;
  std::mutex mutex_;
  std::condition_variable released_;
  bool release_ = false;
};

// A real robot's run: no world, its camera file and radius; the robot
// hangs in its second pirouette's worth of frames.
TEST_F(RemoteExploreTest, RobotThatStopsAnsweringEndsTheRunStuckWithTheMapSoFar) {
  HangingRobot robot(320, 240, 5);
  // Released before the server stops, however the test ends.
  struct Release {
    HangingRobot& robot;
    ~Release() { robot.Release(); }
  };
  Serving serving(robot);
  const Release release{robot};

  ExploreRequest request;
  request.robot_url = serving.Url();
  request.camera_path = World("yujin.yaml");
  request.radius_m = 0.04;
  request.robot_timeout_s = 0.3;
  request.out_dir = dir_ / "out";
  request.quiet = true;
  const ExploreReport report = RunExplore(request);

  EXPECT_EQ(report.result.status, "stuck");
  EXPECT_NE(report.result.reason.find("did not answer"), std::string::npos) << report.result.reason;
  EXPECT_EQ(report.result.frames, 5);
  EXPECT_TRUE(fs::exists(dir_.path() / "out" / "map.yaml"));
  EXPECT_TRUE(fs::exists(dir_.path() / "out" / "map.pgm"));
  EXPECT_TRUE(fs::exists(dir_.path() / "out" / "run.json"));
  EXPECT_FALSE(report.run.contains("eval"));  // no world, no truth
}

TEST_F(RemoteExploreTest, RobotThatRefusesACommandEndsTheRunStuck) {
  testing::FakeRobot robot(320, 240);
  robot.fail_capture = true;
  Serving serving(robot);

  ExploreRequest request;
  request.robot_url = serving.Url();
  request.camera_path = World("yujin.yaml");
  request.radius_m = 0.04;
  request.out_dir = dir_ / "out";
  request.quiet = true;
  const ExploreReport report = RunExplore(request);

  EXPECT_EQ(report.result.status, "stuck");
  EXPECT_NE(report.result.reason.find("unplugged"), std::string::npos) << report.result.reason;
  EXPECT_TRUE(fs::exists(dir_.path() / "out" / "map.yaml"));
}

// A robot whose frames are not the camera file's size answers garbage for
// this run: the run ends "stuck" saying so, before any frame is mapped.
TEST_F(RemoteExploreTest, FramesOfAnotherSizeThanTheCameraEndTheRunStuck) {
  testing::FakeRobot robot(640, 480);
  Serving serving(robot);

  ExploreRequest request;
  request.robot_url = serving.Url();
  request.camera_path = World("yujin.yaml");  // 320 x 240
  request.radius_m = 0.04;
  request.out_dir = dir_ / "out";
  request.quiet = true;
  const ExploreReport report = RunExplore(request);

  EXPECT_EQ(report.result.status, "stuck");
  EXPECT_NE(report.result.reason.find("640x480"), std::string::npos) << report.result.reason;
  EXPECT_EQ(report.result.frames, 0);
  EXPECT_TRUE(fs::exists(dir_.path() / "out" / "map.yaml"));
}

// A robot that is not there: a clear error, and no output folder half made.
TEST_F(RemoteExploreTest, NoRobotThereIsAnErrorBeforeAnyOutput) {
  ExploreRequest request;
  request.robot_url = "tcp://127.0.0.1:1";  // nothing serves port 1
  request.camera_path = World("yujin.yaml");
  request.radius_m = 0.04;
  request.out_dir = dir_ / "out";
  request.record_dir = dir_ / "log";
  request.quiet = true;
  EXPECT_THROW(RunExplore(request), robot::RobotError);
  EXPECT_FALSE(fs::exists(dir_.path() / "out"));
  EXPECT_FALSE(fs::exists(dir_.path() / "log"));
}

}  // namespace
}  // namespace pirouette::run
