#include "pirouette/core/polygon.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace pirouette::core {
namespace {

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  return (b.x() - a.x()) * (c.y() - a.y()) - (b.y() - a.y()) * (c.x() - a.x());
}

int Orientation(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c) {
  const double cross = Cross(a, b, c);
  return (cross > 0.0) - (cross < 0.0);
}

// True where p, known to be on the line through a and b, lies on the segment ab.
bool WithinSegment(const Eigen::Vector2d& p, const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return p.x() >= std::min(a.x(), b.x()) && p.x() <= std::max(a.x(), b.x()) &&
         p.y() >= std::min(a.y(), b.y()) && p.y() <= std::max(a.y(), b.y());
}

// True where the closed segments ab and cd share a point.
bool SegmentsMeet(const Eigen::Vector2d& a, const Eigen::Vector2d& b, const Eigen::Vector2d& c,
                  const Eigen::Vector2d& d) {
  const int o1 = Orientation(a, b, c);
  const int o2 = Orientation(a, b, d);
  const int o3 = Orientation(c, d, a);
  const int o4 = Orientation(c, d, b);
  if (o1 != o2 && o3 != o4) return true;
  return (o1 == 0 && WithinSegment(c, a, b)) || (o2 == 0 && WithinSegment(d, a, b)) ||
         (o3 == 0 && WithinSegment(a, c, d)) || (o4 == 0 && WithinSegment(b, c, d));
}

// Point i (0-based) as messages name it.
std::string Number(std::size_t i) { return std::to_string(i + 1); }

}  // namespace

std::optional<std::string> PolygonProblem(const std::vector<Eigen::Vector2d>& points) {
  const std::size_t n = points.size();
  const auto next = [n](std::size_t i) { return (i + 1) % n; };
  for (std::size_t i = 0; i < n; ++i) {
    if (points[i] == points[next(i)]) {
      return "points " + Number(i) + " and " + Number(next(i)) + " are the same point";
    }
  }
  bool collinear = true;
  for (std::size_t i = 2; i < n; ++i) {
    collinear = collinear && Orientation(points[0], points[1], points[i]) == 0;
  }
  if (collinear) return "the points lie on one line: the polygon has no area";
  for (std::size_t i = 0; i < n; ++i) {
    // Adjacent edges share a point; they must not run back over each other.
    const Eigen::Vector2d& a = points[i];
    const Eigen::Vector2d& b = points[next(i)];
    const Eigen::Vector2d& c = points[next(next(i))];
    if (Orientation(a, b, c) == 0 && (a - b).dot(c - b) > 0.0) {
      return "the polygon folds back on itself at point " + Number(next(i));
    }
    for (std::size_t j = i + 2; j < n; ++j) {
      if (next(j) == i) continue;  // adjacent through the closing edge
      if (SegmentsMeet(a, b, points[j], points[next(j)])) {
        return "the polygon is not simple: the edge from point " + Number(i) + " to point " +
               Number(next(i)) + " meets the edge from point " + Number(j) + " to point " +
               Number(next(j));
      }
    }
  }
  double twice_area = 0.0;
  for (std::size_t i = 0; i < n; ++i) {
    twice_area += points[i].x() * points[next(i)].y() - points[next(i)].x() * points[i].y();
  }
  if (std::fabs(twice_area) < 2e-12) return "the polygon has no area";
  return std::nullopt;
}

}  // namespace pirouette::core
