#include "pirouette/sim/block_grid.h"

#include <algorithm>
#include <cstddef>
#include <map>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>
#include <stdexcept>
#include <utility>

namespace pirouette::sim {
namespace {

void CheckCells(const BlockGrid& grid) {
  if (grid.solid.size() != grid.geometry.CellCount()) {
    throw std::invalid_argument("BlockGrid: the cells do not match the geometry");
  }
}

// The box over cells [x0, x1) × [y0, y1), its corners the cells' corners.
Solid Box(const core::GridGeometry& g, int x0, int x1, int y0, int y1, double height,
          core::Rgb colour) {
  const double r = g.resolution();
  const Eigen::Vector2d lo = g.origin() + Eigen::Vector2d(x0 * r, y0 * r);
  const Eigen::Vector2d hi = g.origin() + Eigen::Vector2d(x1 * r, y1 * r);
  Solid solid;
  solid.kind = Solid::Kind::kGridBlock;
  solid.footprint = {lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}};  // counter-clockwise
  solid.height = height;
  solid.colour = colour;
  return solid;
}

// An 8-bit picture of the grid, one pixel a cell, row r the grid's row r,
// with a border of `border` pixels all 0: 255 where `keep` holds, else 0.
template <typename Keep>
cv::Mat Picture(const BlockGrid& grid, int border, Keep keep) {
  const core::GridGeometry& g = grid.geometry;
  cv::Mat picture(g.height() + 2 * border, g.width() + 2 * border, CV_8U, cv::Scalar(0));
  for (int y = 0; y < g.height(); ++y) {
    auto* row = picture.ptr<std::uint8_t>(y + border);
    for (int x = 0; x < g.width(); ++x) row[x + border] = keep(g.Flat({x, y})) ? 255 : 0;
  }
  return picture;
}

}  // namespace

std::size_t BlockGrid::SolidCount() const {
  return static_cast<std::size_t>(std::count(solid.begin(), solid.end(), std::uint8_t{1}));
}

std::vector<Solid> BlockGridSolids(const BlockGrid& grid, double height, core::Rgb colour) {
  CheckCells(grid);
  if (!(height > 0.0)) throw std::invalid_argument("BlockGridSolids: height must be > 0");
  const core::GridGeometry& g = grid.geometry;
  std::vector<Solid> solids;
  // The open boxes: a run [x0, x1) → the row it began in.
  std::map<std::pair<int, int>, int> open;
  std::map<std::pair<int, int>, int> next;
  for (int y = 0; y <= g.height(); ++y) {
    next.clear();
    if (y < g.height()) {
      for (int x = 0; x < g.width();) {
        if (!grid.IsSolid({x, y})) {
          ++x;
          continue;
        }
        const int x0 = x;
        while (x < g.width() && grid.IsSolid({x, y})) ++x;
        const auto run = std::make_pair(x0, x);
        const auto it = open.find(run);
        next[run] = it == open.end() ? y : it->second;
      }
    }
    for (const auto& [run, y0] : open) {
      if (next.count(run) == 0) {
        solids.push_back(Box(g, run.first, run.second, y0, y, height, colour));
      }
    }
    std::swap(open, next);
  }
  return solids;
}

std::vector<double> CellClearance(const BlockGrid& grid) {
  CheckCells(grid);
  const core::GridGeometry& g = grid.geometry;
  // The border of blocks stands for the floor's edge: its centres lie half a
  // cell outside the grid, so (D - 1/2) is the distance to the edge.
  const cv::Mat free = Picture(grid, 1, [&](std::size_t i) { return grid.solid[i] == 0; });
  cv::Mat distance;
  cv::distanceTransform(free, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  std::vector<double> clearance(g.CellCount(), 0.0);
  for (int y = 0; y < g.height(); ++y) {
    const float* row = distance.ptr<float>(y + 1);
    for (int x = 0; x < g.width(); ++x) {
      const double d = row[x + 1];
      clearance[g.Flat({x, y})] = d > 0.0 ? (d - 0.5) * g.resolution() : 0.0;
    }
  }
  return clearance;
}

std::optional<Eigen::Vector2d> ChooseGridStart(const BlockGrid& grid, double radius) {
  const core::GridGeometry& g = grid.geometry;
  const std::vector<double> clearance = CellClearance(grid);
  const cv::Mat fits = Picture(grid, 0, [&](std::size_t i) { return clearance[i] > radius; });
  cv::Mat labels;
  cv::Mat stats;
  cv::Mat centroids;
  const int count = cv::connectedComponentsWithStats(fits, labels, stats, centroids, 4, CV_32S);
  int best_label = 0;
  for (int label = 1; label < count; ++label) {
    if (best_label == 0 ||
        stats.at<int>(label, cv::CC_STAT_AREA) > stats.at<int>(best_label, cv::CC_STAT_AREA)) {
      best_label = label;
    }
  }
  if (best_label == 0) return std::nullopt;
  std::optional<core::CellIndex> best;
  double best_clearance = 0.0;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (labels.at<int>(y, x) != best_label) continue;
      const double c = clearance[g.Flat({x, y})];
      if (!best || c > best_clearance) {
        best = core::CellIndex{x, y};
        best_clearance = c;
      }
    }
  }
  return g.CellCentre(*best);
}

BlockGrid SealUnreachable(const BlockGrid& grid, double radius, const Eigen::Vector2d& start) {
  const core::GridGeometry& g = grid.geometry;
  const std::vector<double> clearance = CellClearance(grid);
  cv::Mat fits = Picture(grid, 0, [&](std::size_t i) { return clearance[i] > radius; });
  // The seed: start's cell, or where its centre does not fit, the first of
  // its 8 neighbours that does (as eval::ReachableCells seeds R).
  const core::CellIndex s = g.CellOf(start);
  const auto fits_at = [&](const core::CellIndex& c) {
    return g.Contains(c) && fits.at<std::uint8_t>(c.y, c.x) != 0;
  };
  std::optional<core::CellIndex> seed;
  if (fits_at(s)) seed = s;
  for (int dy = -1; dy <= 1 && !seed; ++dy) {
    for (int dx = -1; dx <= 1 && !seed; ++dx) {
      if (fits_at({s.x + dx, s.y + dy})) seed = core::CellIndex{s.x + dx, s.y + dy};
    }
  }
  if (!seed) return grid;
  cv::floodFill(fits, cv::Point(seed->x, seed->y), cv::Scalar(128), nullptr, cv::Scalar(0),
                cv::Scalar(0), 4);
  // Distance (in cells) to the nearest reachable centre: 0 on one.
  cv::Mat not_reachable;
  cv::compare(fits, cv::Scalar(128), not_reachable, cv::CMP_NE);
  cv::Mat distance;
  cv::distanceTransform(not_reachable, distance, cv::DIST_L2, cv::DIST_MASK_PRECISE, CV_32F);
  BlockGrid sealed = grid;
  const double reach_cells = radius / g.resolution();
  for (int y = 0; y < g.height(); ++y) {
    const float* row = distance.ptr<float>(y);
    for (int x = 0; x < g.width(); ++x) {
      const std::size_t i = g.Flat({x, y});
      if (sealed.solid[i] == 0 && row[x] > reach_cells) sealed.solid[i] = 1;
    }
  }
  return sealed;
}

}  // namespace pirouette::sim
