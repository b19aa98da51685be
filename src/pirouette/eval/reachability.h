#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/sim/world.h"

namespace pirouette::eval {

// The floor's cells on a grid with a margin of two cells around them (one
// would do but for rounding at a cell boundary), in the grid's cell indices
// (which may be negative or past the grid's size: the grid's lattice
// extended): [x0, x0 + width) × [y0, y0 + height). The outermost ring's
// centres lie off the floor, so every cell outside this window is truly
// occupied, and (the window being a rectangle whose border is all occupied)
// the nearest truly occupied cell of any cell inside it lies inside it.
struct TruthWindow {
  std::int64_t x0 = 0;
  std::int64_t y0 = 0;
  int width = 0;
  int height = 0;

  bool Contains(std::int64_t x, std::int64_t y) const {
    return x >= x0 && y >= y0 && x < x0 + width && y < y0 + height;
  }
  // Row-major over the window.
  std::size_t Flat(std::int64_t x, std::int64_t y) const {
    return static_cast<std::size_t>((y - y0) * width + (x - x0));
  }
};

// A world's ground truth on the cells of a grid's lattice (SPEC.md, "eval"),
// row-major over `window`:
//  - free: 255 where the cell's centre is truly free, 0 where it lies inside
//    a solid or off the floor (sim::World::IsOccupied), as
//    cv::distanceTransform takes it;
//  - fits: 1 where the robot's disc fits at the centre (sim::World::Clearance
//    greater than the robot's radius);
//  - reachable: 1 in R, the 4-connected flood fill over the cells that fit,
//    from the cell of the robot's start, or, where that cell's own centre
//    does not fit, from those of its 8 neighbours that do.
struct Reachability {
  TruthWindow window;
  std::vector<std::uint8_t> free;
  std::vector<std::uint8_t> fits;
  std::vector<std::uint8_t> reachable;

  // |R|.
  std::size_t ReachableCount() const;
  // The cells where the disc fits that R does not hold: floor the robot
  // could stand on but never drive to from its start (0 in a world where
  // every free cell is reachable).
  std::size_t UnreachableFitCount() const;
};

// The truth of `world` on `grid`'s cells (only its resolution and origin
// matter: the window covers the whole floor whatever the grid's size). The
// evaluator's (EvaluateMap) and the world generator's one definition of R.
// Relies on World::Clearance being the distance to the nearest occupied point
// (so 1-Lipschitz): a cell whose neighbour's clearance already decides it is
// not asked again, with the result asking would give; the cells asked ask a
// sim::ClearanceIndex (World::Clearance's values, from the nearby solids
// only). Throws
// std::invalid_argument when the floor spans more than 2^26 cells of the
// grid or lies too far from its origin.
Reachability ReachableCells(const sim::World& world, const core::GridGeometry& grid);

}  // namespace pirouette::eval
