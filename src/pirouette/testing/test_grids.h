#pragma once

// Grids for the explore tests: pictures, random obstacles, mazes, spirals,
// and a Dijkstra reference for the distance transform.

#include <cstdint>
#include <functional>
#include <queue>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "pirouette/explore/coarse_grid.h"
#include "pirouette/explore/distance_transform.h"
#include "pirouette/explore/planner.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::testing {

// A grid from a picture: '#' blocked, '.' free, 'G' goal; the first line is
// the top row (largest y), like a map image.
inline explore::CoarseGrid Picture(const std::vector<std::string>& lines) {
  const int h = static_cast<int>(lines.size());
  const int w = static_cast<int>(lines.front().size());
  std::vector<explore::CoarseCell> cells(static_cast<std::size_t>(w) * h);
  for (int y = 0; y < h; ++y) {
    const std::string& line = lines[static_cast<std::size_t>(h - 1 - y)];
    for (int x = 0; x < w; ++x) {
      const char ch = line[static_cast<std::size_t>(x)];
      cells[static_cast<std::size_t>(y) * w + x] = ch == '#'   ? explore::CoarseCell::kBlocked
                                                   : ch == 'G' ? explore::CoarseCell::kGoal
                                                               : explore::CoarseCell::kFree;
    }
  }
  return {core::GridGeometry(1.0, {0.0, 0.0}, w, h), std::move(cells)};
}

// A map from a picture: '#' occupied, '.' free, '?' unknown; the first line
// is the top row (largest y).
inline mapping::TrinaryMap MapPicture(const std::vector<std::string>& lines,
                                      double resolution = 0.1,
                                      Eigen::Vector2d origin = Eigen::Vector2d::Zero()) {
  const int h = static_cast<int>(lines.size());
  const int w = static_cast<int>(lines.front().size());
  mapping::TrinaryMap map{core::GridGeometry(resolution, std::move(origin), w, h),
                          std::vector<mapping::CellState>(static_cast<std::size_t>(w) * h)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const char c = lines[static_cast<std::size_t>(h - 1 - y)][static_cast<std::size_t>(x)];
      map.cells[map.geometry.Flat({x, y})] = c == '#'   ? mapping::CellState::kOccupied
                                             : c == '?' ? mapping::CellState::kUnknown
                                                        : mapping::CellState::kFree;
    }
  }
  return map;
}

// A uniform integer in [0, n) from a generator whose output is fixed by the
// standard (unlike std::uniform_int_distribution's).
inline int Uniform(std::mt19937& rng, int n) {
  return static_cast<int>(rng() % static_cast<std::uint32_t>(n));
}

// w × h cells, each blocked with probability `density`, then `goals` random
// cells made goals.
inline explore::CoarseGrid RandomGrid(int w, int h, double density, int goals, std::uint32_t seed) {
  std::mt19937 rng(seed);
  std::vector<explore::CoarseCell> cells(static_cast<std::size_t>(w) * h,
                                         explore::CoarseCell::kFree);
  for (explore::CoarseCell& c : cells) {
    if (Uniform(rng, 1000000) < density * 1e6) c = explore::CoarseCell::kBlocked;
  }
  for (int i = 0; i < goals; ++i) {
    cells[static_cast<std::size_t>(Uniform(rng, w * h))] = explore::CoarseCell::kGoal;
  }
  return {core::GridGeometry(1.0, {0.0, 0.0}, w, h), std::move(cells)};
}

// A perfect maze (depth-first backtracker) of n × n rooms, each room and
// wall `scale` cells wide, so (2n + 1)·scale cells a side; a goal in the
// corner room.
inline explore::CoarseGrid RandomMaze(int n, int scale, std::uint32_t seed) {
  const int side = 2 * n + 1;
  std::vector<bool> open(static_cast<std::size_t>(side) * side, false);
  const auto at = [&](int x, int y) { return open[static_cast<std::size_t>(y) * side + x]; };
  const auto set = [&](int x, int y) { open[static_cast<std::size_t>(y) * side + x] = true; };
  std::mt19937 rng(seed);
  std::vector<std::pair<int, int>> stack = {{0, 0}};
  set(1, 1);
  const int dirs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  while (!stack.empty()) {
    const auto [rx, ry] = stack.back();
    std::vector<int> options;
    for (int d = 0; d < 4; ++d) {
      const int nx = rx + dirs[d][0];
      const int ny = ry + dirs[d][1];
      if (nx >= 0 && ny >= 0 && nx < n && ny < n && !at(2 * nx + 1, 2 * ny + 1)) {
        options.push_back(d);
      }
    }
    if (options.empty()) {
      stack.pop_back();
      continue;
    }
    const int d = options[static_cast<std::size_t>(Uniform(rng, static_cast<int>(options.size())))];
    set(2 * rx + 1 + dirs[d][0], 2 * ry + 1 + dirs[d][1]);
    set(2 * (rx + dirs[d][0]) + 1, 2 * (ry + dirs[d][1]) + 1);
    stack.emplace_back(rx + dirs[d][0], ry + dirs[d][1]);
  }
  const int w = side * scale;
  std::vector<explore::CoarseCell> cells(static_cast<std::size_t>(w) * w);
  for (int y = 0; y < w; ++y) {
    for (int x = 0; x < w; ++x) {
      cells[static_cast<std::size_t>(y) * w + x] =
          at(x / scale, y / scale) ? explore::CoarseCell::kFree : explore::CoarseCell::kBlocked;
    }
  }
  cells[static_cast<std::size_t>(scale) * w + scale] = explore::CoarseCell::kGoal;
  return {core::GridGeometry(1.0, {0.0, 0.0}, w, w), std::move(cells)};
}

// A square spiral corridor, 1 cell wide between 1-cell walls, scaled by
// `scale`, from the outer corner (0, 0) inwards; the goal at its inner end,
// so the way out winds round and round.
inline explore::CoarseGrid Spiral(int side, int scale) {
  std::vector<bool> open(static_cast<std::size_t>(side) * side, false);
  const auto idx = [&](int x, int y) { return static_cast<std::size_t>(y) * side + x; };
  const int dirs[4][2] = {{1, 0}, {0, 1}, {-1, 0}, {0, -1}};
  int x = 0;
  int y = 0;
  int d = 0;
  open[idx(x, y)] = true;
  int failed_turns = 0;
  while (failed_turns < 2) {
    const int mx = x + dirs[d][0];
    const int my = y + dirs[d][1];
    const int tx = x + 2 * dirs[d][0];
    const int ty = y + 2 * dirs[d][1];
    if (tx >= 0 && ty >= 0 && tx < side && ty < side && !open[idx(tx, ty)]) {
      open[idx(mx, my)] = true;
      open[idx(tx, ty)] = true;
      x = tx;
      y = ty;
      failed_turns = 0;
    } else {
      d = (d + 1) % 4;
      ++failed_turns;
    }
  }
  const int w = side * scale;
  std::vector<explore::CoarseCell> cells(static_cast<std::size_t>(w) * w);
  for (int cy = 0; cy < w; ++cy) {
    for (int cx = 0; cx < w; ++cx) {
      cells[static_cast<std::size_t>(cy) * w + cx] = open[idx(cx / scale, cy / scale)]
                                                         ? explore::CoarseCell::kFree
                                                         : explore::CoarseCell::kBlocked;
    }
  }
  cells[static_cast<std::size_t>(y) * scale * w + static_cast<std::size_t>(x) * scale] =
      explore::CoarseCell::kGoal;
  return {core::GridGeometry(1.0, {0.0, 0.0}, w, w), std::move(cells)};
}

// Dijkstra's algorithm with a binary heap and the same 8-neighbour weights:
// the reference distance of every cell, row-major (kUnreachable as the
// field's).
inline std::vector<std::int32_t> DijkstraReference(const explore::CoarseGrid& grid) {
  const int w = grid.width();
  const int h = grid.height();
  std::vector<std::int32_t> d(static_cast<std::size_t>(w) * h, explore::kUnreachable);
  using Entry = std::pair<std::int32_t, int>;
  std::priority_queue<Entry, std::vector<Entry>, std::greater<>> queue;
  for (int i = 0; i < w * h; ++i) {
    if (grid.cells()[static_cast<std::size_t>(i)] == explore::CoarseCell::kGoal) {
      d[static_cast<std::size_t>(i)] = 0;
      queue.emplace(0, i);
    }
  }
  while (!queue.empty()) {
    const auto [dist, i] = queue.top();
    queue.pop();
    if (dist != d[static_cast<std::size_t>(i)]) continue;
    const int x = i % w;
    const int y = i / w;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        if (dx == 0 && dy == 0) continue;
        const int nx = x + dx;
        const int ny = y + dy;
        if (nx < 0 || ny < 0 || nx >= w || ny >= h) continue;
        const int n = ny * w + nx;
        if (grid.cells()[static_cast<std::size_t>(n)] != explore::CoarseCell::kFree) continue;
        const std::int32_t nd =
            dist + (dx != 0 && dy != 0 ? explore::kChamferDiagonal : explore::kChamferOrthogonal);
        if (nd < d[static_cast<std::size_t>(n)]) {
          d[static_cast<std::size_t>(n)] = nd;
          queue.emplace(nd, n);
        }
      }
    }
  }
  return d;
}

// The field's distances, row-major.
inline std::vector<std::int32_t> Distances(const explore::DistanceField& field) {
  std::vector<std::int32_t> d;
  for (int y = 0; y < field.height(); ++y) {
    for (int x = 0; x < field.width(); ++x) d.push_back(field.At({x, y}));
  }
  return d;
}

// A map of w × h cells of 1 cm, walled all round (one cell thick), free inside.
inline mapping::TrinaryMap WalledMap(int w, int h) {
  mapping::TrinaryMap map{core::GridGeometry(0.01, {0.0, 0.0}, w, h),
                          std::vector<mapping::CellState>(static_cast<std::size_t>(w) * h)};
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const bool wall = x == 0 || y == 0 || x == w - 1 || y == h - 1;
      map.cells[map.geometry.Flat({x, y})] =
          wall ? mapping::CellState::kOccupied : mapping::CellState::kFree;
    }
  }
  return map;
}

// Sets the cells [x0, x1] × [y0, y1] of `map` to `state`.
inline void FillCells(mapping::TrinaryMap& map, int x0, int y0, int x1, int y1,
                      mapping::CellState state) {
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) map.cells[map.geometry.Flat({x, y})] = state;
  }
}

// A planner's options for a robot two 1 cm cells in radius, on coarse cells
// of two map cells.
inline explore::PlannerOptions TwoCellRobot() {
  explore::PlannerOptions options;
  options.robot_radius_m = 0.02;
  options.coarse_factor = 2;
  return options;
}

}  // namespace pirouette::testing
