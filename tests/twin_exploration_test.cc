// A digital twin explored (docs/worlds.md, "Exploring the twins"): the map of
// Gazebo's turtlebot3_world from ../shared/realdata/maps (skipped where
// absent) made a world by `world from-map`, explored by the apartment robot
// with the defaults and no odometry noise, ends complete within the
// noise-free bounds.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace {

namespace fs = std::filesystem;

TEST(TwinExplorationTest, TheTurtlebot3WorldsTwinIsMappedWithinTheBounds) {
  const std::string map =
      std::string(PIROUETTE_SHARED_DIR) + "/realdata/maps/sim_tb3_world/map.yaml";
  if (!fs::exists(map)) GTEST_SKIP() << "no real maps at " << map;
  const pirouette::testing::TempDir dir("pirouette_twin_exploration_test");
  const std::string world = dir / "twin.yaml";
  const auto made =
      pirouette::testing::RunPirouette("world from-map --map " + map + " --out " + world);
  ASSERT_EQ(made.exit_code, 0) << made.output();
  const auto run = pirouette::testing::RunPirouette("explore --quiet --world " + world + " --out " +
                                                    (dir / "out"));
  ASSERT_EQ(run.exit_code, 0) << run.output();
  std::ifstream in(dir / "out/run.json");
  const nlohmann::json j = nlohmann::json::parse(in);
  EXPECT_EQ(j.at("status"), "complete");
  const nlohmann::json& e = j.at("eval");
  EXPECT_GE(e.at("coverage").get<double>(), 0.98);
  EXPECT_LE(e.at("false_free").get<double>(), 0.005);
  EXPECT_LE(e.at("wall_error_m").get<double>(), 0.02);  // one cell of the apartment robot's map
}

}  // namespace
