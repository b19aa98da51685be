// pirouette publishing a run to ROS 2, checked by a subscriber nobody here
// wrote the middleware of: tests/fastdds/ros2_map_listener, on eProsima Fast
// DDS with types fastddsgen made from ROS 2's message definitions.
#include <gtest/gtest.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace pirouette {
namespace {

namespace fs = std::filesystem;
using testing::RunPirouette;

std::string World(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml";
}

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// Runs the listener in the background; its exit code when it is done.
std::future<int> Listen(int domain, const std::string& ros_namespace, const fs::path& out) {
  const std::string command = std::string(ROS2_MAP_LISTENER) + " " + std::to_string(domain) + " " +
                              (ros_namespace.empty() ? "-" : ros_namespace) + " " + out.string() +
                              " 240 2>" + (out / "listener.err").string();
  return std::async(std::launch::async, [command] {
    const int status = std::system(command.c_str());
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  });
}

// A run published over DDS: the last map the Fast DDS subscriber got is
// map.pgm, cell for cell, with map.yaml's resolution and origin, and the last
// status says how the run ended.
TEST(Ros2Publish, AFastDdsSubscriberGetsTheRunsMapCellForCell) {
  const testing::TempDir dir("ros2_publish");
  constexpr int kDomain = 61;
  std::future<int> listener = Listen(kDomain, "robot1", dir.path());
  // The domain goes in through the environment, as ROS 2's does.
  ::setenv("ROS_DOMAIN_ID", std::to_string(kDomain).c_str(), 1);
  const testing::RunResult run = RunPirouette(
      "explore --world " + World("soccer_field") + " --out " + (dir.path() / "out").string() +
      " --quiet --ros2-publish --ros-namespace robot1 --localize none");
  ::unsetenv("ROS_DOMAIN_ID");
  ASSERT_EQ(run.exit_code, 0) << run.output();
  ASSERT_EQ(listener.get(), 0) << ReadFile(dir.path() / "listener.err");

  EXPECT_EQ(ReadFile(dir.path() / "received.pgm"), ReadFile(dir.path() / "out" / "map.pgm"));
  std::istringstream received(ReadFile(dir.path() / "received.txt"));
  double resolution = 0.0;
  double origin_x = 0.0;
  double origin_y = 0.0;
  int maps = 0;
  received >> resolution >> origin_x >> origin_y >> maps;
  std::string status_line;
  std::getline(received >> std::ws, status_line);
  EXPECT_GT(maps, 1);  // the map grew stop by stop, not only at the end
  const std::string yaml = ReadFile(dir.path() / "out" / "map.yaml");
  EXPECT_NE(yaml.find("resolution: " + std::to_string(resolution).substr(0, 4)), std::string::npos)
      << yaml;
  const nlohmann::json status = nlohmann::json::parse(status_line);
  EXPECT_EQ(status["status"], "complete");
  EXPECT_GT(status["stops"].get<int>(), 1);
  EXPECT_GT(status["known_area_m2"].get<double>(), 0.0);
}

TEST(Ros2Publish, BadRosSettingsAreRefusedNamingThem) {
  const testing::TempDir dir("ros2_bad");
  const std::string base = "explore --world " + World("soccer_field") + " --out " +
                           (dir.path() / "out").string() + " --quiet ";
  const testing::RunResult bad_ns = RunPirouette(base + "--ros2-publish --ros-namespace '1 x'");
  EXPECT_EQ(bad_ns.exit_code, 2);
  EXPECT_NE(bad_ns.stderr_only.find("--ros-namespace"), std::string::npos) << bad_ns.output();
  ::setenv("ROS_DOMAIN_ID", "999", 1);
  const testing::RunResult bad_domain = RunPirouette(base + "--ros2-publish");
  ::unsetenv("ROS_DOMAIN_ID");
  EXPECT_EQ(bad_domain.exit_code, 2);
  EXPECT_NE(bad_domain.stderr_only.find("ROS_DOMAIN_ID"), std::string::npos) << bad_domain.output();
  const testing::RunResult lonely = RunPirouette(base + "--ros-namespace robot1");
  EXPECT_EQ(lonely.exit_code, 2);
  EXPECT_NE(lonely.stderr_only.find("--ros2-publish"), std::string::npos) << lonely.output();
}

}  // namespace
}  // namespace pirouette
