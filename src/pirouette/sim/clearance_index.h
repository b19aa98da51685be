#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pirouette/sim/world.h"

namespace pirouette::sim {

// World::Clearance and World::IsOccupied, the very same doubles and answers,
// without asking every solid: the floor is cut into square buckets, each
// listing the solids that come within `reach_m` of it, and a point asks its
// bucket's solids; where none is within reach_m (open floor) it asks them
// all. For rasterising a world's truth over many cells (eval::ReachableCells)
// when the world has many solids (a maze's walls, a building's rooms).
// Relies on the world's occupied set being its solids() and what lies off
// its floor, as World::IsOccupied says. Holds a reference to `world`, which
// must outlive it. Throws std::invalid_argument unless reach_m > 0.
class ClearanceIndex {
 public:
  ClearanceIndex(const World& world, double reach_m);

  double Clearance(const Eigen::Vector2d& p) const;
  bool IsOccupied(const Eigen::Vector2d& p) const;

 private:
  // The bucket holding p, which lies on the floor.
  const std::vector<std::int32_t>& BucketOf(const Eigen::Vector2d& p) const;

  const World& world_;
  double reach_;
  double side_;  // a bucket's
  int columns_ = 0;
  int rows_ = 0;
  std::vector<std::vector<std::int32_t>> buckets_;  // solids' indices, in World::solids() order
};

}  // namespace pirouette::sim
