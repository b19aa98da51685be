#include "pirouette/eval/map_evaluation.h"

#include <array>
#include <cmath>
#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <vector>

namespace pirouette::eval {
namespace {

using mapping::CellState;

// The truth is rasterised over at most this many cells (7 bytes each).
constexpr std::int64_t kMaxTruthCells = std::int64_t{1} << 26;

// Distances between cell centres are square roots of whole numbers; the
// slack keeps exactly kFalseOccupiedCells from counting as farther.
constexpr double kDistanceSlackCells = 1e-3;

// The floor's cells on the map's grid with a margin of two cells around them
// (one would do but for rounding at a cell boundary), in the map's cell
// indices: [x0, x0 + width) × [y0, y0 + height). The outermost ring's centres
// lie off the floor, so every cell outside this window is truly
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
  std::size_t Flat(std::int64_t x, std::int64_t y) const {
    return static_cast<std::size_t>((y - y0) * width + (x - x0));
  }
};

std::int64_t CellIndexOf(double v, double origin, double resolution) {
  const double i = std::floor((v - origin) / resolution);
  if (!(std::fabs(i) < 1e15)) {
    throw std::invalid_argument("EvaluateMap: the map's grid lies too far from the world's floor");
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
    throw std::invalid_argument("EvaluateMap: the floor spans too many cells of the map's grid");
  }
  return {x0, y0, static_cast<int>(width), static_cast<int>(height)};
}

// The world on the window's cells: `free` 255 where the cell's centre is
// truly free, 0 where occupied (as cv::distanceTransform wants it), and
// `fits` 1 where the robot's disc fits (clearance greater than its radius).
struct TruthRaster {
  cv::Mat1b free;
  std::vector<std::uint8_t> fits;
};

TruthRaster RasteriseTruth(const core::GridGeometry& g, const TruthWindow& window,
                           const sim::World& world) {
  const double radius = world.robot().radius;
  TruthRaster truth{
      cv::Mat1b(window.height, window.width),
      std::vector<std::uint8_t>(static_cast<std::size_t>(window.width) * window.height, 0)};
  for (int b = 0; b < window.height; ++b) {
    for (int a = 0; a < window.width; ++a) {
      const Eigen::Vector2d c(
          g.origin().x() + (static_cast<double>(window.x0 + a) + 0.5) * g.resolution(),
          g.origin().y() + (static_cast<double>(window.y0 + b) + 0.5) * g.resolution());
      // A positive clearance means free; only at zero is IsOccupied needed.
      const double clearance = world.Clearance(c);
      const bool occupied = clearance > 0.0 ? false : world.IsOccupied(c);
      truth.free(b, a) = occupied ? 0 : 255;
      truth.fits[window.Flat(window.x0 + a, window.y0 + b)] = clearance > radius ? 1 : 0;
    }
  }
  return truth;
}

// R: the 4-connected flood fill over the cells where the disc fits, from the
// cell of the robot's start, or where that cell's own centre does not clear,
// from those of its 8 neighbours that do; 1 where reachable.
std::vector<std::uint8_t> Reachable(const core::GridGeometry& g, const TruthWindow& window,
                                    const std::vector<std::uint8_t>& fits,
                                    const Eigen::Vector2d& start) {
  std::vector<std::uint8_t> reachable(fits.size(), 0);
  std::vector<std::size_t> frontier;
  const std::int64_t sx = CellIndexOf(start.x(), g.origin().x(), g.resolution());
  const std::int64_t sy = CellIndexOf(start.y(), g.origin().y(), g.resolution());
  const auto seed = [&](std::int64_t x, std::int64_t y) {
    if (!window.Contains(x, y)) return;
    const std::size_t i = window.Flat(x, y);
    if (fits[i] == 0 || reachable[i] != 0) return;
    reachable[i] = 1;
    frontier.push_back(i);
  };
  seed(sx, sy);
  if (frontier.empty()) {
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) seed(sx + dx, sy + dy);
    }
  }
  constexpr std::array<std::array<int, 2>, 4> kSteps = {{{1, 0}, {-1, 0}, {0, 1}, {0, -1}}};
  while (!frontier.empty()) {
    const std::size_t i = frontier.back();
    frontier.pop_back();
    const auto width = static_cast<std::size_t>(window.width);
    const std::int64_t x = window.x0 + static_cast<std::int64_t>(i % width);
    const std::int64_t y = window.y0 + static_cast<std::int64_t>(i / width);
    for (const auto& [dx, dy] : kSteps) seed(x + dx, y + dy);
  }
  return reachable;
}

// The map's cells counted and judged against the truth.
MapEvaluation Judge(const mapping::TrinaryMap& map, const TruthWindow& window,
                    const cv::Mat1b& truth_free, const cv::Mat1f& distance_cells,
                    const std::vector<std::uint8_t>& reachable) {
  const core::GridGeometry& g = map.geometry;
  MapEvaluation e;
  for (const std::uint8_t r : reachable) e.reachable += r;
  std::size_t covered = 0;
  std::size_t false_free = 0;
  std::size_t false_occupied = 0;
  double distance_sum_cells = 0.0;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const bool inside = window.Contains(x, y);
      const int a = static_cast<int>(x - window.x0);
      const int b = static_cast<int>(y - window.y0);
      switch (map.At({x, y})) {
        case CellState::kFree:
          ++e.free;
          if (!inside || truth_free(b, a) == 0) ++false_free;
          if (inside && reachable[window.Flat(x, y)] != 0) ++covered;
          break;
        case CellState::kOccupied: {
          ++e.occupied;
          const double d = inside ? static_cast<double>(distance_cells(b, a)) : 0.0;
          distance_sum_cells += d;
          if (d > kFalseOccupiedCells + kDistanceSlackCells) ++false_occupied;
          break;
        }
        case CellState::kUnknown:
          ++e.unknown;
          break;
      }
    }
  }
  const auto fraction = [](std::size_t part, std::size_t whole) {
    return whole == 0 ? 0.0 : static_cast<double>(part) / static_cast<double>(whole);
  };
  e.coverage = fraction(covered, e.reachable);
  e.false_free = fraction(false_free, e.free);
  e.false_occupied = fraction(false_occupied, e.occupied);
  e.wall_error_m =
      e.occupied == 0 ? 0.0 : distance_sum_cells * g.resolution() / static_cast<double>(e.occupied);
  return e;
}

}  // namespace

MapEvaluation EvaluateMap(const mapping::TrinaryMap& map, const sim::World& world) {
  const core::GridGeometry& g = map.geometry;
  if (map.cells.size() != g.CellCount()) {
    throw std::invalid_argument("EvaluateMap: the map's cells do not match its geometry");
  }
  const TruthWindow window = FloorWindow(g, world.floor().size);
  const TruthRaster truth = RasteriseTruth(g, window, world);
  cv::Mat1f distance_cells;
  cv::distanceTransform(truth.free, distance_cells, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  const std::vector<std::uint8_t> reachable =
      Reachable(g, window, truth.fits, world.robot().start.translation());
  return Judge(map, window, truth.free, distance_cells, reachable);
}

nlohmann::json MapEvaluationToJson(const MapEvaluation& evaluation) {
  return {
      {"coverage", evaluation.coverage},
      {"false_free", evaluation.false_free},
      {"false_occupied", evaluation.false_occupied},
      {"wall_error_m", evaluation.wall_error_m},
      {"cells",
       {{"free", evaluation.free},
        {"occupied", evaluation.occupied},
        {"unknown", evaluation.unknown}}},
      {"reachable_cells", evaluation.reachable},
  };
}

std::string MapEvaluationJson(const MapEvaluation& evaluation) {
  return MapEvaluationToJson(evaluation).dump(2) + "\n";
}

}  // namespace pirouette::eval
