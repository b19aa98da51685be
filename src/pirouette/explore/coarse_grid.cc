#include "pirouette/explore/coarse_grid.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <utility>

namespace pirouette::explore {

CoarseGrid::CoarseGrid(core::GridGeometry geometry, std::vector<CoarseCell> cells)
    : geometry_(std::move(geometry)), cells_(std::move(cells)) {
  if (cells_.size() != geometry_.CellCount()) {
    throw std::invalid_argument("CoarseGrid: one cell per cell of the geometry");
  }
}

namespace {

// The map cells by which the coarse lattice starts before the map: the
// remainder of the map origin's cell index (from the world origin) modulo
// k, when the origin lies on the map's lattice; else 0.
int Shift(double origin, double resolution, int factor) {
  const double cells = origin / resolution;
  const double whole = std::round(cells);
  if (std::abs(cells - whole) > 1e-6 || std::abs(whole) > 1e9) return 0;
  const auto k = static_cast<long long>(factor);
  return static_cast<int>(((static_cast<long long>(whole) % k) + k) % k);
}

}  // namespace

CoarseGrid CoarseGrid::FromConfigurationSpace(const mapping::TrinaryMap& cspace, int factor) {
  if (factor < 1) throw std::invalid_argument("CoarseGrid: the coarse factor must be >= 1");
  const core::GridGeometry& g = cspace.geometry;
  const int sx = Shift(g.origin().x(), g.resolution(), factor);
  const int sy = Shift(g.origin().y(), g.resolution(), factor);
  const int w = (g.width() + sx + factor - 1) / factor;
  const int h = (g.height() + sy + factor - 1) / factor;
  // Per coarse cell, the OR of 1 << state over its map cells.
  std::vector<std::uint8_t> seen(static_cast<std::size_t>(w) * h, 0);
  for (int y = 0; y < g.height(); ++y) {
    const std::size_t coarse_row = static_cast<std::size_t>((y + sy) / factor) * w;
    const std::size_t map_row = static_cast<std::size_t>(y) * g.width();
    for (int x = 0; x < g.width(); ++x) {
      seen[coarse_row + (x + sx) / factor] |=
          static_cast<std::uint8_t>(1U << static_cast<unsigned>(cspace.cells[map_row + x]));
    }
  }
  constexpr std::uint8_t kUnknownBit = 1U << static_cast<unsigned>(mapping::CellState::kUnknown);
  constexpr std::uint8_t kOccupiedBit = 1U << static_cast<unsigned>(mapping::CellState::kOccupied);
  std::vector<CoarseCell> cells(seen.size());
  std::transform(seen.begin(), seen.end(), cells.begin(), [](std::uint8_t s) {
    if ((s & kOccupiedBit) != 0) return CoarseCell::kBlocked;
    if ((s & kUnknownBit) != 0) return CoarseCell::kGoal;
    return CoarseCell::kFree;
  });
  const Eigen::Vector2d origin = g.origin() - g.resolution() * Eigen::Vector2d(sx, sy);
  return {core::GridGeometry(g.resolution() * factor, origin, w, h), std::move(cells)};
}

int DefaultCoarseFactor(double robot_radius_m, double resolution_m) {
  if (!std::isfinite(robot_radius_m) || !(robot_radius_m > 0.0) || !std::isfinite(resolution_m) ||
      !(resolution_m > 0.0)) {
    throw std::invalid_argument("DefaultCoarseFactor: radius and resolution must be positive");
  }
  const double k = std::floor(0.5 * robot_radius_m / resolution_m + 1e-9);
  return std::max(1, static_cast<int>(std::min(k, 1e6)));
}

}  // namespace pirouette::explore
