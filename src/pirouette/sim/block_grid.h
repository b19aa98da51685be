#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <optional>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/core/rgb.h"
#include "pirouette/sim/world.h"

namespace pirouette::sim {

// A map's cells stood up as blocks (SPEC.md, the `grid` obstacle): each cell
// of `geometry` (placed in the world's frame) either a solid square block or
// free floor. The value type between a map_server map and a world.
struct BlockGrid {
  core::GridGeometry geometry;
  std::vector<std::uint8_t> solid;  // 1 a block, 0 free; row-major as geometry.Flat

  bool IsSolid(const core::CellIndex& c) const { return solid[geometry.Flat(c)] != 0; }
  std::size_t SolidCount() const;
};

// The blocks as axis-aligned boxes (Solid::Kind::kGridBlock), `height` tall,
// of `colour`: each row's runs of blocks, a run extended upward while the row
// above holds the very same run. Their union is exactly the blocks' union,
// their corners exactly the cells' corners, in far fewer solids than cells
// (a wall a run, a room's unknown outside a few boxes), which keeps the
// renderer's mesh, the ray-cast truth and collisions fast. Throws
// std::invalid_argument unless solid.size() matches the geometry and height > 0.
std::vector<Solid> BlockGridSolids(const BlockGrid& grid, double height, core::Rgb colour);

// The clearance of each cell's centre from the blocks in metres, row-major:
// (D - 1/2)·resolution where D is the Euclidean distance in cells to the
// nearest block's centre (exact for a block beside or in line with the cell,
// at most 0.21 cells over for one diagonal to it), the distance to the
// grid's edge (which is occupied: the floor ends there) where that is less,
// 0 on a block. From OpenCV's exact Euclidean distance transform.
std::vector<double> CellClearance(const BlockGrid& grid);

// Where from-map starts the robot (SPEC.md, "Worlds nobody drew by hand"):
// among the cells whose clearance exceeds `radius`, the 4-connected region
// with the most cells, and in it the cell farthest from the blocks (the
// lowest row, then the lowest column, among equals); its centre. Nothing when
// the disc fits nowhere.
std::optional<Eigen::Vector2d> ChooseGridStart(const BlockGrid& grid, double radius);

// The grid with gaps narrower than the robot closed: every free cell that no
// robot disc (of `radius`) can cover, standing where it fits and can drive to
// from `start` (4-connected over the cells whose clearance exceeds radius),
// becomes a block. A gap in a wall narrower than the disc, where a laser saw
// through, and the free cells beyond it are sealed, so that the camera does
// not see through what the robot cannot pass and every free cell left is
// reachable; a room's corners lose the cells the disc cannot sweep. Specks
// (single blocks in the open) stay: they may be a chair's leg. Returns the
// grid unchanged when start's cell is off the grid or the disc does not fit
// near it (nothing is reachable: LoadWorldFile refuses such a start).
BlockGrid SealUnreachable(const BlockGrid& grid, double radius, const Eigen::Vector2d& start);

}  // namespace pirouette::sim
