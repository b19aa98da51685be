#include "pirouette/eval/loop_closure_check.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>
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
    const core::Pose2 error = edge.from_T_to.Inverse() * (a->Inverse() * *b);
    const double m = error.translation().norm();
    const double deg = std::abs(core::NormalizeAngle(error.heading())) * 180.0 / std::numbers::pi;
    ++check.accepted;
    if (m <= kLoopClosureToleranceM && deg <= kLoopClosureToleranceDeg) ++check.correct;
    check.worst_m = std::max(check.worst_m, m);
    check.worst_deg = std::max(check.worst_deg, deg);
  }
  return check;
}

}  // namespace pirouette::eval
