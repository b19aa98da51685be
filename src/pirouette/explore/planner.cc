#include "pirouette/explore/planner.h"

#include <cmath>
#include <stdexcept>

#include "pirouette/explore/configuration_space.h"
#include "pirouette/explore/distance_transform.h"
#include "pirouette/explore/goal_memory.h"

namespace pirouette::explore {
namespace {

// Whether the straight segment from a to b crosses only kFree cells of the
// grid (or the cell `goal`, if `goal_too`), sampled at an eighth of a cell.
bool SegmentFree(const CoarseGrid& grid, const Eigen::Vector2d& a, const Eigen::Vector2d& b,
                 bool goal_too, const core::CellIndex& goal) {
  const double length = (b - a).norm();
  const int samples = 1 + static_cast<int>(std::ceil(8.0 * length / grid.geometry().resolution()));
  for (int i = 0; i <= samples; ++i) {
    const Eigen::Vector2d p = a + (b - a) * (static_cast<double>(i) / samples);
    const std::optional<core::CellIndex> c = grid.geometry().CellAt(p);
    if (!c) return false;
    if (grid.At(*c) != CoarseCell::kFree && !(goal_too && *c == goal)) return false;
  }
  return true;
}

core::CellIndex RobotCell(const core::GridGeometry& geometry, const Eigen::Vector2d& p_world) {
  const std::optional<core::CellIndex> c = geometry.CellAt(p_world);
  if (!c) throw std::out_of_range("Planner: the robot is off the map");
  return *c;
}

class DistanceTransformPlanner final : public Planner {
 public:
  explicit DistanceTransformPlanner(const PlannerOptions& options) : options_(options) {
    options_.Check();
  }

  std::optional<Plan> Next(const mapping::TrinaryMap& map,
                           const core::Pose2& world_T_robot) override {
    const Eigen::Vector2d& robot = world_T_robot.translation();
    static_cast<void>(RobotCell(map.geometry, robot));
    CoarseGrid grid = PlanningGrid(map, options_);
    const core::CellIndex start = RobotCell(grid.geometry(), robot);
    // The last plan told the robot to pirouette where it stands.
    const bool stalled = goals_.Stalled(robot, 0.5 * map.geometry.resolution());
    while (true) {
      for (const Eigen::Vector2d& p : goals_.given_up()) {
        const std::optional<core::CellIndex> c = grid.geometry().CellAt(p);
        if (c && grid.At(*c) == CoarseCell::kGoal) grid.Set(*c, CoarseCell::kBlocked);
      }
      const DistanceField field = ChamferDistanceTransform(grid);
      const std::optional<Path> path = SteepestDescent(grid, field, start);
      if (!path) {
        goals_.Forget();
        return std::nullopt;
      }
      Plan plan = PlanAlong(grid, *path, robot, false);
      plan.goal_world = grid.geometry().CellCentre(path->goal);
      if (stalled && goals_.IsLastGoal(plan.goal_world)) {
        // Its pirouette there did not clear the goal: give it up, like
        // explore_lite's progress timeout.
        goals_.GiveUp(plan.goal_world);
        continue;
      }
      goals_.Remember(robot, plan.goal_world, plan.waypoints_world.empty());
      return plan;
    }
  }

  void ReportUnreachable(const Plan& plan) override { goals_.GiveUp(plan.goal_world); }

 private:
  PlannerOptions options_;
  GoalMemory goals_;  // goals given up, as their cells' centres
};

}  // namespace

void PlannerOptions::Check() const {
  if (!std::isfinite(robot_radius_m) || !(robot_radius_m > 0.0)) {
    throw std::invalid_argument("PlannerOptions: robot_radius_m must be finite and > 0");
  }
  if (coarse_factor < 0) throw std::invalid_argument("PlannerOptions: coarse_factor must be >= 0");
}

int PlannerOptions::CoarseFactor(double resolution_m) const {
  return coarse_factor > 0 ? coarse_factor : DefaultCoarseFactor(robot_radius_m, resolution_m);
}

CoarseGrid PlanningGrid(const mapping::TrinaryMap& map, const PlannerOptions& options) {
  return CoarseGrid::FromConfigurationSpace(MakeConfigurationSpace(map, options.robot_radius_m),
                                            options.CoarseFactor(map.geometry.resolution()));
}

Plan PlanAlong(const CoarseGrid& grid, const Path& path, const Eigen::Vector2d& robot_world,
               bool enter_goal) {
  const core::GridGeometry& g = grid.geometry();
  std::vector<core::CellIndex> cells = path.cells;
  if (enter_goal) cells.push_back(path.goal);
  Plan plan;
  plan.goal_cell = path.goal;
  for (const core::CellIndex& c : cells) plan.waypoints_world.push_back(g.CellCentre(c));
  if (!cells.empty() && g.CellOf(robot_world) == cells.front()) {
    const bool last = plan.waypoints_world.size() == 1;
    if (last || SegmentFree(grid, robot_world, plan.waypoints_world[1], enter_goal, path.goal)) {
      plan.waypoints_world.erase(plan.waypoints_world.begin());
    }
  }
  Eigen::Vector2d from = robot_world;
  for (const Eigen::Vector2d& p : plan.waypoints_world) {
    plan.length_m += (p - from).norm();
    from = p;
  }
  return plan;
}

std::unique_ptr<Planner> MakeDistanceTransformPlanner(const PlannerOptions& options) {
  return std::make_unique<DistanceTransformPlanner>(options);
}

}  // namespace pirouette::explore
