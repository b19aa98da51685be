#include "pirouette/sim/world.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <utility>

#include "pirouette/core/geometry2.h"

namespace pirouette::sim {
namespace {

using core::Cross;
using core::DistanceToSegment;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Twice the signed area of the polygon: positive when counter-clockwise.
double TwiceSignedArea(const std::vector<Eigen::Vector2d>& polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    sum += Cross(polygon[i], polygon[(i + 1) % polygon.size()]);
  }
  return sum;
}

// Even-odd (crossing number) test; for a simple polygon it equals the
// winding test. Points exactly on an edge may go either way: callers decide
// the boundary by distance.
bool InsidePolygon(const Eigen::Vector2d& p, const std::vector<Eigen::Vector2d>& polygon) {
  bool inside = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[j];
    if ((a.y() > p.y()) != (b.y() > p.y())) {
      const double x_cross = a.x() + (p.y() - a.y()) * (b.x() - a.x()) / (b.y() - a.y());
      if (p.x() < x_cross) inside = !inside;
    }
  }
  return inside;
}

// True when the closed segments ab and cd share a point.
bool SegmentsIntersect(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                       const Eigen::Vector2d& d) {
  const double d1 = Cross(b - a, c - a);
  const double d2 = Cross(b - a, d - a);
  const double d3 = Cross(d - c, a - c);
  const double d4 = Cross(d - c, b - c);
  if (((d1 > 0 && d2 < 0) || (d1 < 0 && d2 > 0)) && ((d3 > 0 && d4 < 0) || (d3 < 0 && d4 > 0))) {
    return true;
  }
  const auto on_segment = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q,
                             const Eigen::Vector2d& r) {  // r collinear with pq: is it on pq?
    return std::min(p.x(), q.x()) <= r.x() && r.x() <= std::max(p.x(), q.x()) &&
           std::min(p.y(), q.y()) <= r.y() && r.y() <= std::max(p.y(), q.y());
  };
  return (d1 == 0 && on_segment(a, b, c)) || (d2 == 0 && on_segment(a, b, d)) ||
         (d3 == 0 && on_segment(c, d, a)) || (d4 == 0 && on_segment(c, d, b));
}

// True when the polygon has at least 3 vertices, non-zero area, and no two
// edges meet except adjacent edges at their shared vertex. O(n²); used only
// in debug checks (the world file loader validates its input itself).
[[maybe_unused]] bool IsSimplePolygon(const std::vector<Eigen::Vector2d>& polygon) {
  const std::size_t n = polygon.size();
  if (n < 3 || TwiceSignedArea(polygon) == 0.0) return false;
  for (std::size_t i = 0; i < n; ++i) {
    for (std::size_t j = i + 1; j < n; ++j) {
      const bool adjacent = j == i + 1 || (i == 0 && j == n - 1);
      if (adjacent) continue;
      if (SegmentsIntersect(polygon[i], polygon[(i + 1) % n], polygon[j], polygon[(j + 1) % n])) {
        return false;
      }
    }
  }
  return true;
}

// The smallest t >= 0 where origin + t·direction (unit) meets the closed
// segment ab, or infinity.
double RaySegment(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                  const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  const Eigen::Vector2d edge = b - a;
  const Eigen::Vector2d to_a = a - origin;
  const double denominator = Cross(direction, edge);
  const double scale = std::max(edge.norm(), to_a.norm());
  if (std::abs(denominator) <= 1e-15 * std::max(edge.norm(), 1e-300)) {
    // Parallel: a hit only when collinear, at the nearer end ahead.
    if (std::abs(Cross(to_a, direction)) > 1e-12 * std::max(scale, 1.0)) return kInfinity;
    const double ta = to_a.dot(direction);
    const double tb = (b - origin).dot(direction);
    if (std::max(ta, tb) < 0.0) return kInfinity;
    return std::max(0.0, std::min(ta, tb));
  }
  const double t = Cross(to_a, edge) / denominator;
  const double s = Cross(to_a, direction) / denominator;
  constexpr double kSlack = 1e-12;  // so that a ray through a vertex is not missed
  if (t < 0.0 || s < -kSlack || s > 1.0 + kSlack) return kInfinity;
  return t;
}

// The smallest t >= 0 where origin + t·direction (unit) meets the closed disc, or infinity.
double RayCircle(const Eigen::Vector2d& origin, const Eigen::Vector2d& direction,
                 const Circle& circle) {
  const Eigen::Vector2d f = origin - circle.centre;
  const double b = f.dot(direction);
  const double c = f.squaredNorm() - circle.radius * circle.radius;
  if (c <= 0.0) return 0.0;  // origin inside or on the circle
  const double discriminant = b * b - c;
  if (discriminant < 0.0) return kInfinity;
  // Both roots have the sign of -b (their product c is positive); the nearer one,
  // computed without cancellation.
  if (b >= 0.0) return kInfinity;
  const double far = -b + std::sqrt(discriminant);
  return c / far;
}

Solid MakeRectangle(Solid::Kind kind, const Eigen::Vector2d& centre, const Eigen::Vector2d& axis,
                    double half_length, double half_width, double height, core::Rgb colour) {
  const Eigen::Vector2d normal(-axis.y(), axis.x());
  Solid solid;
  solid.kind = kind;
  solid.footprint = {centre - half_length * axis - half_width * normal,
                     centre + half_length * axis - half_width * normal,
                     centre + half_length * axis + half_width * normal,
                     centre - half_length * axis + half_width * normal};
  solid.height = height;
  solid.colour = colour;
  return solid;
}

// An axis-aligned box [x0, x1] × [y0, y1], counter-clockwise.
Solid MakeAlignedBox(Solid::Kind kind, double x0, double y0, double x1, double y1, double height,
                     core::Rgb colour) {
  Solid solid;
  solid.kind = kind;
  solid.footprint = {{x0, y0}, {x1, y0}, {x1, y1}, {x0, y1}};
  solid.height = height;
  solid.colour = colour;
  return solid;
}

}  // namespace

Eigen::Vector2d Chessboard::InnerCorner(int col, int row) const {
  const Eigen::Vector2d along(std::cos(yaw_rad), std::sin(yaw_rad));
  const Eigen::Vector2d across(-along.y(), along.x());
  return centre + square * ((col - (cols - 1) / 2.0) * along + (row - (rows - 1) / 2.0) * across);
}

double Solid::SignedDistance(const Eigen::Vector2d& p) const {
  if (circle) return (p - circle->centre).norm() - circle->radius;
  assert(!footprint.empty());
  double distance = kInfinity;
  for (std::size_t i = 0; i < footprint.size(); ++i) {
    distance = std::min(distance,
                        DistanceToSegment(p, footprint[i], footprint[(i + 1) % footprint.size()]));
  }
  return InsidePolygon(p, footprint) ? -distance : distance;
}

World::World(std::string name, Floor floor, std::optional<BoundaryWalls> walls,
             std::vector<Solid> obstacles, Light light, RobotSpec robot,
             std::vector<Chessboard> chessboards)
    : name_(std::move(name)),
      floor_(std::move(floor)),
      walls_(walls),
      obstacles_(std::move(obstacles)),
      light_(std::move(light)),
      robot_(std::move(robot)),
      chessboards_(std::move(chessboards)) {
  for (const Chessboard& board : chessboards_) {
    if (board.cols < 2 || board.rows < 2 || !(board.square > 0.0)) {
      throw std::invalid_argument(
          "World: a chessboard needs at least 2 × 2 inner corners and a square > 0");
    }
  }
  if (!(floor_.size.x() > 0.0) || !(floor_.size.y() > 0.0) || !(robot_.radius >= 0.0) ||
      (walls_ && !(walls_->thickness >= 0.0 && walls_->height >= 0.0))) {
    throw std::invalid_argument(
        "World: the floor's size must be > 0, the robot's radius and the walls' sizes >= 0");
  }
  solids_ = obstacles_;
  if (walls_) {
    // Outside the floor, each wall spanning the corners so that the four
    // overlap there: no gap, seen from any side.
    const double t = walls_->thickness;
    const double x = floor_.size.x();
    const double y = floor_.size.y();
    const double h = walls_->height;
    const core::Rgb c = walls_->colour;
    constexpr Solid::Kind kKind = Solid::Kind::kBoundaryWall;
    solids_.push_back(MakeAlignedBox(kKind, -t, -t, x + t, 0.0, h, c));   // south
    solids_.push_back(MakeAlignedBox(kKind, x, -t, x + t, y + t, h, c));  // east
    solids_.push_back(MakeAlignedBox(kKind, -t, y, x + t, y + t, h, c));  // north
    solids_.push_back(MakeAlignedBox(kKind, -t, -t, 0.0, y + t, h, c));   // west
  }
}

bool World::OnFloor(const Eigen::Vector2d& p) const {
  return p.x() >= 0.0 && p.x() <= floor_.size.x() && p.y() >= 0.0 && p.y() <= floor_.size.y();
}

bool World::IsOccupied(const Eigen::Vector2d& p) const {
  if (!OnFloor(p)) return true;
  return std::any_of(solids_.begin(), solids_.end(),
                     [&p](const Solid& solid) { return solid.SignedDistance(p) <= kOnFaceM; });
}

double World::Clearance(const Eigen::Vector2d& p) const {
  if (!OnFloor(p)) return 0.0;
  double clearance = std::min({p.x(), floor_.size.x() - p.x(), p.y(), floor_.size.y() - p.y()});
  for (const Solid& solid : solids_) {
    clearance = std::min(clearance, solid.SignedDistance(p));
    if (clearance <= 0.0) return 0.0;
  }
  return clearance;
}

std::optional<double> World::RayCast(const Eigen::Vector2d& origin,
                                     const Eigen::Vector2d& direction, double max_range) const {
  assert(direction.norm() > 0.0);
  if (IsOccupied(origin)) return max_range >= 0.0 ? std::optional<double>(0.0) : std::nullopt;
  const Eigen::Vector2d d = direction.normalized();

  // Where the ray leaves the floor's rectangle (the origin is on it).
  double t_hit = kInfinity;
  for (int axis = 0; axis < 2; ++axis) {
    if (d[axis] > 0.0) t_hit = std::min(t_hit, (floor_.size[axis] - origin[axis]) / d[axis]);
    if (d[axis] < 0.0) t_hit = std::min(t_hit, -origin[axis] / d[axis]);
  }
  // The origin is outside every solid, so the first point of a solid that the
  // ray meets lies on its boundary.
  for (const Solid& solid : solids_) {
    if (solid.circle) {
      t_hit = std::min(t_hit, RayCircle(origin, d, *solid.circle));
      continue;
    }
    const std::vector<Eigen::Vector2d>& polygon = solid.footprint;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      t_hit = std::min(t_hit, RaySegment(origin, d, polygon[i], polygon[(i + 1) % polygon.size()]));
    }
  }
  if (t_hit > max_range) return std::nullopt;
  return t_hit;
}

Solid MakeBox(const Eigen::Vector2d& centre, const Eigen::Vector2d& size, double yaw_rad,
              double height, core::Rgb colour) {
  // size.x() lies along the yaw direction, size.y() across it.
  return MakeRectangle(Solid::Kind::kBox, centre, {std::cos(yaw_rad), std::sin(yaw_rad)},
                       size.x() / 2.0, size.y() / 2.0, height, colour);
}

Solid MakeCylinder(const Eigen::Vector2d& centre, double radius, double height, core::Rgb colour) {
  Solid solid;
  solid.kind = Solid::Kind::kCylinder;
  solid.footprint.reserve(kCylinderSides);
  for (int i = 0; i < kCylinderSides; ++i) {
    const double angle = 2.0 * std::numbers::pi * i / kCylinderSides;
    solid.footprint.emplace_back(centre.x() + radius * std::cos(angle),
                                 centre.y() + radius * std::sin(angle));
  }
  solid.circle = Circle{centre, radius};
  solid.height = height;
  solid.colour = colour;
  return solid;
}

// The wall's footprint is the segment from → to thickened by thickness / 2 on
// each side, with square ends flush with `from` and `to` (not extended past
// them): a wall drawn from a boundary wall's inner face meets it without
// crossing it. A wall with from == to has no direction; it is taken along +x
// (a degenerate rectangle of zero length).
Solid MakeWall(const Eigen::Vector2d& from, const Eigen::Vector2d& to, double thickness,
               double height, core::Rgb colour) {
  const Eigen::Vector2d along = to - from;
  const double length = along.norm();
  const Eigen::Vector2d axis =
      length > 0.0 ? Eigen::Vector2d(along / length) : Eigen::Vector2d::UnitX();
  return MakeRectangle(Solid::Kind::kWall, (from + to) / 2.0, axis, length / 2.0, thickness / 2.0,
                       height, colour);
}

// A last point equal to the first (a closed ring) is dropped; a clockwise
// polygon is reversed.
Solid MakePrism(std::vector<Eigen::Vector2d> points, double height, core::Rgb colour) {
  if (points.size() > 1 && points.front() == points.back()) points.pop_back();
  assert(IsSimplePolygon(points));
  if (TwiceSignedArea(points) < 0.0) std::reverse(points.begin(), points.end());
  Solid solid;
  solid.kind = Solid::Kind::kPrism;
  solid.footprint = std::move(points);
  solid.height = height;
  solid.colour = colour;
  return solid;
}

}  // namespace pirouette::sim
