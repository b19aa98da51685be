#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>
#include <stdexcept>
#include <utility>

#include "pirouette/core/geometry2.h"

namespace pirouette::core {

// A cell index: x is the column, y the row; row 0 is the lowest y.
struct CellIndex {
  int x = 0;
  int y = 0;
  friend bool operator==(const CellIndex&, const CellIndex&) = default;
};

// The geometry of a regular grid on the floor: cell size, the world position
// of the lower-left cell's lower-left corner, and the size in cells. An
// immutable value; the constructor checks it (Cartographer's MapLimits).
class GridGeometry {
 public:
  // Throws std::invalid_argument unless resolution > 0 and both sizes > 0.
  GridGeometry(double resolution_m, Eigen::Vector2d origin, int width, int height)
      : resolution_(resolution_m), origin_(std::move(origin)), width_(width), height_(height) {
    if (!(resolution_m > 0.0) || width <= 0 || height <= 0) {
      throw std::invalid_argument("GridGeometry: resolution and size must be positive");
    }
  }

  // The smallest grid of cells of `resolution_m` whose lower-left corner is
  // `origin` and that covers the rectangle [origin, origin + extent].
  static GridGeometry Covering(double resolution_m, const Eigen::Vector2d& origin,
                               const Eigen::Vector2d& extent) {
    const auto cells = [&](double length) {
      return std::max(1, static_cast<int>(std::ceil(length / resolution_m - 1e-9)));
    };
    return {resolution_m, origin, cells(extent.x()), cells(extent.y())};
  }

  double resolution() const { return resolution_; }
  const Eigen::Vector2d& origin() const { return origin_; }
  int width() const { return width_; }
  int height() const { return height_; }
  std::size_t CellCount() const {
    return static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  }

  bool Contains(const CellIndex& c) const {
    return c.x >= 0 && c.y >= 0 && c.x < width_ && c.y < height_;
  }

  // Row-major index of a cell inside the grid.
  std::size_t Flat(const CellIndex& c) const {
    return static_cast<std::size_t>(c.y) * static_cast<std::size_t>(width_) +
           static_cast<std::size_t>(c.x);
  }
  CellIndex Unflat(std::size_t i) const {
    return {static_cast<int>(i % static_cast<std::size_t>(width_)),
            static_cast<int>(i / static_cast<std::size_t>(width_))};
  }

  // The cell holding a world point, which may lie outside the grid.
  CellIndex CellOf(const Eigen::Vector2d& p_world) const {
    return {static_cast<int>(std::floor((p_world.x() - origin_.x()) / resolution_)),
            static_cast<int>(std::floor((p_world.y() - origin_.y()) / resolution_))};
  }

  // The cell holding a world point, or nothing when it is off the grid.
  std::optional<CellIndex> CellAt(const Eigen::Vector2d& p_world) const {
    const CellIndex c = CellOf(p_world);
    if (!Contains(c)) return std::nullopt;
    return c;
  }

  Eigen::Vector2d CellCentre(const CellIndex& c) const {
    return {origin_.x() + (c.x + 0.5) * resolution_, origin_.y() + (c.y + 0.5) * resolution_};
  }

  friend bool operator==(const GridGeometry& a, const GridGeometry& b) {
    return a.resolution_ == b.resolution_ && a.origin_ == b.origin_ && a.width_ == b.width_ &&
           a.height_ == b.height_;
  }

 private:
  double resolution_;
  Eigen::Vector2d origin_;
  int width_;
  int height_;
};

// Whether `pred` holds for any cell, on the grid or off it, whose centre lies
// within reach_m of the segment from -> to (the corridor a disc of reach_m
// sweeps along it). Stops at the first such cell.
template <typename Pred>
bool AnyCellNearSegment(const GridGeometry& g, const Eigen::Vector2d& from,
                        const Eigen::Vector2d& to, double reach_m, Pred&& pred) {
  const Eigen::Vector2d margin(reach_m, reach_m);
  const CellIndex a = g.CellOf(from.cwiseMin(to) - margin);
  const CellIndex b = g.CellOf(from.cwiseMax(to) + margin);
  for (int y = a.y; y <= b.y; ++y) {
    for (int x = a.x; x <= b.x; ++x) {
      const CellIndex c{x, y};
      if (DistanceToSegment(g.CellCentre(c), from, to) > reach_m) continue;
      if (pred(c)) return true;
    }
  }
  return false;
}

}  // namespace pirouette::core
