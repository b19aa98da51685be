#include "pirouette/sim/obstacle_placer.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <limits>
#include <utility>

#include "pirouette/core/geometry2.h"

namespace pirouette::sim {
namespace {

using core::Cross;
using core::DistanceToSegment;

// Closer than this (metres) counts as touching: flush, neither a gap nor an overlap.
constexpr double kTouchM = 1e-6;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// cos(m · 15°) for m = 0..6, the decimals nearest each.
constexpr std::array<double, 7> kCos15 = {
    1.0, 0.96592582628906831, 0.86602540378443865, 0.70710678118654752, 0.5, 0.25881904510252076,
    0.0};

// The distance from p to the convex polygon's boundary, negative inside.
double SignedDistanceToConvex(const Eigen::Vector2d& p,
                              const std::vector<Eigen::Vector2d>& polygon) {
  double distance = kInfinity;
  bool inside = true;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    distance = std::min(distance, DistanceToSegment(p, a, b));
    inside = inside && Cross(b - a, p - a) >= 0.0;
  }
  return inside ? -distance : distance;
}

// The widest separation of two convex counter-clockwise polygons along the
// outward normals of a's edges: positive where one of them separates them.
double Separation(const std::vector<Eigen::Vector2d>& a, const std::vector<Eigen::Vector2d>& b) {
  double best = -kInfinity;
  for (std::size_t i = 0; i < a.size(); ++i) {
    const Eigen::Vector2d edge = a[(i + 1) % a.size()] - a[i];
    const Eigen::Vector2d normal = Eigen::Vector2d(edge.y(), -edge.x()) / edge.norm();
    double a_max = -kInfinity;
    for (const Eigen::Vector2d& v : a) a_max = std::max(a_max, normal.dot(v));
    double b_min = kInfinity;
    for (const Eigen::Vector2d& v : b) b_min = std::min(b_min, normal.dot(v));
    best = std::max(best, b_min - a_max);
  }
  return best;
}

}  // namespace

Eigen::Vector2d YawDirection(int k) {
  assert(k >= 0 && k < 24);
  const int m = k % 6;
  Eigen::Vector2d d(kCos15[m], kCos15[6 - m]);
  for (int quarter = 0; quarter < k / 6; ++quarter) d = Eigen::Vector2d(-d.y(), d.x());
  return d;
}

// Eigen's fixed-size vectors go by reference (Eigen's alignment rules).
ObstaclePlacer::ObstaclePlacer(
    const Eigen::Vector2d& floor_size)  // NOLINT(modernize-pass-by-value)
    : floor_size_(floor_size) {}

ObstaclePlacer::Footprint ObstaclePlacer::Rectangle(const Eigen::Vector2d& lo,
                                                    const Eigen::Vector2d& hi) {
  return {{lo, {hi.x(), lo.y()}, hi, {lo.x(), hi.y()}}, std::nullopt, lo, hi};
}

ObstaclePlacer::Footprint ObstaclePlacer::FootprintOf(const ObstacleSpec& obstacle) {
  Footprint f;
  const auto rectangle = [&f](const Eigen::Vector2d& centre, const Eigen::Vector2d& axis,
                              double half_length, double half_width) {
    const Eigen::Vector2d normal(-axis.y(), axis.x());
    f.polygon = {centre - half_length * axis - half_width * normal,
                 centre + half_length * axis - half_width * normal,
                 centre + half_length * axis + half_width * normal,
                 centre - half_length * axis + half_width * normal};
  };
  if (const auto* box = std::get_if<BoxSpec>(&obstacle.shape)) {
    const int k = static_cast<int>(std::lround(box->yaw_deg / 15.0));
    assert(k * 15.0 == box->yaw_deg && k >= 0 && k < 24);
    rectangle(box->centre, YawDirection(k), box->size.x() / 2.0, box->size.y() / 2.0);
  } else if (const auto* wall = std::get_if<WallSpec>(&obstacle.shape)) {
    const Eigen::Vector2d along = wall->to - wall->from;
    rectangle((wall->from + wall->to) / 2.0, along / along.norm(), along.norm() / 2.0,
              wall->thickness / 2.0);
  } else if (const auto* cylinder = std::get_if<CylinderSpec>(&obstacle.shape)) {
    f.circle = Eigen::Vector3d(cylinder->centre.x(), cylinder->centre.y(), cylinder->radius);
    f.lo = cylinder->centre - Eigen::Vector2d::Constant(cylinder->radius);
    f.hi = cylinder->centre + Eigen::Vector2d::Constant(cylinder->radius);
    return f;
  } else {
    f.polygon = std::get<PrismSpec>(obstacle.shape).points;
    double twice_area = 0.0;
    for (std::size_t i = 0; i < f.polygon.size(); ++i) {
      twice_area += Cross(f.polygon[i], f.polygon[(i + 1) % f.polygon.size()]);
    }
    if (twice_area < 0.0) std::reverse(f.polygon.begin(), f.polygon.end());
  }
  f.lo = f.hi = f.polygon.front();
  for (const Eigen::Vector2d& v : f.polygon) {
    f.lo = f.lo.cwiseMin(v);
    f.hi = f.hi.cwiseMax(v);
  }
  return f;
}

double ObstaclePlacer::Gap(const Footprint& a, const Footprint& b) {
  if (a.circle && b.circle) {
    return (a.circle->head<2>() - b.circle->head<2>()).norm() - a.circle->z() - b.circle->z();
  }
  if (a.circle || b.circle) {
    const Footprint& disc = a.circle ? a : b;
    const Footprint& polygon = a.circle ? b : a;
    return SignedDistanceToConvex(disc.circle->head<2>(), polygon.polygon) - disc.circle->z();
  }
  const double separation =
      std::max(Separation(a.polygon, b.polygon), Separation(b.polygon, a.polygon));
  if (separation < -kTouchM) return separation;  // no axis separates them: they overlap
  // Apart (or touching): the nearest points are a vertex of one and an edge of the other.
  double distance = kInfinity;
  for (const Eigen::Vector2d& v : a.polygon) {
    distance = std::min(distance, std::abs(SignedDistanceToConvex(v, b.polygon)));
  }
  for (const Eigen::Vector2d& v : b.polygon) {
    distance = std::min(distance, std::abs(SignedDistanceToConvex(v, a.polygon)));
  }
  return distance;
}

bool ObstaclePlacer::KeepsFromEdges(const Footprint& f, double gap, bool flush) const {
  const std::array<double, 4> to_edges = {f.lo.x(), floor_size_.x() - f.hi.x(), f.lo.y(),
                                          floor_size_.y() - f.hi.y()};
  for (const double d : to_edges) {
    if (d < -kTouchM) return false;
    if (flush && d <= kTouchM) continue;
    if (d < gap) return false;
  }
  return true;
}

void ObstaclePlacer::AddWall(const ObstacleSpec& wall) {
  placed_.push_back({FootprintOf(wall), true});
  obstacles_.push_back(wall);
}

void ObstaclePlacer::AddKeepOut(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  keep_out_.push_back(Rectangle(lo, hi));
}

bool ObstaclePlacer::TryAdd(const ObstacleSpec& obstacle, double gap, bool against_wall) {
  const Footprint f = FootprintOf(obstacle);
  if (!KeepsFromEdges(f, gap, against_wall)) return false;
  for (const Footprint& zone : keep_out_) {
    if (Gap(f, zone) < 0.0) return false;
  }
  for (const Placed& other : placed_) {
    // Bounding boxes this far apart keep the gap.
    const Eigen::Vector2d apart =
        (f.lo - other.footprint.hi).cwiseMax(other.footprint.lo - f.hi).cwiseMax(0.0);
    if (apart.norm() >= gap) continue;
    const double g = Gap(f, other.footprint);
    if (g < -kTouchM) return false;
    if (other.wall && against_wall && g <= kTouchM) continue;
    if (g < gap) return false;
  }
  placed_.push_back({f, false});
  obstacles_.push_back(obstacle);
  return true;
}

double ObstaclePlacer::Clearance(const Eigen::Vector2d& p) const {
  double clearance = std::min({p.x(), floor_size_.x() - p.x(), p.y(), floor_size_.y() - p.y()});
  for (const Placed& other : placed_) {
    const Footprint& f = other.footprint;
    clearance = std::min(clearance, f.circle ? (p - f.circle->head<2>()).norm() - f.circle->z()
                                             : SignedDistanceToConvex(p, f.polygon));
  }
  return std::max(clearance, 0.0);
}

}  // namespace pirouette::sim
