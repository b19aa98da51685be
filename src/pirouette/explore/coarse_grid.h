#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::explore {

// What a coarse planning cell is for the distance transform.
enum class CoarseCell : std::uint8_t {
  kFree = 0,     // every map cell in it is free in configuration space: the robot may pass
  kGoal = 1,     // no map cell in it is blocked, some are unknown: space to explore
  kBlocked = 2,  // some map cell in it is blocked in configuration space
};

// The coarse planning grid of Taylor, Geva & Boles (2005, §4): each cell
// covers k × k map cells, so that a free coarse cell keeps the robot a margin
// from obstacles and a path over it needs fewer, longer moves. Row-major, row
// 0 the lowest y, like the map; its geometry has resolution k · the map's.
class CoarseGrid {
 public:
  // A grid of given cells (e.g. for benchmarks); throws std::invalid_argument
  // unless cells.size() == geometry.CellCount().
  CoarseGrid(core::GridGeometry geometry, std::vector<CoarseCell> cells);

  // Classifies the coarse cells of a configuration space (see
  // MakeConfigurationSpace): kBlocked if any of its map cells is kOccupied,
  // else kGoal if any is kUnknown, else kFree. The coarse cells lie on the
  // world's lattice of k map cells (cell (i, j) covers the map cells whose
  // index from the world origin, divided by k, is the coarse cell's from it),
  // so that they stay put when the map grows by whole cells; when the map's
  // origin is not on its own lattice they start at the map's origin. Coarse
  // cells at the map's edges may hang over it; only their map cells on the
  // map count. Throws std::invalid_argument unless factor >= 1.
  static CoarseGrid FromConfigurationSpace(const mapping::TrinaryMap& cspace, int factor);

  const core::GridGeometry& geometry() const { return geometry_; }
  int width() const { return geometry_.width(); }
  int height() const { return geometry_.height(); }
  const std::vector<CoarseCell>& cells() const { return cells_; }
  CoarseCell At(const core::CellIndex& c) const { return cells_[geometry_.Flat(c)]; }
  void Set(const core::CellIndex& c, CoarseCell value) { cells_[geometry_.Flat(c)] = value; }

 private:
  core::GridGeometry geometry_;
  std::vector<CoarseCell> cells_;
};

// The default coarse factor k (map cells a coarse cell's side) for a robot
// of `robot_radius_m` on a map of `resolution_m`: the most whole map cells in
// half the robot's radius, at least 1 (so 2 for a 4 cm robot on 1 cm cells,
// 3 for a 15 cm robot on 2 cm cells). A gap a robot passes with a clearance
// c left over (gap − diameter) stays open on the coarse grid, whatever its
// alignment, only if c ≥ about two coarse sides; the apartment's furniture
// stands 0.45 m apart for a 0.30 m robot (c = radius), so the coarse side
// is half a radius. coarse_grid_test.cc checks every shipped world.
// Throws std::invalid_argument unless both are finite and > 0.
int DefaultCoarseFactor(double robot_radius_m, double resolution_m);

}  // namespace pirouette::explore
