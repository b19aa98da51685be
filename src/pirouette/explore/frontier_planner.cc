#include "pirouette/explore/frontier_planner.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <deque>
#include <limits>
#include <optional>
#include <stdexcept>
#include <utility>

#include "pirouette/explore/distance_transform.h"
#include "pirouette/explore/goal_memory.h"
#include "pirouette/explore/path.h"

namespace pirouette::explore {
namespace {

using mapping::CellState;

constexpr std::array<std::array<int, 2>, 4> kNeighbours4 = {{{1, 0}, {0, 1}, {-1, 0}, {0, -1}}};
constexpr std::array<std::array<int, 2>, 8> kNeighbours8 = {
    {{1, 0}, {1, 1}, {0, 1}, {-1, 1}, {-1, 0}, {-1, -1}, {0, -1}, {1, -1}}};

bool IsFrontierCell(const mapping::TrinaryMap& map, const core::CellIndex& c) {
  if (map.At(c) != CellState::kUnknown) return false;
  return std::any_of(kNeighbours4.begin(), kNeighbours4.end(), [&](const auto& d) {
    const core::CellIndex n{c.x + d[0], c.y + d[1]};
    return map.geometry.Contains(n) && map.At(n) == CellState::kFree;
  });
}

// The free cell nearest `start` in breadth-first order (explore_lite's
// nearestCell), if any.
std::optional<core::CellIndex> NearestFree(const mapping::TrinaryMap& map,
                                           const core::CellIndex& start) {
  const core::GridGeometry& g = map.geometry;
  std::vector<bool> seen(g.CellCount(), false);
  std::deque<core::CellIndex> queue = {start};
  seen[g.Flat(start)] = true;
  while (!queue.empty()) {
    const core::CellIndex c = queue.front();
    queue.pop_front();
    if (map.At(c) == CellState::kFree) return c;
    for (const auto& d : kNeighbours4) {
      const core::CellIndex n{c.x + d[0], c.y + d[1]};
      if (g.Contains(n) && !seen[g.Flat(n)]) {
        seen[g.Flat(n)] = true;
        queue.push_back(n);
      }
    }
  }
  return std::nullopt;
}

class FrontierPlanner final : public Planner {
 public:
  FrontierPlanner(const PlannerOptions& options, const FrontierOptions& frontier_options)
      : options_(options), frontier_options_(frontier_options) {
    options_.Check();
    frontier_options_.Check();
    if (frontier_options_.min_frontier_size_m == 0.0) {
      frontier_options_.min_frontier_size_m = 3.0 * options_.robot_radius_m;
    }
  }

  std::optional<Plan> Next(const mapping::TrinaryMap& map,
                           const core::Pose2& world_T_robot) override {
    const Eigen::Vector2d& robot = world_T_robot.translation();
    if (!map.geometry.CellAt(robot)) throw std::out_of_range("Planner: the robot is off the map");
    const double tolerance_m =
        frontier_options_.blacklist_tolerance_cells * map.geometry.resolution();
    const CoarseGrid grid = PlanningGrid(map, options_);
    const core::CellIndex start = grid.geometry().CellOf(robot);
    const bool stalled = goals_.Stalled(robot, 0.5 * map.geometry.resolution());
    for (const Frontier& frontier : FindFrontiers(map, robot, frontier_options_)) {
      // The centroid, or if it cannot be reached, the cell nearest the robot
      // whose coarse cell is not blocked.
      const std::optional<Eigen::Vector2d> near =
          NearestOpenCell(map.geometry, grid, frontier, robot);
      std::vector<Eigen::Vector2d> targets = {frontier.centroid_world};
      if (near) targets.push_back(*near);
      for (const Eigen::Vector2d& target : targets) {
        if (goals_.GaveUp(target, tolerance_m)) continue;
        std::optional<Plan> plan = PlanTo(grid, start, robot, target);
        if (!plan) continue;
        if (stalled && goals_.NearLastGoal(target, tolerance_m)) {
          goals_.GiveUp(target);
          continue;
        }
        goals_.Remember(robot, plan->goal_world, plan->waypoints_world.empty());
        return plan;
      }
    }
    goals_.Forget();
    return std::nullopt;
  }

  void ReportUnreachable(const Plan& plan) override { goals_.GiveUp(plan.goal_world); }

 private:
  // The centre of the frontier's cell nearest the robot among those whose
  // coarse cell is not blocked, if any.
  static std::optional<Eigen::Vector2d> NearestOpenCell(const core::GridGeometry& map,
                                                        const CoarseGrid& grid,
                                                        const Frontier& frontier,
                                                        const Eigen::Vector2d& robot) {
    std::optional<Eigen::Vector2d> best;
    double best_distance = std::numeric_limits<double>::infinity();
    for (const core::CellIndex& c : frontier.cells) {
      const Eigen::Vector2d p = map.CellCentre(c);
      const std::optional<core::CellIndex> coarse = grid.geometry().CellAt(p);
      if (!coarse || grid.At(*coarse) == CoarseCell::kBlocked) continue;
      const double distance = (p - robot).norm();
      if (distance < best_distance) {
        best_distance = distance;
        best = p;
      }
    }
    return best;
  }

  // The shortest path on the coarse grid to the coarse cell of `target`,
  // unless it is blocked.
  static std::optional<Plan> PlanTo(const CoarseGrid& grid, const core::CellIndex& start,
                                    const Eigen::Vector2d& robot, const Eigen::Vector2d& target) {
    const std::optional<core::CellIndex> goal = grid.geometry().CellAt(target);
    if (!goal || grid.At(*goal) == CoarseCell::kBlocked) return std::nullopt;
    // One goal; the path keeps to known free coarse cells like the paper's.
    std::vector<CoarseCell> cells = grid.cells();
    std::replace(cells.begin(), cells.end(), CoarseCell::kGoal, CoarseCell::kBlocked);
    CoarseGrid single(grid.geometry(), std::move(cells));
    single.Set(*goal, CoarseCell::kGoal);
    const DistanceField field = ChamferDistanceTransform(single);
    const std::optional<Path> path = SteepestDescent(single, field, start);
    if (!path) return std::nullopt;
    Plan plan = PlanAlong(single, *path, robot, grid.At(*goal) == CoarseCell::kFree);
    plan.goal_world = target;
    return plan;
  }

  PlannerOptions options_;
  FrontierOptions frontier_options_;
  GoalMemory goals_;
};

}  // namespace

void FrontierOptions::Check() const {
  const auto ok = [](double v) { return std::isfinite(v) && v >= 0.0; };
  if (!ok(potential_scale) || !ok(gain_scale) || !ok(min_frontier_size_m)) {
    throw std::invalid_argument(
        "FrontierOptions: potential_scale, gain_scale and min_frontier_size_m must be finite and "
        ">= 0");
  }
  if (blacklist_tolerance_cells < 0) {
    throw std::invalid_argument("FrontierOptions: blacklist_tolerance_cells must be >= 0");
  }
}

std::vector<Frontier> FindFrontiers(const mapping::TrinaryMap& map,
                                    const Eigen::Vector2d& robot_world,
                                    const FrontierOptions& options) {
  options.Check();
  const core::GridGeometry& g = map.geometry;
  std::vector<Frontier> frontiers;
  const std::optional<core::CellIndex> robot_cell = g.CellAt(robot_world);
  if (!robot_cell) return frontiers;
  const core::CellIndex start = NearestFree(map, *robot_cell).value_or(*robot_cell);

  std::vector<bool> visited(g.CellCount(), false);
  std::vector<bool> frontier_flag(g.CellCount(), false);
  std::deque<core::CellIndex> queue = {start};
  visited[g.Flat(start)] = true;
  while (!queue.empty()) {
    const core::CellIndex c = queue.front();
    queue.pop_front();
    for (const auto& d : kNeighbours4) {
      const core::CellIndex n{c.x + d[0], c.y + d[1]};
      if (!g.Contains(n)) continue;
      const std::size_t i = g.Flat(n);
      if (map.At(n) == CellState::kFree && !visited[i]) {
        visited[i] = true;
        queue.push_back(n);
      } else if (!frontier_flag[i] && IsFrontierCell(map, n)) {
        // A new frontier: grow it over 8-connected frontier cells.
        Frontier f;
        f.distance_m = std::numeric_limits<double>::infinity();
        std::deque<core::CellIndex> grow = {n};
        frontier_flag[i] = true;
        Eigen::Vector2d sum = Eigen::Vector2d::Zero();
        while (!grow.empty()) {
          const core::CellIndex fc = grow.front();
          grow.pop_front();
          f.cells.push_back(fc);
          const Eigen::Vector2d p = g.CellCentre(fc);
          sum += p;
          const double distance = (p - robot_world).norm();
          if (distance < f.distance_m) {
            f.distance_m = distance;
            f.nearest_world = p;
          }
          for (const auto& d8 : kNeighbours8) {
            const core::CellIndex m{fc.x + d8[0], fc.y + d8[1]};
            if (g.Contains(m) && !frontier_flag[g.Flat(m)] && IsFrontierCell(map, m)) {
              frontier_flag[g.Flat(m)] = true;
              grow.push_back(m);
            }
          }
        }
        f.centroid_world = sum / static_cast<double>(f.cells.size());
        f.size_m = static_cast<double>(f.cells.size()) * g.resolution();
        if (f.size_m + 1e-12 < options.min_frontier_size_m) continue;
        f.cost = options.potential_scale * f.distance_m - options.gain_scale * f.size_m;
        frontiers.push_back(std::move(f));
      }
    }
  }
  std::stable_sort(frontiers.begin(), frontiers.end(),
                   [](const Frontier& a, const Frontier& b) { return a.cost < b.cost; });
  return frontiers;
}

std::unique_ptr<Planner> MakeFrontierPlanner(const PlannerOptions& options,
                                             FrontierOptions frontier_options) {
  return std::make_unique<FrontierPlanner>(options, frontier_options);
}

}  // namespace pirouette::explore
