#include "pirouette/mapping/trinary_map.h"

#include <cstddef>

#include "pirouette/core/geometry2.h"

namespace pirouette::mapping {
namespace {

// The 4-connected unknown group of `seed`, as flat indices, each cell marked
// in `seen`.
std::vector<std::size_t> UnknownGroup(const TrinaryMap& map, const core::CellIndex& seed,
                                      std::vector<bool>& seen) {
  const core::GridGeometry& g = map.geometry;
  std::vector<std::size_t> group{g.Flat(seed)};
  seen[group.front()] = true;
  for (std::size_t next = 0; next < group.size(); ++next) {
    const core::CellIndex c = g.Unflat(group[next]);
    const core::CellIndex around[4] = {
        {c.x + 1, c.y}, {c.x - 1, c.y}, {c.x, c.y + 1}, {c.x, c.y - 1}};
    for (const core::CellIndex& n : around) {
      if (!g.Contains(n)) continue;
      const std::size_t i = g.Flat(n);
      if (seen[i] || map.cells[i] != CellState::kUnknown) continue;
      seen[i] = true;
      group.push_back(i);
    }
  }
  return group;
}

// Whether an occupied cell is among the 8 neighbours of any cell of `group`.
bool BesideAnObstacle(const TrinaryMap& map, const std::vector<std::size_t>& group) {
  const core::GridGeometry& g = map.geometry;
  for (const std::size_t i : group) {
    const core::CellIndex c = g.Unflat(i);
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const core::CellIndex n{c.x + dx, c.y + dy};
        if (g.Contains(n) && map.At(n) == CellState::kOccupied) return true;
      }
    }
  }
  return false;
}

}  // namespace

bool DiscKnownFree(const TrinaryMap& map, const Eigen::Vector2d& p_m, double radius_m) {
  const core::GridGeometry& g = map.geometry;
  const core::CellIndex lo = g.CellOf(p_m - Eigen::Vector2d(radius_m, radius_m));
  const core::CellIndex hi = g.CellOf(p_m + Eigen::Vector2d(radius_m, radius_m));
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      const core::CellIndex c{x, y};
      if ((g.CellCentre(c) - p_m).norm() > radius_m) continue;
      if (!g.Contains(c) || map.At(c) != CellState::kFree) return false;
    }
  }
  return true;
}

bool CorridorKnownFree(const TrinaryMap& map, const Eigen::Vector2d& from,
                       const Eigen::Vector2d& to, double radius_m) {
  const core::GridGeometry& g = map.geometry;
  return !core::AnyCellNearSegment(
      g, from, to, radius_m + 0.5 * g.resolution(),
      [&](const core::CellIndex& c) { return !g.Contains(c) || map.At(c) != CellState::kFree; });
}

TrinaryMap FillPinholes(const TrinaryMap& map, int max_cells) {
  const core::GridGeometry& g = map.geometry;
  TrinaryMap out = map;
  std::vector<bool> seen(map.cells.size(), false);
  for (std::size_t i = 0; i < map.cells.size(); ++i) {
    if (seen[i] || map.cells[i] != CellState::kUnknown) continue;
    const std::vector<std::size_t> group = UnknownGroup(map, g.Unflat(i), seen);
    if (static_cast<int>(group.size()) > max_cells || BesideAnObstacle(map, group)) continue;
    for (const std::size_t c : group) out.cells[c] = CellState::kFree;
  }
  return out;
}

}  // namespace pirouette::mapping
