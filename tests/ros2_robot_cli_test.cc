// Exploring a ROS 2 robot over DDS: `pirouette sim-serve --ros2` serves the
// simulator as one, `pirouette explore --robot ros2` drives it to complete;
// a robot that is not there, or whose publisher goes mid-run, ends the run
// with a reason naming the topic and the map so far written.
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <future>
#include <nlohmann/json.hpp>
#include <string>
#include <thread>
#include <vector>

#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

extern char** environ;  // NOLINT(readability-redundant-declaration): for posix_spawn

namespace pirouette::ros2_robot_cli_test {
namespace {

namespace fs = std::filesystem;
using testing::RunPirouette;

std::string World(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml";
}

// A program in the background; stopped (SIGINT, as Ctrl-C) when the object
// goes unless stopped first.
class Background {
 public:
  explicit Background(std::vector<std::string> args) {
    std::vector<char*> argv;
    for (std::string& a : args) argv.push_back(a.data());
    argv.push_back(nullptr);
    if (posix_spawn(&pid_, argv[0], nullptr, nullptr, argv.data(), environ) != 0) pid_ = 0;
  }
  ~Background() { Stop(SIGINT); }
  Background(const Background&) = delete;
  Background& operator=(const Background&) = delete;

  bool started() const { return pid_ > 0; }
  // Sends `signal` and waits for the process; its exit status.
  int Stop(int signal) {
    if (pid_ <= 0) return -1;
    ::kill(pid_, signal);
    int status = 0;
    ::waitpid(pid_, &status, 0);
    pid_ = 0;
    return status;
  }

 private:
  pid_t pid_ = 0;
};

// `pirouette sim-serve --ros2` in DDS domain `domain` (set for the
// processes this test starts after it, too).
class SimServeRos2 : public Background {
 public:
  SimServeRos2(const std::string& world, int domain, const std::string& ros_namespace)
      : Background((::setenv("ROS_DOMAIN_ID", std::to_string(domain).c_str(), 1),
                    std::vector<std::string>{PIROUETTE_BINARY, "sim-serve", "--world", world,
                                             "--ros2", "--ros-namespace", ros_namespace})) {}
};

nlohmann::json RunJson(const testing::TempDir& dir) {
  return nlohmann::json::parse(dir.Read("out/run.json"));
}

TEST(Ros2Robot, TheSimulatorServedOverDdsIsExploredToComplete) {
  const testing::TempDir dir("ros2_robot");
  constexpr int kDomain = 64;
  SimServeRos2 server(World("soccer_field"), kDomain, "bot");
  ASSERT_TRUE(server.started());
  const testing::RunResult run =
      RunPirouette("explore --robot ros2 --ros-namespace bot --world " + World("soccer_field") +
                   " --out " + (dir / "out") + " --quiet --localize none");
  ::unsetenv("ROS_DOMAIN_ID");
  ASSERT_EQ(run.exit_code, 0) << run.output();
  const nlohmann::json result = RunJson(dir);
  EXPECT_EQ(result["status"], "complete");
  EXPECT_EQ(result["robot"], "ros2");
  // Within SPEC.md's bounds for a noise-free run.
  EXPECT_GE(result["eval"]["coverage"].get<double>(), 0.95) << result.dump(2);
  EXPECT_LE(result["eval"]["false_free"].get<double>(), 0.005) << result.dump(2);
  // sim-serve stops on Ctrl-C with exit code 0.
  const int status = server.Stop(SIGINT);
  EXPECT_TRUE(WIFEXITED(status) && WEXITSTATUS(status) == 0) << status;
}

// The independent check: a ROS 2 robot on Fast DDS that pirouette's DDS
// layer had no part in (tests/fastdds/ros2_fake_robot: bgr8 images, reliable
// odometry, its body the simulator over the line protocol) is explored to
// complete.
TEST(Ros2Robot, AFastDdsRobotIsExploredToComplete) {
  const testing::TempDir dir("ros2_fastdds_robot");
  constexpr int kDomain = 67;
  const std::string port_file = dir / "port";
  Background simulator({PIROUETTE_BINARY, "sim-serve", "--world", World("soccer_field"), "--port",
                        "0", "--port-file", port_file});
  ASSERT_TRUE(simulator.started());
  for (int i = 0; i < 600 && !fs::exists(port_file); ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  std::string port = dir.Read("port");
  while (!port.empty() && (port.back() == '\n' || port.back() == '\r')) port.pop_back();
  ASSERT_FALSE(port.empty()) << "sim-serve did not start";
  Background robot({ROS2_FAKE_ROBOT, std::to_string(kDomain), "fastdds", "127.0.0.1", port, "600"});
  ASSERT_TRUE(robot.started());
  ::setenv("ROS_DOMAIN_ID", std::to_string(kDomain).c_str(), 1);
  const testing::RunResult run =
      RunPirouette("explore --robot ros2 --ros-namespace fastdds --world " + World("soccer_field") +
                   " --out " + (dir / "out") + " --quiet --localize none");
  ::unsetenv("ROS_DOMAIN_ID");
  ASSERT_EQ(run.exit_code, 0) << run.output();
  const nlohmann::json result = RunJson(dir);
  EXPECT_EQ(result["status"], "complete");
  EXPECT_GE(result["eval"]["coverage"].get<double>(), 0.95) << result.dump(2);
  EXPECT_LE(result["eval"]["false_free"].get<double>(), 0.005) << result.dump(2);
}

// Malformed samples from the network: thousands of random byte strings,
// from empty to 64 kB, typed as ROS 2's Odometry and Image on the wire
// (tests/fastdds/ros2_junk_publisher). pirouette neither crashes nor takes
// them for a robot: it ends with its usual failure, naming the topic.
TEST(Ros2Robot, JunkUnderRos2NamesNeverCrashesIt) {
  const testing::TempDir dir("ros2_junk");
  constexpr int kDomain = 68;
  Background junk({ROS2_JUNK_PUBLISHER, std::to_string(kDomain), "junk", "8", "7"});
  ASSERT_TRUE(junk.started());
  ::setenv("ROS_DOMAIN_ID", std::to_string(kDomain).c_str(), 1);
  const testing::RunResult run =
      RunPirouette("explore --robot ros2 --ros-namespace junk --world " + World("soccer_field") +
                   " --out " + (dir / "out") + " --quiet --robot-timeout 4");
  ::unsetenv("ROS_DOMAIN_ID");
  EXPECT_EQ(run.exit_code, 1) << run.output();
  EXPECT_NE(run.stderr_only.find("rt/junk/"), std::string::npos) << run.output();
  const int status = junk.Stop(SIGINT);
  EXPECT_TRUE(WIFEXITED(status) || WIFSIGNALED(status));
}

TEST(Ros2Robot, NoRobotOnTheDomainIsAClearFailureAndLeavesNothing) {
  const testing::TempDir dir("ros2_robot_none");
  ::setenv("ROS_DOMAIN_ID", "65", 1);
  const testing::RunResult run =
      RunPirouette("explore --robot ros2 --world " + World("soccer_field") + " --out " +
                   (dir / "out") + " --quiet --robot-timeout 2");
  ::unsetenv("ROS_DOMAIN_ID");
  EXPECT_EQ(run.exit_code, 1) << run.output();
  EXPECT_NE(run.stderr_only.find("no odometry on rt/odom"), std::string::npos) << run.output();
  EXPECT_FALSE(fs::exists(dir / "out/map.pgm"));
}

TEST(Ros2Robot, ARobotWhosePublisherGoesEndsStuckWithTheMapSoFar) {
  const testing::TempDir dir("ros2_robot_gone");
  constexpr int kDomain = 66;
  SimServeRos2 server(World("cluttered_room"), kDomain, "bot");
  ASSERT_TRUE(server.started());
  std::future<testing::RunResult> explore = std::async(std::launch::async, [&dir] {
    return RunPirouette("explore --robot ros2 --ros-namespace bot --world " +
                        World("cluttered_room") + " --out " + (dir / "out") +
                        " --quiet --localize none");
  });
  // Some stops in, the robot dies without a word.
  std::this_thread::sleep_for(std::chrono::seconds(4));
  server.Stop(SIGKILL);
  ::unsetenv("ROS_DOMAIN_ID");
  const testing::RunResult run = explore.get();
  EXPECT_EQ(run.exit_code, 1) << run.output();
  const nlohmann::json result = RunJson(dir);
  EXPECT_EQ(result["status"], "stuck");
  EXPECT_NE(result["reason"].get<std::string>().find("rt/bot/odom"), std::string::npos)
      << result["reason"];
  EXPECT_GT(result["frames"].get<int>(), 0);
  EXPECT_FALSE(dir.Read("out/map.pgm").empty());
}

}  // namespace
}  // namespace pirouette::ros2_robot_cli_test
