#pragma once

#include <vector>

#include "pirouette/core/pose2.h"
#include "pirouette/localize/pose_graph.h"

namespace pirouette::eval {

// How true a pose graph's loop closures are, against the simulator's truth
// (issue 21's precision: an accepted closure is correct when its relative
// pose lies within 2 cm and 1° of the true one).
struct LoopClosureCheck {
  int accepted = 0;  // the graph's loop-closure edges
  int correct = 0;   // of them, those within the tolerance
  double worst_m = 0.0;
  double worst_deg = 0.0;
};

inline constexpr double kLoopClosureToleranceM = 0.02;
inline constexpr double kLoopClosureToleranceDeg = 1.0;

// Checks every EdgeKind::kLoopClosure edge of `graph`. A stop's true pose is
// that of its first frame (a stop's frame is its first frame's: the graph
// tracker's node_T_frame is the identity there): `frame_stops[k]` is the
// stop of frame k and `truth[k]` where the simulator had the robot then.
// Frames past either vector's end are ignored; an edge whose stop has no
// frame there is not counted. Throws nothing.
LoopClosureCheck CheckLoopClosures(const localize::PoseGraph& graph,
                                   const std::vector<int>& frame_stops,
                                   const std::vector<core::Pose2>& truth);

// How many of the loops there were to close the graph closed (issue 21's
// recall), by the graph's own rule applied to the truth: a stop had a loop
// to close when the earlier stop truly nearest it lies within reach_m (the
// graph's overlap reach) and more than loop_path_m back along the stops'
// true path (GraphTrackerOptions::loop_path_m); it closed it when the graph
// holds an EdgeKind::kLoopClosure edge into it. Stops' true poses as
// CheckLoopClosures takes them; stops with no true frame are left out.
struct LoopClosureRecall {
  int opportunities = 0;
  int closed = 0;
};
LoopClosureRecall CheckLoopClosureRecall(const localize::PoseGraph& graph,
                                         const std::vector<int>& frame_stops,
                                         const std::vector<core::Pose2>& truth, double reach_m,
                                         double loop_path_m);

}  // namespace pirouette::eval
