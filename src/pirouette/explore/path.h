#pragma once

#include <optional>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/explore/coarse_grid.h"
#include "pirouette/explore/distance_transform.h"

namespace pirouette::explore {

// A path on the coarse grid, down a distance field to a goal.
struct Path {
  // The cells the robot drives through, in order: its start cell (or the
  // free neighbour it starts from), each an 8-neighbour of the one before,
  // to the last cell before the goal. Empty when the start cell is the goal.
  std::vector<core::CellIndex> cells;
  core::CellIndex goal;  // the cell the descent ends in (distance 0)
};

// Steepest descent on `field` (a converged ChamferDistanceTransform of
// `grid`) from `start` (Taylor, Geva & Boles 2005, §4): each step goes to
// the 8-neighbour of smallest distance, so the distance falls at every step
// and the path is a shortest one (in chamfer length). Ties go to an
// orthogonal step (which, with 3-4 weights, is the one on a shortest path),
// then to the direction of the previous step (fewer turns), then to the
// first in a fixed order. If `start` is blocked or no goal is reachable from
// it, the descent starts from its reachable free 8-neighbour of smallest
// distance. Returns nothing when there is none; throws std::out_of_range
// when `start` is off the grid.
std::optional<Path> SteepestDescent(const CoarseGrid& grid, const DistanceField& field,
                                    const core::CellIndex& start);

}  // namespace pirouette::explore
