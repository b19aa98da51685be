// Whole explorations in the simulator: the robot, knowing nothing, maps a
// world by itself to status "complete" within the bounds of
// docs/measurements.md, "Exploration maps": coverage >= 0.98, false_free <=
// 0.005, false_occupied <= 0.02, wall_error_m <= one map cell.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pirouette/eval/map_evaluation.h"
#include "pirouette/io/world_file.h"
#include "pirouette/run/explorer.h"
#include "pirouette/run/simulated_exploration.h"

namespace pirouette::run {
namespace {

std::string WorldPath(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml";
}

void ExpectExploredWithinBounds(const std::string& name, PlannerKind planner) {
  const sim::World world = io::LoadWorldFile(WorldPath(name));
  run::ExplorationOptions options;
  options.seed = 1;
  options.planner = planner;
  const ExplorationResult result = Explore(world, options);
  // The map of record: what map.pgm holds and run.json's eval judges.
  const eval::MapEvaluation eval = eval::EvaluateMap(result.grid.ToMapOfRecord(), world);
  const double cell = result.grid.geometry().resolution();
  EXPECT_EQ(result.status, "complete") << name << ": " << result.reason;
  EXPECT_GE(eval.coverage, 0.98) << name;
  EXPECT_LE(eval.false_free, 0.005) << name;
  EXPECT_LE(eval.false_occupied, 0.02) << name;
  EXPECT_LE(eval.wall_error_m, cell) << name;
  EXPECT_GT(result.pirouettes, 1) << name;
  // Every pirouette's frames, and a look before every straight move.
  EXPECT_GE(result.frames, result.pirouettes * core::kPirouetteTurns + result.moves) << name;
}

TEST(ExplorationTest, SoccerFieldIsMappedCompletely) {
  ExpectExploredWithinBounds("soccer_field", PlannerKind::kDistanceTransform);
}

TEST(ExplorationTest, MazeIsMappedCompletely) {
  ExpectExploredWithinBounds("maze", PlannerKind::kDistanceTransform);
}

TEST(ExplorationTest, FrontierBaselineMapsTheSoccerField) {
  ExpectExploredWithinBounds("soccer_field", PlannerKind::kFrontier);
}

TEST(ExplorationTest, ReturnHomeEndsWhereItStarted) {
  const sim::World world = io::LoadWorldFile(WorldPath("two_rooms"));
  run::ExplorationOptions options;
  options.return_home = true;
  const ExplorationResult result = Explore(world, options);
  EXPECT_EQ(result.status, "complete") << result.reason;
  const core::Pose2& start = world.robot().start;
  EXPECT_LT((result.final_true_pose->translation() - start.translation()).norm(), 0.02);
  EXPECT_LT(std::abs(core::NormalizeAngle(result.final_true_pose->heading() - start.heading())),
            0.02);
}

TEST(ExplorationTest, SameWorldAndSeedGiveTheSameMap) {
  const sim::World world = io::LoadWorldFile(WorldPath("soccer_field"));
  run::ExplorationOptions options;
  options.seed = 3;
  options.max_steps = 15;
  const ExplorationResult a = Explore(world, options);
  const ExplorationResult b = Explore(world, options);
  const mapping::TrinaryMap map_a = a.grid.ToTrinary();
  const mapping::TrinaryMap map_b = b.grid.ToTrinary();
  EXPECT_EQ(map_a.geometry, map_b.geometry);
  EXPECT_TRUE(map_a.cells == map_b.cells);
  EXPECT_EQ(a.moves, b.moves);
  EXPECT_EQ(a.status, "step-limit");
}

TEST(ExplorationTest, StepLimitStopsTheRun) {
  const sim::World world = io::LoadWorldFile(WorldPath("soccer_field"));
  run::ExplorationOptions options;
  options.max_steps = 3;
  const ExplorationResult result = Explore(world, options);
  EXPECT_EQ(result.status, "step-limit");
  EXPECT_EQ(result.moves, 3);
}

TEST(ExplorationTest, AStopRequestEndsTheRunWithTheMapSoFar) {
  const sim::World world = io::LoadWorldFile(WorldPath("soccer_field"));
  const std::atomic<bool> stop{true};
  run::ExplorationOptions options;
  options.stop_requested = &stop;
  const ExplorationResult result = Explore(world, options);
  EXPECT_EQ(result.status, "interrupted");
  // Checked between the frames of a pirouette too (a real robot's takes a
  // while): a stop asked before the start ends the run before the first frame.
  EXPECT_EQ(result.frames, 0);
  EXPECT_EQ(result.pirouettes, 0);
}

}  // namespace
}  // namespace pirouette::run
