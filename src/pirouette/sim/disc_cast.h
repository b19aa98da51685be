#pragma once

#include <Eigen/Core>
#include <limits>

#include "pirouette/sim/world.h"

namespace pirouette::sim {

// How far the disc may overlap something before a move counts as blocked.
// The robot then stops where it first touched (overlap 0), so a robot in
// contact lies this far outside the blocking set: it can drive away from the
// contact or along it, without rounding errors deciding.
inline constexpr double kOverlapTolerance = 1e-9;

// The result of a disc cast (CastDisc): where a straight move is blocked,
// and where it stops.
struct ContactResult {
  // Where the disc first touches (overlap 0) the blocking piece.
  double touch = std::numeric_limits<double>::infinity();
  // Where the overlap first exceeds kOverlapTolerance.
  double blocked = std::numeric_limits<double>::infinity();
};

// Where a disc of `radius` at `origin` driving along u (unit) first overlaps
// an obstacle, a wall or the floor's outside by more than kOverlapTolerance,
// and where it touched it first. Exact for polygons, circles and the floor.
ContactResult CastDisc(const World& world, const Eigen::Vector2d& origin, const Eigen::Vector2d& u,
                       double radius);

}  // namespace pirouette::sim
