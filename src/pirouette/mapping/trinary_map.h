#pragma once

#include <Eigen/Core>
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

// Whether a disc of `radius_m` at `p_m` covers only free cells: every cell
// whose centre lies within radius_m of p_m is on the map and kFree.
bool DiscKnownFree(const TrinaryMap& map, const Eigen::Vector2d& p_m, double radius_m);

// Whether every cell whose centre lies within radius_m plus half a cell of the
// segment from -> to is on the map and kFree: the corridor a disc of radius_m
// sweeps driving from -> to, with the cells its rim touches.
bool CorridorKnownFree(const TrinaryMap& map, const Eigen::Vector2d& from,
                       const Eigen::Vector2d& to, double radius_m);

// The map with its pinholes filled: every 4-connected group of at most
// `max_cells` unknown cells with no occupied cell among its cells' 8
// neighbours (floor seen free all round whose own evidence never crossed the
// map's thresholds) becomes free. Larger unknown areas, and unknown cells
// beside an obstacle, are kept. Cells off the map count as not occupied.
TrinaryMap FillPinholes(const TrinaryMap& map, int max_cells);

}  // namespace pirouette::mapping
