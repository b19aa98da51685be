#include "pirouette/sim/maze_plan.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>

namespace pirouette::sim {
namespace {

// Widths of n corridors summing to `total`, each in [lo, hi] where that is
// possible: each drawn in [lo, hi], then all moved towards lo (or hi) in
// proportion until they sum to `total`, then whole millimetres.
std::vector<Mm> DrawWidths(SeededRandom& random, Mm total, int n, Mm lo, Mm hi) {
  if (total < n * lo || total > n * hi) {  // the floor does not allow it: equal widths
    std::vector<Mm> widths(static_cast<std::size_t>(n), total / n);
    for (Mm i = 0; i < total % n; ++i) ++widths[static_cast<std::size_t>(i)];
    return widths;
  }
  const auto l = static_cast<double>(lo);
  const auto h = static_cast<double>(hi);
  const auto t = static_cast<double>(total);
  std::vector<double> drawn(static_cast<std::size_t>(n));
  double sum = 0.0;
  for (double& w : drawn) sum += (w = random.Uniform(l, h));
  for (double& w : drawn) {
    if (sum > t) w = l + (w - l) * (t - n * l) / (sum - n * l);
    if (sum < t) w = h - (h - w) * (n * h - t) / (n * h - sum);
  }
  std::vector<Mm> widths;
  Mm used = 0;
  for (const double w : drawn) {
    widths.push_back(std::clamp(static_cast<Mm>(std::floor(w)), lo, hi));
    used += widths.back();
  }
  // The millimetres the floors left over, one each to corridors below hi.
  for (std::size_t i = 0; used < total; i = (i + 1) % widths.size()) {
    if (widths[i] < hi) {
      ++widths[i];
      ++used;
    }
  }
  return widths;
}

// Corridors across a floor `length` long with walls `t` thick between them.
std::vector<Mm> DrawCorridors(SeededRandom& random, Mm length, Mm t, Mm lo, Mm hi) {
  const Mm most = std::max<Mm>(1, (length + t) / (lo + t));
  const Mm fewest = std::min(most, (length + t + hi + t - 1) / (hi + t));
  const int n = static_cast<int>(random.Between(std::max<Mm>(1, fewest), most));
  return DrawWidths(random, length - (n - 1) * t, n, lo, hi);
}

// The lower edges of the corridors (each the previous one's end plus a wall).
std::vector<Mm> Starts(const std::vector<Mm>& widths, Mm t) {
  std::vector<Mm> starts;
  Mm at = 0;
  for (const Mm w : widths) {
    starts.push_back(at);
    at += w + t;
  }
  return starts;
}

// open[cell][direction]: direction 0 east, 1 north; from a recursive backtracker.
std::vector<std::array<bool, 2>> SpanningTree(SeededRandom& random, int nx, int ny) {
  const auto index = [nx](int x, int y) {
    return static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) + static_cast<std::size_t>(x);
  };
  std::vector<std::array<bool, 2>> open(static_cast<std::size_t>(nx) * static_cast<std::size_t>(ny),
                                        {false, false});
  std::vector<bool> visited(open.size(), false);
  const int start = static_cast<int>(random.Below(open.size()));
  std::vector<int> stack = {start};
  visited[static_cast<std::size_t>(start)] = true;
  while (!stack.empty()) {
    const int cell = stack.back();
    const int x = cell % nx;
    const int y = cell / nx;
    struct Step {
      int x, y;
    };
    std::vector<Step> next;
    for (const Step s : {Step{x + 1, y}, Step{x - 1, y}, Step{x, y + 1}, Step{x, y - 1}}) {
      if (s.x >= 0 && s.y >= 0 && s.x < nx && s.y < ny && !visited[index(s.x, s.y)]) {
        next.push_back(s);
      }
    }
    if (next.empty()) {
      stack.pop_back();
      continue;
    }
    const Step s = next[random.Below(next.size())];
    // The wall between the two cells, held by the lower-left one.
    if (s.x != x) open[index(std::min(x, s.x), y)][0] = true;
    if (s.y != y) open[index(x, std::min(y, s.y))][1] = true;
    visited[index(s.x, s.y)] = true;
    stack.push_back(s.y * nx + s.x);
  }
  return open;
}

}  // namespace

MazePlan DrawMazePlan(SeededRandom& random, const MazePlanOptions& o) {
  assert(o.thickness % 2 == 0);
  const Mm t = o.thickness;
  MazePlan plan;
  plan.columns = DrawCorridors(random, o.width, t, o.corridor_min, o.corridor_max);
  plan.rows = DrawCorridors(random, o.height, t, o.corridor_min, o.corridor_max);
  const int nx = static_cast<int>(plan.columns.size());
  const int ny = static_cast<int>(plan.rows.size());
  const std::vector<Mm> xs = Starts(plan.columns, t);
  const std::vector<Mm> ys = Starts(plan.rows, t);
  const std::vector<std::array<bool, 2>> open = SpanningTree(random, nx, ny);
  const auto closed = [&](int x, int y, int direction) {
    return !open[static_cast<std::size_t>(y) * static_cast<std::size_t>(nx) +
                 static_cast<std::size_t>(x)][direction];
  };
  // Each line between two columns (rows): runs of closed walls merged, each
  // run reaching over the wall-thick squares at its ends so that corners close.
  for (int x = 0; x + 1 < nx; ++x) {
    const Mm centre = xs[x] + plan.columns[x] + t / 2;
    for (int y = 0; y < ny;) {
      if (!closed(x, y, 0)) {
        ++y;
        continue;
      }
      int end = y;
      while (end + 1 < ny && closed(x, end + 1, 0)) ++end;
      plan.walls.push_back({centre, std::max<Mm>(0, ys[y] - t), centre,
                            std::min(o.height, ys[end] + plan.rows[end] + t)});
      y = end + 1;
    }
  }
  for (int y = 0; y + 1 < ny; ++y) {
    const Mm centre = ys[y] + plan.rows[y] + t / 2;
    for (int x = 0; x < nx;) {
      if (!closed(x, y, 1)) {
        ++x;
        continue;
      }
      int end = x;
      while (end + 1 < nx && closed(end + 1, y, 1)) ++end;
      plan.walls.push_back({std::max<Mm>(0, xs[x] - t), centre,
                            std::min(o.width, xs[end] + plan.columns[end] + t), centre});
      x = end + 1;
    }
  }
  for (int y = 0; y < ny; ++y) {
    for (int x = 0; x < nx; ++x) {
      plan.cells.push_back({xs[x], ys[y], xs[x] + plan.columns[x], ys[y] + plan.rows[y]});
    }
  }
  return plan;
}

}  // namespace pirouette::sim
