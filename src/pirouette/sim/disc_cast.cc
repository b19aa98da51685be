#include "pirouette/sim/disc_cast.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pirouette/core/geometry2.h"

namespace pirouette::sim {
namespace {

using core::DistanceToSegment;

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// A closed interval of the path parameter s (metres along the move);
// empty when lo > hi.
struct Interval {
  double lo = -kInfinity;
  double hi = kInfinity;
  bool empty() const { return lo > hi; }
};

constexpr Interval kEmpty{kInfinity, -kInfinity};

Interval Intersect(const Interval& a, const Interval& b) {
  return {std::max(a.lo, b.lo), std::min(a.hi, b.hi)};
}

// {s : lo <= value0 + s·rate <= hi}.
Interval Slab(double value0, double rate, double lo, double hi) {
  if (rate == 0.0) return value0 >= lo && value0 <= hi ? Interval{} : kEmpty;
  const double s0 = (lo - value0) / rate;
  const double s1 = (hi - value0) / rate;
  return {std::min(s0, s1), std::max(s0, s1)};
}

// The line origin + s·u (u unit) inside the closed disc (centre, rho).
Interval LineInDisc(const Eigen::Vector2d& origin, const Eigen::Vector2d& u,
                    const Eigen::Vector2d& centre, double rho) {
  if (rho < 0.0) return kEmpty;
  const Eigen::Vector2d f = origin - centre;
  const double b = f.dot(u);
  const double discriminant = b * b - (f.squaredNorm() - rho * rho);
  if (discriminant < 0.0) return kEmpty;
  const double root = std::sqrt(discriminant);
  return {-b - root, -b + root};
}

// The line inside the capsule of radius rho around the segment ab: the union
// of the discs at its ends and the rectangle along it, which is convex, so
// the line meets it in one interval.
Interval LineInCapsule(const Eigen::Vector2d& origin, const Eigen::Vector2d& u,
                       const Eigen::Vector2d& a, const Eigen::Vector2d& b, double rho) {
  if (rho < 0.0) return kEmpty;
  Interval result = kEmpty;
  const auto unite = [&result](const Interval& part) {
    if (part.empty()) return;
    result = {std::min(result.lo, part.lo), std::max(result.hi, part.hi)};
  };
  unite(LineInDisc(origin, u, a, rho));
  unite(LineInDisc(origin, u, b, rho));
  const Eigen::Vector2d edge = b - a;
  const double length = edge.norm();
  if (length > 0.0) {
    const Eigen::Vector2d along = edge / length;
    const Eigen::Vector2d normal(-along.y(), along.x());
    const Eigen::Vector2d offset = origin - a;
    unite(Intersect(Slab(offset.dot(along), u.dot(along), 0.0, length),
                    Slab(offset.dot(normal), u.dot(normal), -rho, rho)));
  }
  return result;
}

// Takes one piece into account: `deep` is where the disc overlaps it by more
// than kOverlapTolerance, `touching` where it touches it at all, `deepening`
// whether the overlap grows as the robot starts to move.
void Consider(const Interval& deep, const Interval& touching, bool deepening,
              ContactResult& result) {
  if (deep.empty() || deep.hi < 0.0) return;
  double blocked = deep.lo;
  if (deep.lo < 0.0) {
    // Already overlapping more than the tolerance (a bad start): blocked only
    // when the move makes it worse.
    if (!deepening) return;
    blocked = 0.0;
  }
  if (blocked < result.blocked) {
    result.blocked = blocked;
    result.touch = std::clamp(touching.empty() ? blocked : touching.lo, 0.0, blocked);
  }
}

}  // namespace

// The method: what the robot's disc must not overlap, cut into convex pieces: for each
// polygon edge, the capsule of radius (radius - depth) around it holds the
// centres where the disc overlaps the edge by at least `depth`; for each
// circle, the disc of radius (R + radius - depth); for each side of the
// floor, the half plane beyond the line (radius - depth) inside it. A
// polygon's interior cannot be reached without crossing the capsules around
// its edges, so these pieces catch every first contact. Along the line
// origin + s·u each piece is one interval of s.
ContactResult CastDisc(const World& world, const Eigen::Vector2d& origin, const Eigen::Vector2d& u,
                       double radius) {
  ContactResult result;
  const double deep_radius = radius - kOverlapTolerance;
  for (const Solid& solid : world.solids()) {
    if (solid.circle) {
      const Eigen::Vector2d& c = solid.circle->centre;
      const double r = solid.circle->radius;
      Consider(LineInDisc(origin, u, c, r + deep_radius), LineInDisc(origin, u, c, r + radius),
               u.dot(origin - c) < 0.0, result);
      continue;
    }
    const std::vector<Eigen::Vector2d>& polygon = solid.footprint;
    for (std::size_t i = 0; i < polygon.size(); ++i) {
      const Eigen::Vector2d& a = polygon[i];
      const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
      const Interval deep = LineInCapsule(origin, u, a, b, deep_radius);
      if (deep.empty() || deep.hi < 0.0) continue;
      // Deepening: moving toward the nearest point of the edge.
      const Eigen::Vector2d ab = b - a;
      const double t = ab.squaredNorm() > 0.0
                           ? std::clamp((origin - a).dot(ab) / ab.squaredNorm(), 0.0, 1.0)
                           : 0.0;
      const bool deepening =
          u.dot(origin - (a + t * ab)) < 0.0 || DistanceToSegment(origin, a, b) == 0.0;
      Consider(deep, LineInCapsule(origin, u, a, b, radius), deepening, result);
    }
  }
  // The floor's sides: the disc must keep within [0, size] on each axis.
  const Eigen::Vector2d& size = world.floor().size;
  for (int axis = 0; axis < 2; ++axis) {
    const double p = origin[axis];
    const double v = u[axis];
    // Overlap with the low side: radius - p; with the high side: radius - (size - p).
    Consider(Slab(p, v, -kInfinity, deep_radius), Slab(p, v, -kInfinity, radius), v < 0.0, result);
    Consider(Slab(p, v, size[axis] - deep_radius, kInfinity),
             Slab(p, v, size[axis] - radius, kInfinity), v > 0.0, result);
  }
  return result;
}

}  // namespace pirouette::sim
