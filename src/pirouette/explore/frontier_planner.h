#pragma once

#include <Eigen/Core>
#include <memory>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/explore/planner.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::explore {

// The options of explore_lite (J. Horner, m-explore, explore/src/explore.cpp
// and frontier_search.cpp), the frontier exploration most ROS users run.
struct FrontierOptions {
  double potential_scale = 3.0;  // weight of the distance to a frontier (per metre)
  double gain_scale = 1.0;       // weight of a frontier's size (per metre)
  // Frontiers smaller than this are dropped; 0: 3 robot radii (explore_lite's
  // 0.5 m is about 3 radii of a TurtleBot).
  double min_frontier_size_m = 0.0;
  // A goal within this many map cells (in x and in y) of a blacklisted one is
  // blacklisted too (explore_lite's tolerance).
  int blacklist_tolerance_cells = 5;

  // Throws std::invalid_argument unless the scales are finite and >= 0, the
  // size finite and >= 0 and the tolerance >= 0.
  void Check() const;
};

// One frontier: a group of 8-connected frontier cells, i.e. unknown map
// cells with a free 4-neighbour.
struct Frontier {
  std::vector<core::CellIndex> cells;                        // map cells
  Eigen::Vector2d centroid_world = Eigen::Vector2d::Zero();  // the mean of the cells' centres
  Eigen::Vector2d nearest_world = Eigen::Vector2d::Zero();   // the cell centre nearest the robot
  double distance_m = 0.0;  // straight from the robot to nearest_world
  double size_m = 0.0;      // cells × resolution
  // potential_scale · distance_m − gain_scale · size_m: the lower, the better.
  double cost = 0.0;
};

// explore_lite's frontier search: a breadth-first search over free map cells
// (4-connected) from the robot's cell (or the free cell nearest it, if it is
// not free) finds the frontier cells next to the free space the robot can
// reach; each new one grows into its frontier over 8-connected frontier
// cells. Frontiers under options.min_frontier_size_m are dropped (here 0
// keeps all); the rest come sorted by cost, lowest first. Empty when the robot is off the
// map. Unlike explore_lite, the centroid counts every cell and the distance is
// in metres (explore_lite scales it by the resolution once more).
std::vector<Frontier> FindFrontiers(const mapping::TrinaryMap& map,
                                    const Eigen::Vector2d& robot_world,
                                    const FrontierOptions& options);

// The baseline planner, explore_lite on pirouette's map, grid and loop: the
// goal is the centroid of the frontier of lowest cost, reached by the
// shortest path over the same coarse grid as the paper's planner (the
// chamfer distance transform from that one goal's coarse cell, the way
// move_base's global planner computes a potential from its goal). Where the
// centroid cannot be reached (its coarse cell blocked, no path, or
// blacklisted), the goal is the frontier's cell nearest the robot among
// those whose coarse cell is not blocked; where neither can be reached, the
// next frontier's. Goals reported unreachable are
// blacklisted (explore_lite's blacklist, with its tolerance), and so is a
// goal that comes out again after the robot pirouetted where its last plan
// left it (explore_lite's progress timeout). Plan::goal_world is the goal;
// the robot drives into its coarse cell when that is free and stops before
// it when it holds unknown space.
std::unique_ptr<Planner> MakeFrontierPlanner(const PlannerOptions& options,
                                             FrontierOptions frontier_options = {});

}  // namespace pirouette::explore
