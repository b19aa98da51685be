#include "pirouette/eval/reachability.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <stdexcept>

#include "pirouette/sim/clearance_index.h"

namespace pirouette::eval {
namespace {

// The truth is rasterised over at most this many cells (3 bytes each).
constexpr std::int64_t kMaxTruthCells = std::int64_t{1} << 26;

// A cell whose clearance exceeds the robot's radius by more than this many
// metres plus k cells decides the k cells after it on its row (see
// RasteriseRow). Far above the rounding of a clearance or of a cell's
// centre (~1e-16 m on a floor of metres), far below any cell.
constexpr double kLipschitzSlackM = 1e-9;

// The clearance index answers from its buckets up to the radius plus this
// many cells, and asks every solid beyond (where a cell then decides at
// least as many cells after it): longer bucket lists against more cells that
// ask every solid.
constexpr double kIndexReachCells = 8.0;

std::int64_t CellIndexOf(double v, double origin, double resolution) {
  const double i = std::floor((v - origin) / resolution);
  if (!(std::fabs(i) < 1e15)) {
    throw std::invalid_argument("ReachableCells: the grid lies too far from the world's floor");
  }
  return static_cast<std::int64_t>(i);
}

TruthWindow FloorWindow(const core::GridGeometry& g, const Eigen::Vector2d& floor_size) {
  const double r = g.resolution();
  constexpr std::int64_t kMargin = 2;
  const std::int64_t x0 = CellIndexOf(0.0, g.origin().x(), r) - kMargin;
  const std::int64_t y0 = CellIndexOf(0.0, g.origin().y(), r) - kMargin;
  const std::int64_t x1 = CellIndexOf(floor_size.x(), g.origin().x(), r) + kMargin;
  const std::int64_t y1 = CellIndexOf(floor_size.y(), g.origin().y(), r) + kMargin;
  const std::int64_t width = x1 - x0 + 1;
  const std::int64_t height = y1 - y0 + 1;
  if (width * height > kMaxTruthCells) {
    throw std::invalid_argument("ReachableCells: the floor spans too many cells of the grid");
  }
  return {x0, y0, static_cast<int>(width), static_cast<int>(height)};
}

// Row b of the window's `free` and `fits`. Each cell asked gives its
// clearance d; World::Clearance being 1-Lipschitz, a cell k cells further
// along the row has clearance >= d - k·resolution, so where that exceeds the
// radius (with kLipschitzSlackM to spare for rounding) the cell fits and is
// free without asking: what asking would have given.
void RasteriseRow(const core::GridGeometry& g, const sim::World& world,
                  const sim::ClearanceIndex& index, int b, Reachability& truth) {
  const TruthWindow& window = truth.window;
  const double radius = world.robot().radius;
  const double y = g.origin().y() + (static_cast<double>(window.y0 + b) + 0.5) * g.resolution();
  const std::size_t row = static_cast<std::size_t>(b) * static_cast<std::size_t>(window.width);
  for (int a = 0; a < window.width;) {
    const Eigen::Vector2d c(
        g.origin().x() + (static_cast<double>(window.x0 + a) + 0.5) * g.resolution(), y);
    // A clearance over sim::kOnFaceM means free; only below is IsOccupied
    // needed (a face's point is in its solid).
    const double clearance = index.Clearance(c);
    const bool occupied = clearance > sim::kOnFaceM ? false : index.IsOccupied(c);
    truth.free[row + a] = occupied ? 0 : 255;
    truth.fits[row + a] = clearance > radius ? 1 : 0;
    const double spare_cells = (clearance - radius - kLipschitzSlackM) / g.resolution();
    const int decided =
        spare_cells >= 1.0
            ? static_cast<int>(std::min<double>(std::floor(spare_cells), window.width - a - 1))
            : 0;
    for (int k = 1; k <= decided; ++k) {
      truth.free[row + a + k] = 255;
      truth.fits[row + a + k] = 1;
    }
    a += decided + 1;
  }
}

// R over `fits`, from the cell of `start` (or its 8 neighbours that fit).
void FloodFill(const core::GridGeometry& g, const Eigen::Vector2d& start, Reachability& truth) {
  const TruthWindow& window = truth.window;
  std::vector<std::size_t> frontier;
  const std::int64_t sx = CellIndexOf(start.x(), g.origin().x(), g.resolution());
  const std::int64_t sy = CellIndexOf(start.y(), g.origin().y(), g.resolution());
  const auto seed = [&](std::int64_t x, std::int64_t y) {
    if (!window.Contains(x, y)) return;
    const std::size_t i = window.Flat(x, y);
    if (truth.fits[i] == 0 || truth.reachable[i] != 0) return;
    truth.reachable[i] = 1;
    frontier.push_back(i);
  };
  seed(sx, sy);
  if (frontier.empty()) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) seed(sx + dx, sy + dy);
    }
  }
  constexpr std::array<std::array<int, 2>, 4> kSteps = {{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
  const auto width = static_cast<std::size_t>(window.width);
  while (!frontier.empty()) {
    const std::size_t i = frontier.back();
    frontier.pop_back();
    const std::int64_t x = window.x0 + static_cast<std::int64_t>(i % width);
    const std::int64_t y = window.y0 + static_cast<std::int64_t>(i / width);
    for (const auto& [dx, dy] : kSteps) seed(x + dx, y + dy);
  }
}

}  // namespace

std::size_t Reachability::ReachableCount() const {
  std::size_t count = 0;
  for (const std::uint8_t r : reachable) count += r;
  return count;
}

std::size_t Reachability::UnreachableFitCount() const {
  std::size_t count = 0;
  for (std::size_t i = 0; i < fits.size(); ++i) count += fits[i] != 0 && reachable[i] == 0;
  return count;
}

Reachability ReachableCells(const sim::World& world, const core::GridGeometry& grid) {
  Reachability truth;
  truth.window = FloorWindow(grid, world.floor().size);
  const std::size_t cells =
      static_cast<std::size_t>(truth.window.width) * static_cast<std::size_t>(truth.window.height);
  truth.free.assign(cells, 0);
  truth.fits.assign(cells, 0);
  truth.reachable.assign(cells, 0);
  const sim::ClearanceIndex index(world,
                                  world.robot().radius + kIndexReachCells * grid.resolution());
  for (int b = 0; b < truth.window.height; ++b) RasteriseRow(grid, world, index, b, truth);
  FloodFill(grid, world.robot().start.translation(), truth);
  return truth;
}

}  // namespace pirouette::eval
