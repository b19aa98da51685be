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

void ExpectExploredWithinBounds(const sim::World& world, const std::string& name,
                                PlannerKind planner) {
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

void ExpectExploredWithinBounds(const std::string& name, PlannerKind planner) {
  ExpectExploredWithinBounds(io::LoadWorldFile(WorldPath(name)), name, planner);
}

TEST(ExplorationTest, SoccerFieldIsMappedCompletely) {
  ExpectExploredWithinBounds("soccer_field", PlannerKind::kDistanceTransform);
}

TEST(ExplorationTest, MazeIsMappedCompletely) {
  ExpectExploredWithinBounds("maze", PlannerKind::kDistanceTransform);
}

// Two rooms joined by a passage 0.13 m wide and 0.30 m long: 1.6 diameters of
// the Yujin robot, a clearance of 5 cm, which a cell of wall error on each
// side brings under the two coarse cells (2 cm each) that keep a passage
// open on the coarse planning grid whatever its alignment
// (explore::DefaultCoarseFactor). The coarse plans end at the
// passage's mouth, the east room unseen (coverage 0.50 before); a plan on the
// map's own cells, the explorer's fallback when the coarse grid has none,
// takes the robot through, each leg looked at first as always.
TEST(ExplorationTest, APassageTooNarrowForTheCoarseGridIsPassed) {
  const std::string walls = "{thickness: 0.02, height: 0.10, colour: [240, 235, 225]";
  std::string text =
      "format: pirouette-world/1\n"
      "name: narrow-passage\n"
      "floor: {size: [1.60, 0.80], colour: [140, 95, 55], texture: 0.08}\n"
      "walls: {height: 0.10, thickness: 0.02, colour: [240, 235, 225]}\n"
      "obstacles:\n";
  for (const char* ends :
       {"[0.65, 0.00], to: [0.65, 0.335]", "[0.65, 0.465], to: [0.65, 0.80]",
        "[0.95, 0.00], to: [0.95, 0.335]", "[0.95, 0.465], to: [0.95, 0.80]",
        "[0.65, 0.335], to: [0.95, 0.335]", "[0.65, 0.465], to: [0.95, 0.465]"}) {
    text += std::string("  - wall: ") + walls + ", from: " + ends + "}\n";
  }
  text += "robot: {start: [0.30, 0.40, 0], radius: 0.04, camera: yujin.yaml}\n";
  const sim::World world = io::ParseWorldText(text, WorldPath("narrow_passage"));
  ExpectExploredWithinBounds(world, "narrow_passage", PlannerKind::kDistanceTransform);
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
