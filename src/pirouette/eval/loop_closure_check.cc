#include "pirouette/eval/loop_closure_check.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <optional>

#include "pirouette/core/angle.h"

namespace pirouette::eval {

namespace {

// The true pose of each stop: its first frame's.
std::vector<std::optional<core::Pose2>> StopTruth(const localize::PoseGraph& graph,
                                                  const std::vector<int>& frame_stops,
                                                  const std::vector<core::Pose2>& truth) {
  std::vector<std::optional<core::Pose2>> stop_truth(graph.NodeCount());
  const std::size_t frames = std::min(frame_stops.size(), truth.size());
  for (std::size_t k = 0; k < frames; ++k) {
    const int s = frame_stops[k];
    if (s < 0 || static_cast<std::size_t>(s) >= stop_truth.size()) continue;
    auto& t = stop_truth[static_cast<std::size_t>(s)];
    if (!t) t = truth[k];
  }
  return stop_truth;
}

}  // namespace

LoopClosureRecall CheckLoopClosureRecall(const localize::PoseGraph& graph,
                                         const std::vector<int>& frame_stops,
                                         const std::vector<core::Pose2>& truth, double reach_m,
                                         double loop_path_m) {
  const std::vector<std::optional<core::Pose2>> stop_truth = StopTruth(graph, frame_stops, truth);
  // The true path to each stop along the stops.
  std::vector<double> path(stop_truth.size(), 0.0);
  for (std::size_t s = 1; s < stop_truth.size(); ++s) {
    const bool both = stop_truth[s] && stop_truth[s - 1];
    path[s] =
        path[s - 1] +
        (both ? (stop_truth[s]->translation() - stop_truth[s - 1]->translation()).norm() : 0.0);
  }
  std::vector<bool> closed(stop_truth.size(), false);
  for (const localize::PoseGraphEdge& edge : graph.edges()) {
    if (edge.kind == localize::EdgeKind::kLoopClosure && edge.to >= 0 &&
        static_cast<std::size_t>(edge.to) < closed.size()) {
      closed[static_cast<std::size_t>(edge.to)] = true;
    }
  }
  LoopClosureRecall recall;
  for (std::size_t s = 1; s < stop_truth.size(); ++s) {
    if (!stop_truth[s]) continue;
    std::optional<std::size_t> nearest;
    double nearest_m = reach_m;
    for (std::size_t j = 0; j < s; ++j) {
      if (!stop_truth[j]) continue;
      const double d = (stop_truth[j]->translation() - stop_truth[s]->translation()).norm();
      if (d <= nearest_m) {
        nearest_m = d;
        nearest = j;
      }
    }
    if (!nearest || path[s] - path[*nearest] <= loop_path_m) continue;
    ++recall.opportunities;
    if (closed[s]) ++recall.closed;
  }
  return recall;
}

LoopClosureCheck CheckLoopClosures(const localize::PoseGraph& graph,
                                   const std::vector<int>& frame_stops,
                                   const std::vector<core::Pose2>& truth) {
  const std::vector<std::optional<core::Pose2>> stop_truth = StopTruth(graph, frame_stops, truth);
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
