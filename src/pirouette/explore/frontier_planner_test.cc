#include "pirouette/explore/frontier_planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "pirouette/explore/planner.h"
#include "pirouette/testing/test_grids.h"

namespace pirouette::explore {
namespace {

using mapping::CellState;

using testing::FillCells;
using testing::WalledMap;

using testing::TwoCellRobot;

// Known floor for x < 25, unknown beyond (frontier A: the column x = 25, 28
// cells); a 2 × 2 unknown pocket at (3..4, 20..21) (frontier B, 4 cells); and
// a walled closet with an unknown cell the robot cannot reach.
mapping::TrinaryMap TwoFrontiers(int unknown_from = 25) {
  mapping::TrinaryMap map = WalledMap(40, 30);
  FillCells(map, unknown_from, 1, 38, 28, CellState::kUnknown);
  FillCells(map, 3, 20, 4, 21, CellState::kUnknown);
  FillCells(map, 10, 22, 16, 28, CellState::kOccupied);
  FillCells(map, 11, 23, 15, 27, CellState::kFree);
  FillCells(map, 13, 25, 13, 25, CellState::kUnknown);
  return map;
}

const Eigen::Vector2d kRobot(0.10, 0.10);

TEST(FrontierSearchTest, GroupsFrontierCellsAndCostsThemLikeExploreLite) {
  FrontierOptions options;
  const std::vector<Frontier> frontiers = FindFrontiers(TwoFrontiers(), kRobot, options);
  ASSERT_EQ(frontiers.size(), 2U);  // not the closet's
  const Frontier& a = frontiers[0];
  const Frontier& b = frontiers[1];
  EXPECT_EQ(a.cells.size(), 28U);
  EXPECT_NEAR(a.size_m, 0.28, 1e-12);
  EXPECT_NEAR(a.centroid_world.x(), 0.255, 1e-12);
  EXPECT_NEAR(a.centroid_world.y(), 0.15, 1e-12);
  EXPECT_NEAR(a.nearest_world.x(), 0.255, 1e-12);
  EXPECT_NEAR(a.nearest_world.y(), 0.105, 1e-12);
  EXPECT_NEAR(a.distance_m, std::hypot(0.155, 0.005), 1e-12);
  EXPECT_NEAR(a.cost, 3.0 * a.distance_m - 1.0 * 0.28, 1e-12);
  EXPECT_EQ(b.cells.size(), 4U);
  EXPECT_NEAR(b.centroid_world.x(), 0.04, 1e-12);
  EXPECT_NEAR(b.centroid_world.y(), 0.21, 1e-12);
  EXPECT_NEAR(b.distance_m, std::hypot(0.055, 0.105), 1e-12);
  EXPECT_NEAR(b.cost, 3.0 * b.distance_m - 0.04, 1e-12);
  EXPECT_LT(a.cost, b.cost);
}

TEST(FrontierSearchTest, GainAndPotentialScalesReorder) {
  FrontierOptions options;
  options.gain_scale = 0.0;  // nearest first
  const std::vector<Frontier> frontiers = FindFrontiers(TwoFrontiers(), kRobot, options);
  ASSERT_EQ(frontiers.size(), 2U);
  EXPECT_EQ(frontiers[0].cells.size(), 4U);
}

TEST(FrontierSearchTest, SmallFrontiersAreDropped) {
  FrontierOptions options;
  options.min_frontier_size_m = 0.05;
  const std::vector<Frontier> frontiers = FindFrontiers(TwoFrontiers(), kRobot, options);
  ASSERT_EQ(frontiers.size(), 1U);
  EXPECT_EQ(frontiers[0].cells.size(), 28U);
}

TEST(FrontierSearchTest, DiagonalCellsGroupAndARobotOffFreeSpaceStillSearches) {
  // Unknown along the top row and the right column meet at a corner: one
  // frontier, 8-connected. The robot stands on an unknown cell.
  mapping::TrinaryMap map = WalledMap(20, 20);
  FillCells(map, 1, 18, 18, 18, CellState::kUnknown);
  FillCells(map, 18, 1, 18, 18, CellState::kUnknown);
  FillCells(map, 5, 5, 5, 5, CellState::kUnknown);
  const std::vector<Frontier> frontiers = FindFrontiers(map, {0.055, 0.055}, FrontierOptions{});
  ASSERT_EQ(frontiers.size(), 2U);
  // 17 + 17 (the corner cell has no free neighbour) and the cell under the robot.
  EXPECT_EQ(frontiers[0].cells.size() + frontiers[1].cells.size(), 17U + 17U + 1U);
  EXPECT_TRUE(FindFrontiers(map, {-1.0, 0.0}, FrontierOptions{}).empty());
}

TEST(FrontierPlannerTest, HeadsForTheCheapestFrontierAndStopsBeforeTheUnknown) {
  const auto planner = MakeFrontierPlanner(TwoCellRobot());
  const mapping::TrinaryMap map = TwoFrontiers();
  const std::optional<Plan> plan = planner->Next(map, core::Pose2(kRobot.x(), kRobot.y(), 0.0));
  ASSERT_TRUE(plan);
  EXPECT_NEAR(plan->goal_world.x(), 0.255, 1e-12);
  EXPECT_NEAR(plan->goal_world.y(), 0.15, 1e-12);
  const CoarseGrid grid = PlanningGrid(map, TwoCellRobot());
  EXPECT_EQ(plan->goal_cell, grid.geometry().CellOf(plan->goal_world));
  EXPECT_EQ(grid.At(plan->goal_cell), CoarseCell::kGoal);
  ASSERT_FALSE(plan->waypoints_world.empty());
  for (const Eigen::Vector2d& p : plan->waypoints_world) {
    EXPECT_EQ(grid.At(grid.geometry().CellOf(p)), CoarseCell::kFree);
  }
  const core::CellIndex last = grid.geometry().CellOf(plan->waypoints_world.back());
  EXPECT_LE(std::abs(last.x - plan->goal_cell.x), 1);
  EXPECT_LE(std::abs(last.y - plan->goal_cell.y), 1);
}

TEST(FrontierPlannerTest, DrivesIntoAFreeCentroid) {
  // An L-shaped frontier whose centroid lies in known free floor.
  mapping::TrinaryMap map = WalledMap(30, 30);
  FillCells(map, 1, 28, 28, 28, CellState::kUnknown);
  FillCells(map, 28, 1, 28, 28, CellState::kUnknown);
  const auto planner = MakeFrontierPlanner(TwoCellRobot());
  const std::optional<Plan> plan = planner->Next(map, core::Pose2(0.05, 0.05, 0.0));
  ASSERT_TRUE(plan);
  const CoarseGrid grid = PlanningGrid(map, TwoCellRobot());
  EXPECT_EQ(grid.At(plan->goal_cell), CoarseCell::kFree);
  ASSERT_FALSE(plan->waypoints_world.empty());
  EXPECT_EQ(plan->waypoints_world.back(), grid.geometry().CellCentre(plan->goal_cell));
}

TEST(FrontierPlannerTest, BlockedCentroidFallsBackToTheNearestCell) {
  // Unknown bands along the top and the right: one L-shaped frontier (the
  // row y = 24 and the column x = 24) whose centroid, (0.185, 0.185), is in
  // an obstacle.
  mapping::TrinaryMap map = WalledMap(30, 30);
  FillCells(map, 1, 24, 28, 28, CellState::kUnknown);
  FillCells(map, 24, 1, 28, 28, CellState::kUnknown);
  FillCells(map, 17, 17, 19, 19, CellState::kOccupied);
  const Eigen::Vector2d robot(0.05, 0.05);
  const std::vector<Frontier> frontiers = FindFrontiers(map, robot, FrontierOptions{});
  ASSERT_EQ(frontiers.size(), 1U);
  EXPECT_NEAR(frontiers[0].centroid_world.x(), 0.185, 1e-12);
  const CoarseGrid grid = PlanningGrid(map, TwoCellRobot());
  ASSERT_EQ(grid.At(grid.geometry().CellOf(frontiers[0].centroid_world)), CoarseCell::kBlocked);
  const std::optional<Plan> plan =
      MakeFrontierPlanner(TwoCellRobot())->Next(map, core::Pose2(robot.x(), robot.y(), 0.0));
  ASSERT_TRUE(plan);
  EXPECT_EQ(plan->goal_world, frontiers[0].nearest_world);
  EXPECT_EQ(plan->goal_cell, grid.geometry().CellOf(frontiers[0].nearest_world));
  EXPECT_NEAR(std::max(plan->goal_world.x(), plan->goal_world.y()), 0.245, 1e-12);
}

TEST(FrontierPlannerTest, BlacklistsGoalsReportedUnreachableWithinATolerance) {
  const core::Pose2 robot(kRobot.x(), kRobot.y(), 0.0);
  FrontierOptions options;
  options.min_frontier_size_m = 0.05;  // leaves frontier A only
  {
    const auto planner = MakeFrontierPlanner(TwoCellRobot(), options);
    const std::optional<Plan> plan = planner->Next(TwoFrontiers(), robot);
    ASSERT_TRUE(plan);
    planner->ReportUnreachable(*plan);
    EXPECT_FALSE(planner->Next(TwoFrontiers(), robot));
    // The frontier seen 2 cells farther: its centroid is within 5 cells.
    EXPECT_FALSE(planner->Next(TwoFrontiers(27), robot));
    // 6 cells farther: a new goal.
    const std::optional<Plan> farther = planner->Next(TwoFrontiers(31), robot);
    ASSERT_TRUE(farther);
    EXPECT_NEAR(farther->goal_world.x(), 0.315, 1e-12);
  }
  {
    // Without the report, the same goal again.
    const auto planner = MakeFrontierPlanner(TwoCellRobot(), options);
    ASSERT_TRUE(planner->Next(TwoFrontiers(), robot));
    EXPECT_TRUE(planner->Next(TwoFrontiers(), robot));
  }
}

TEST(FrontierPlannerTest, FrontiersWithNoPathArePassedOver) {
  // Frontier A lies behind a wall with a gap of one map cell: the frontier
  // search finds it, the robot cannot get through. B is reachable.
  mapping::TrinaryMap map = TwoFrontiers();
  FillCells(map, 21, 1, 22, 14, CellState::kOccupied);
  FillCells(map, 21, 16, 22, 28, CellState::kOccupied);
  FrontierOptions options;
  options.min_frontier_size_m = 0.01;
  const auto planner = MakeFrontierPlanner(TwoCellRobot(), options);
  const std::optional<Plan> plan = planner->Next(map, core::Pose2(kRobot.x(), kRobot.y(), 0.0));
  ASSERT_TRUE(plan);
  EXPECT_NEAR(plan->goal_world.x(), 0.04, 1e-12);
}

TEST(FrontierPlannerTest, AGoalThatOutlastsAPirouetteThereIsGivenUp) {
  // The robot stands in the last free coarse cell before frontier B.
  mapping::TrinaryMap map = WalledMap(30, 30);
  FillCells(map, 20, 10, 27, 11, CellState::kUnknown);
  const auto planner = MakeFrontierPlanner(TwoCellRobot(), FrontierOptions{});
  const std::optional<Plan> first = planner->Next(map, core::Pose2(0.05, 0.05, 0.0));
  ASSERT_TRUE(first);
  ASSERT_FALSE(first->waypoints_world.empty());
  const Eigen::Vector2d stop = first->waypoints_world.back();
  const core::Pose2 there(stop.x(), stop.y(), 0.0);
  const std::optional<Plan> at = planner->Next(map, there);
  ASSERT_TRUE(at);
  EXPECT_TRUE(at->waypoints_world.empty());
  EXPECT_FALSE(planner->Next(map, there));  // still unknown after the pirouette: given up
}

TEST(FrontierPlannerTest, RejectsBadOptions) {
  FrontierOptions bad;
  bad.potential_scale = -1.0;
  EXPECT_THROW(MakeFrontierPlanner(TwoCellRobot(), bad), std::invalid_argument);
  bad = FrontierOptions{};
  bad.blacklist_tolerance_cells = -2;
  EXPECT_THROW(MakeFrontierPlanner(TwoCellRobot(), bad), std::invalid_argument);
  EXPECT_THROW(MakeFrontierPlanner(PlannerOptions{}), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::explore
