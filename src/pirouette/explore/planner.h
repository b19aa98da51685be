#pragma once

#include <Eigen/Core>
#include <memory>
#include <optional>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/core/pose2.h"
#include "pirouette/explore/coarse_grid.h"
#include "pirouette/explore/path.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::explore {

struct PlannerOptions {
  double robot_radius_m = 0.0;  // the robot's footprint is a disc of this radius
  // Map cells a coarse cell's side; 0: DefaultCoarseFactor of the radius.
  int coarse_factor = 0;

  // Throws std::invalid_argument unless the radius is finite and > 0 and
  // coarse_factor >= 0.
  void Check() const;
  // The coarse factor on a map of `resolution_m`.
  int CoarseFactor(double resolution_m) const;
};

// Where to go next: a path from the robot's position, in straight legs
// between coarse cell centres, to the last free coarse cell before a goal;
// there the robot pirouettes and sees into the unknown.
struct Plan {
  // From the robot's position, excluding it; empty when the robot is
  // already where it should pirouette. MovesAlong turns them into moves.
  std::vector<Eigen::Vector2d> waypoints_world;
  core::CellIndex goal_cell;  // on the planner's coarse grid
  Eigen::Vector2d goal_world =
      Eigen::Vector2d::Zero();  // the goal (its cell's centre, or a frontier's centroid)
  double length_m = 0.0;        // from the robot's position along the waypoints
};

// An exploration planner, called by the run loop after each pirouette.
class Planner {
 public:
  virtual ~Planner() = default;

  // The next path from the robot's position to explore, or nothing when no
  // reachable unknown space is left (exploration complete). Throws
  // std::out_of_range when the robot is off the map.
  virtual std::optional<Plan> Next(const mapping::TrinaryMap& map,
                                   const core::Pose2& world_T_robot) = 0;

  // Tells the planner the last plan's goal could not be reached (e.g. the
  // look before a move found it blocked again and again): it is not chosen
  // again.
  virtual void ReportUnreachable(const Plan& plan) { static_cast<void>(plan); }
};

// The paper's planner (Taylor, Geva & Boles 2005, §4): configuration space,
// coarse grid, chamfer distance transform from every coarse cell that holds
// unknown space, steepest descent from the robot's cell. A goal is given up
// when it was reported unreachable, or when the last plan had the robot
// pirouette where it stood and the same goal comes out again (its cell keeps
// unknown space the robot does not see from there).
// Throws std::invalid_argument when the options are bad.
std::unique_ptr<Planner> MakeDistanceTransformPlanner(const PlannerOptions& options);

// The coarse planning grid of a map: its configuration space for the robot,
// classified in coarse cells of options.CoarseFactor.
CoarseGrid PlanningGrid(const mapping::TrinaryMap& map, const PlannerOptions& options);

// The plan that follows `path` on `grid` from the robot at `robot_world`:
// the centres of the path's cells, then that of its goal cell if
// `enter_goal` (a goal the robot drives into). The centre of the robot's own
// cell, when it comes first, is left out if it is the only one (the robot is
// already there) or if the straight leg from the robot to the next centre
// crosses only kFree cells. Does not set goal_world.
Plan PlanAlong(const CoarseGrid& grid, const Path& path, const Eigen::Vector2d& robot_world,
               bool enter_goal);

}  // namespace pirouette::explore
