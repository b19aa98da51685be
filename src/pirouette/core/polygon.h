#pragma once

#include <Eigen/Core>
#include <optional>
#include <string>
#include <vector>

namespace pirouette::core {

// Why `points` (a closed polygon, either orientation, at least 3 points, the
// last not repeating the first) is not a simple polygon with an area; nullopt
// when it is one. Points are numbered from 1 in messages: repeated
// neighbours, all points on one line, an edge that folds back on the one
// before it, two edges that meet, no area.
std::optional<std::string> PolygonProblem(const std::vector<Eigen::Vector2d>& points);

}  // namespace pirouette::core
