#pragma once

#include <cstdint>
#include <vector>

#include "pirouette/core/grid_geometry.h"

namespace pirouette::mapping {

// What a map says about one cell, as ROS's map_server reads it (trinary mode).
enum class CellState : std::uint8_t { kUnknown = 0, kFree = 1, kOccupied = 2 };

// A thresholded map: one state per cell of `geometry`, row-major, row 0 the
// lowest y. What is written to map.pgm and what `eval` judges.
struct TrinaryMap {
  core::GridGeometry geometry;
  std::vector<CellState> cells;  // geometry.CellCount() of them

  CellState At(const core::CellIndex& c) const { return cells[geometry.Flat(c)]; }
};

}  // namespace pirouette::mapping
