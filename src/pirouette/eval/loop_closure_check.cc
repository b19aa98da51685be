#include "pirouette/eval/loop_closure_check.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include "pirouette/core/angle.h"

namespace pirouette::eval {

LoopClosureCheck CheckLoopClosures(const localize::PoseGraph& graph,
                                   const std::vector<int>& frame_stops,
                                   const std::vector<core::Pose2>& truth) {
  // The true pose of each stop: its first frame's.
  std::vector<std::optional<core::Pose2>> stop_truth(graph.NodeCount());
  const std::size_t frames = std::min(frame_stops.size(), truth.size());
  for (std::size_t k = 0; k < frames; ++k) {
    const int s = frame_stops[k];
    if (s < 0 || static_cast<std::size_t>(s) >= stop_truth.size()) continue;
    auto& t = stop_truth[static_cast<std::size_t>(s)];
    if (!t) t = truth[k];
  }
  LoopClosureCheck check;
  for (const localize::PoseGraphEdge& edge : graph.edges()) {
    if (edge.kind != localize::EdgeKind::kLoopClosure) continue;
    const auto& a = stop_truth[static_cast<std::size_t>(edge.from)];
    const auto& b = stop_truth[static_cast<std::size_t>(edge.to)];
    if (!a || !b) continue;
    // The edge's own residual at the true poses (its translation's length is
    // the distance between the measured and the true relative position).
    const Eigen::Vector3d error = localize::EdgeError(*a, *b, edge.from_T_to);
    const double m = error.head<2>().norm();
    const double deg = core::RadToDeg(std::abs(error.z()));
    ++check.accepted;
    if (m <= kLoopClosureToleranceM && deg <= kLoopClosureToleranceDeg) ++check.correct;
    check.worst_m = std::max(check.worst_m, m);
    check.worst_deg = std::max(check.worst_deg, deg);
  }
  return check;
}

}  // namespace pirouette::eval
