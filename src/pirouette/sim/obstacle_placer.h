#pragma once

#include <Eigen/Core>
#include <optional>
#include <vector>

#include "pirouette/sim/world_spec.h"

namespace pirouette::sim {

// The direction of yaw k · 15°, k in [0, 24), from a table of the exact
// decimals rather than std::cos and std::sin (whose last bit the standard
// leaves to each library), so that placement decides the same everywhere.
Eigen::Vector2d YawDirection(int k);

// Lays obstacles on a floor so that every gap the robot might try is either
// closed or wide enough for it: each obstacle added keeps at least `gap`
// metres from every other obstacle, every wall and the floor's edges, except
// that one drawn against a wall may stand flush against walls and edges
// (touching, not overlapping). With gaps at least a robot's diameter, no
// pocket of floor is closed off (obstacles are convex); the world generator
// still checks every world with the evaluator's reachability.
//
// Obstacles must be convex: boxes (yaw a multiple of 15°), cylinders, walls
// and convex prisms. Pure geometry in doubles on +, −, ×, ÷ and √ only.
class ObstaclePlacer {
 public:
  explicit ObstaclePlacer(const Eigen::Vector2d& floor_size);

  // Adds a wall or other fixed obstacle whatever it touches; obstacles drawn
  // against a wall may stand flush against it.
  void AddWall(const ObstacleSpec& wall);
  // An area nothing may overlap (a doorway and the floor each side of it).
  void AddKeepOut(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi);

  // Adds `obstacle` when it lies on the floor, overlaps nothing, keeps `gap`
  // from every obstacle and keeps `gap` from every wall and floor edge it
  // does not touch (`against_wall`) or from all of them (otherwise); returns
  // whether it was added.
  bool TryAdd(const ObstacleSpec& obstacle, double gap, bool against_wall);

  // The distance from p to the nearest obstacle, wall or floor edge (0 off the floor or inside).
  double Clearance(const Eigen::Vector2d& p) const;

  // The obstacles in the order added, walls among them.
  const std::vector<ObstacleSpec>& obstacles() const { return obstacles_; }

 private:
  struct Footprint {
    std::vector<Eigen::Vector2d> polygon;   // convex, counter-clockwise (empty for a circle)
    std::optional<Eigen::Vector3d> circle;  // centre x, y and radius
    Eigen::Vector2d lo;                     // bounding box
    Eigen::Vector2d hi;
  };
  struct Placed {
    Footprint footprint;
    bool wall = false;
  };

  static Footprint FootprintOf(const ObstacleSpec& obstacle);
  static Footprint Rectangle(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi);
  // The distance between two footprints; negative where they overlap.
  static double Gap(const Footprint& a, const Footprint& b);
  // Whether the footprint lies on the floor and keeps `gap` from each floor
  // edge (or touches it, where `flush`).
  bool KeepsFromEdges(const Footprint& f, double gap, bool flush) const;

  Eigen::Vector2d floor_size_;
  std::vector<Placed> placed_;
  std::vector<Footprint> keep_out_;
  std::vector<ObstacleSpec> obstacles_;
};

}  // namespace pirouette::sim
