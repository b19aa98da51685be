#include "pirouette/explore/planner.h"

#include <gtest/gtest.h>

#include <stdexcept>

#include "pirouette/explore/configuration_space.h"
#include "pirouette/explore/moves.h"
#include "pirouette/testing/test_grids.h"

namespace pirouette::explore {
namespace {

using mapping::CellState;

using testing::FillCells;
using testing::WalledMap;

using testing::TwoCellRobot;

TEST(PlannerTest, LeadsStraightToTheNearestUnknownAndStopsBeforeIt) {
  mapping::TrinaryMap map = WalledMap(30, 20);
  FillCells(map, 20, 1, 28, 18, CellState::kUnknown);
  const auto planner = MakeDistanceTransformPlanner(TwoCellRobot());
  const core::Pose2 robot(0.05, 0.10, 0.0);
  const std::optional<Plan> plan = planner->Next(map, robot);
  ASSERT_TRUE(plan);
  // Along coarse row 5 (centres at y = 0.11) to the last free coarse cell
  // (9, 5) before the unknown at x >= 0.20; the robot's own cell's centre
  // is left out, the way to the next being clear.
  ASSERT_EQ(plan->waypoints_world.size(), 7U);
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_NEAR(plan->waypoints_world[i].x(), 0.07 + 0.02 * static_cast<double>(i), 1e-12);
    EXPECT_NEAR(plan->waypoints_world[i].y(), 0.11, 1e-12);
  }
  EXPECT_EQ(plan->goal_cell, (core::CellIndex{10, 5}));
  EXPECT_NEAR(plan->goal_world.x(), 0.21, 1e-12);
  EXPECT_NEAR(plan->length_m, std::hypot(0.02, 0.01) + 0.12, 1e-12);

  const std::vector<core::Move> moves = MovesAlong(robot, plan->waypoints_world);
  ASSERT_EQ(moves.size(), 4U);  // turn, the short leg onto the row, turn back, one drive
  EXPECT_NEAR(moves[3].amount, 0.12, 1e-12);
}

TEST(PlannerTest, WaypointsKeepToFreeCoarseCells) {
  // An L-shaped corridor: the plan turns the corner on free coarse cells.
  mapping::TrinaryMap map = WalledMap(40, 40);
  FillCells(map, 12, 1, 38, 26, CellState::kOccupied);
  FillCells(map, 30, 30, 38, 38, CellState::kUnknown);
  const PlannerOptions options = TwoCellRobot();
  const auto planner = MakeDistanceTransformPlanner(options);
  const core::Pose2 robot(0.06, 0.06, 0.0);
  const std::optional<Plan> plan = planner->Next(map, robot);
  ASSERT_TRUE(plan);
  const CoarseGrid grid = PlanningGrid(map, options);
  ASSERT_FALSE(plan->waypoints_world.empty());
  for (const Eigen::Vector2d& p : plan->waypoints_world) {
    EXPECT_EQ(grid.At(grid.geometry().CellOf(p)), CoarseCell::kFree);
  }
  EXPECT_EQ(grid.At(plan->goal_cell), CoarseCell::kGoal);
  // The last waypoint's cell neighbours the goal's.
  const core::CellIndex last = grid.geometry().CellOf(plan->waypoints_world.back());
  EXPECT_LE(std::abs(last.x - plan->goal_cell.x), 1);
  EXPECT_LE(std::abs(last.y - plan->goal_cell.y), 1);
  // Far fewer moves than cells: collinear steps merge.
  EXPECT_LE(MovesAlong(robot, plan->waypoints_world).size(), 8U);
}

TEST(PlannerTest, NothingWhenNoUnknownIsLeftOrReachable) {
  const auto planner = MakeDistanceTransformPlanner(TwoCellRobot());
  EXPECT_FALSE(planner->Next(WalledMap(20, 20), core::Pose2(0.1, 0.1, 0.0)));
  // Unknown only behind a wall.
  mapping::TrinaryMap map = WalledMap(30, 20);
  FillCells(map, 20, 1, 20, 18, CellState::kOccupied);
  FillCells(map, 21, 1, 28, 18, CellState::kUnknown);
  EXPECT_FALSE(planner->Next(map, core::Pose2(0.1, 0.1, 0.0)));
}

TEST(PlannerTest, GoalUnderTheRobotGivesAnEmptyPlanThenIsGivenUp) {
  mapping::TrinaryMap map = WalledMap(30, 20);
  FillCells(map, 10, 10, 10, 10, CellState::kUnknown);  // in the robot's coarse cell
  FillCells(map, 22, 4, 23, 5, CellState::kUnknown);    // a second goal, farther
  const auto planner = MakeDistanceTransformPlanner(TwoCellRobot());
  const core::Pose2 robot(0.105, 0.105, 0.0);
  const std::optional<Plan> here = planner->Next(map, robot);
  ASSERT_TRUE(here);
  EXPECT_TRUE(here->waypoints_world.empty());
  EXPECT_EQ(here->goal_cell, (core::CellIndex{5, 5}));
  // The robot pirouetted there and the cell is still unknown: give it up.
  const std::optional<Plan> next = planner->Next(map, robot);
  ASSERT_TRUE(next);
  EXPECT_EQ(next->goal_cell, (core::CellIndex{11, 2}));
  EXPECT_FALSE(next->waypoints_world.empty());
}

TEST(PlannerTest, ReportedUnreachableGoalsAreNotOfferedAgain) {
  mapping::TrinaryMap map = WalledMap(40, 20);
  FillCells(map, 30, 10, 31, 11, CellState::kUnknown);  // nearer
  FillCells(map, 4, 10, 5, 11, CellState::kUnknown);    // farther
  const auto planner = MakeDistanceTransformPlanner(TwoCellRobot());
  const core::Pose2 robot(0.22, 0.11, 0.0);
  const std::optional<Plan> first = planner->Next(map, robot);
  ASSERT_TRUE(first);
  EXPECT_EQ(first->goal_cell, (core::CellIndex{15, 5}));
  planner->ReportUnreachable(*first);
  const std::optional<Plan> second = planner->Next(map, robot);
  ASSERT_TRUE(second);
  EXPECT_EQ(second->goal_cell, (core::CellIndex{2, 5}));
  planner->ReportUnreachable(*second);
  EXPECT_FALSE(planner->Next(map, robot));
}

TEST(PlannerTest, RobotInABlockedCellStartsFromAFreeNeighbour) {
  mapping::TrinaryMap map = WalledMap(30, 20);
  FillCells(map, 20, 1, 28, 18, CellState::kUnknown);
  // An obstacle seen right beside the robot puts its cell in c-space.
  FillCells(map, 8, 12, 8, 12, CellState::kOccupied);
  const PlannerOptions options = TwoCellRobot();
  const CoarseGrid grid = PlanningGrid(map, options);
  const core::Pose2 robot(0.085, 0.105, 0.0);
  ASSERT_EQ(grid.At(grid.geometry().CellOf(robot.translation())), CoarseCell::kBlocked);
  const std::optional<Plan> plan = MakeDistanceTransformPlanner(options)->Next(map, robot);
  ASSERT_TRUE(plan);
  ASSERT_FALSE(plan->waypoints_world.empty());
  EXPECT_EQ(grid.At(grid.geometry().CellOf(plan->waypoints_world.front())), CoarseCell::kFree);
}

TEST(PlannerTest, PlanAlongEntersAFreeGoalWhenAsked) {
  mapping::TrinaryMap map = WalledMap(20, 10);
  const CoarseGrid known = PlanningGrid(map, TwoCellRobot());
  CoarseGrid grid = known;
  grid.Set({7, 2}, CoarseCell::kGoal);
  const DistanceField field = ChamferDistanceTransform(grid);
  const std::optional<Path> path = SteepestDescent(grid, field, {3, 2});
  ASSERT_TRUE(path);
  const Plan stop = PlanAlong(grid, *path, grid.geometry().CellCentre({3, 2}), false);
  const Plan enter = PlanAlong(grid, *path, grid.geometry().CellCentre({3, 2}), true);
  ASSERT_EQ(stop.waypoints_world.size(), 3U);
  ASSERT_EQ(enter.waypoints_world.size(), 4U);
  EXPECT_EQ(enter.waypoints_world.back(), grid.geometry().CellCentre({7, 2}));
  EXPECT_NEAR(enter.length_m, 0.08, 1e-12);
}

TEST(PlannerTest, RejectsBadOptionsAndARobotOffTheMap) {
  EXPECT_THROW(MakeDistanceTransformPlanner(PlannerOptions{}), std::invalid_argument);
  PlannerOptions bad = TwoCellRobot();
  bad.coarse_factor = -1;
  EXPECT_THROW(MakeDistanceTransformPlanner(bad), std::invalid_argument);
  const auto planner = MakeDistanceTransformPlanner(TwoCellRobot());
  EXPECT_THROW(planner->Next(WalledMap(10, 10), core::Pose2(0.5, 0.05, 0.0)), std::out_of_range);
}

TEST(PlannerTest, DefaultCoarseFactorFollowsTheRadius) {
  PlannerOptions options;
  options.robot_radius_m = 0.04;
  EXPECT_EQ(options.CoarseFactor(0.01), 2);
  options.coarse_factor = 5;
  EXPECT_EQ(options.CoarseFactor(0.01), 5);
}

}  // namespace
}  // namespace pirouette::explore
