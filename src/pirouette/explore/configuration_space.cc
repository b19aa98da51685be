#include "pirouette/explore/configuration_space.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdlib>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

namespace pirouette::explore {
namespace {

using mapping::CellState;

struct Offset {
  int dx;
  int dy;
};

// The cell offsets whose centres lie nearer than `radius_cells` to some
// point of the origin's cell, a unit square: the distance from a centre
// (dx, dy) to the square is |(max(|dx| - 1/2, 0), max(|dy| - 1/2, 0))|.
std::vector<Offset> DiscOffsets(double radius_cells) {
  const auto gap = [](int d) { return std::max(std::abs(d) - 0.5, 0.0); };
  const double r2 = radius_cells * radius_cells;
  const int reach = static_cast<int>(std::ceil(radius_cells + 0.5));
  std::vector<Offset> offsets;
  for (int dy = -reach; dy <= reach; ++dy) {
    for (int dx = -reach; dx <= reach; ++dx) {
      if (gap(dx) * gap(dx) + gap(dy) * gap(dy) < r2) offsets.push_back({dx, dy});
    }
  }
  return offsets;
}

void CheckRadius(double robot_radius_m, const char* what) {
  if (!std::isfinite(robot_radius_m) || robot_radius_m < 0.0) {
    throw std::invalid_argument(std::string(what) + ": the robot radius must be finite and >= 0");
  }
}

}  // namespace

mapping::TrinaryMap MakeConfigurationSpace(const mapping::TrinaryMap& map, double robot_radius_m) {
  CheckRadius(robot_radius_m, "MakeConfigurationSpace");
  const core::GridGeometry& g = map.geometry;
  const int w = g.width();
  const int h = g.height();
  mapping::TrinaryMap cspace = map;
  const auto occupied = [&](int x, int y) {
    return x >= 0 && y >= 0 && x < w && y < h &&
           map.cells[static_cast<std::size_t>(y) * w + x] == CellState::kOccupied;
  };
  const std::vector<Offset> disc = DiscOffsets(robot_radius_m / g.resolution());
  // The occupied cell nearest any cell outside an obstacle has a 4-neighbour
  // that is not occupied (else a neighbour towards that cell would be nearer),
  // so stamping the discs of those boundary cells alone is exact.
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      if (!occupied(x, y)) continue;
      if (occupied(x - 1, y) && occupied(x + 1, y) && occupied(x, y - 1) && occupied(x, y + 1)) {
        continue;
      }
      for (const Offset& o : disc) {
        const int cx = x + o.dx;
        const int cy = y + o.dy;
        if (cx < 0 || cy < 0 || cx >= w || cy >= h) continue;
        cspace.cells[static_cast<std::size_t>(cy) * w + cx] = CellState::kOccupied;
      }
    }
  }
  return cspace;
}

int ClearFootprint(mapping::TrinaryMap& map, const Eigen::Vector2d& robot_world,
                   double robot_radius_m) {
  CheckRadius(robot_radius_m, "ClearFootprint");
  const core::GridGeometry& g = map.geometry;
  const std::optional<core::CellIndex> here = g.CellAt(robot_world);
  if (!here) return 0;
  int freed = 0;
  // The cells whose squares lie within the radius of this cell's centre are
  // those into which this one's would grow: the same offsets.
  for (const Offset& o : DiscOffsets(robot_radius_m / g.resolution())) {
    const core::CellIndex c{here->x + o.dx, here->y + o.dy};
    if (!g.Contains(c)) continue;
    CellState& state = map.cells[g.Flat(c)];
    if (state != CellState::kOccupied) continue;
    state = CellState::kFree;
    ++freed;
  }
  return freed;
}

}  // namespace pirouette::explore
