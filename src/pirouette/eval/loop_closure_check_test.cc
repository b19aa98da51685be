#include "pirouette/eval/loop_closure_check.h"

#include <gtest/gtest.h>

#include <vector>

#include "pirouette/core/angle.h"

namespace pirouette::eval {
namespace {

using core::Pose2;
using localize::EdgeKind;
using localize::PoseGraph;
using localize::PoseGraphEdge;

// Three stops of two frames each, the truth of each frame; stop 2 comes back
// near stop 0.
struct Fixture {
  PoseGraph graph;
  std::vector<int> frame_stops{0, 0, 1, 1, 2, 2};
  std::vector<Pose2> truth{Pose2(0, 0, 0),   Pose2(0, 0, 0.5),      Pose2(2, 0, 1.0),
                           Pose2(2, 0, 1.5), Pose2(0.1, 0.05, 0.2), Pose2(0.1, 0.05, 0.7)};
  Fixture() {
    for (int i = 0; i < 3; ++i) graph.AddNode(Pose2(i, 0, 0));
  }
  // The true relative pose of stop `to` seen from stop `from`.
  Pose2 True(int from, int to) const {
    return truth[2 * static_cast<std::size_t>(from)].Inverse() *
           truth[2 * static_cast<std::size_t>(to)];
  }
  void Close(int from, int to, const Pose2& from_T_to, EdgeKind kind = EdgeKind::kLoopClosure) {
    PoseGraphEdge edge;
    edge.from = from;
    edge.to = to;
    edge.from_T_to = from_T_to;
    edge.kind = kind;
    graph.AddEdge(edge);
  }
};

TEST(CheckLoopClosures, ATrueClosureIsCorrectAndAWrongOneIsNot) {
  Fixture f;
  f.Close(0, 2, f.True(0, 2) * Pose2(0.015, 0.0, core::DegToRad(0.5)));  // within 2 cm, 1°
  f.Close(0, 2, f.True(0, 2) * Pose2(0.0, 0.03, 0.0));                   // 3 cm off
  f.Close(1, 2, f.True(1, 2) * Pose2(0.0, 0.0, core::DegToRad(2.0)));    // 2° off
  f.Close(0, 1, Pose2(5, 5, 1), EdgeKind::kScanMatch);                   // not a closure
  const LoopClosureCheck check = CheckLoopClosures(f.graph, f.frame_stops, f.truth);
  EXPECT_EQ(check.accepted, 3);
  EXPECT_EQ(check.correct, 1);
  EXPECT_NEAR(check.worst_m, 0.03, 1e-9);
  EXPECT_NEAR(check.worst_deg, 2.0, 1e-9);
}

TEST(CheckLoopClosures, AStopWithoutATrueFrameIsNotCounted) {
  Fixture f;
  f.Close(0, 2, f.True(0, 2));
  f.truth.resize(4);  // the run stopped before stop 2's truth was known
  EXPECT_EQ(CheckLoopClosures(f.graph, f.frame_stops, f.truth).accepted, 0);
  f.frame_stops = {};
  EXPECT_EQ(CheckLoopClosures(f.graph, f.frame_stops, {}).accepted, 0);
}

// Stop 2 comes back 11 cm from stop 0 after 3.9 m of path: a loop to close
// within a reach of 0.5 m and a loop path of 2 m; not with a 5 m loop path,
// nor a 10 cm reach. Stop 1 has only stop 0 before it, 2 m back and out of
// reach.
TEST(CheckLoopClosureRecall, CountsTheLoopsTheTruthHadAndThoseTheGraphClosed) {
  Fixture f;
  LoopClosureRecall recall = CheckLoopClosureRecall(f.graph, f.frame_stops, f.truth, 0.5, 2.0);
  EXPECT_EQ(recall.opportunities, 1);
  EXPECT_EQ(recall.closed, 0);
  f.Close(0, 1, Pose2(2, 0, 1), EdgeKind::kScanMatch);  // not a closure
  EXPECT_EQ(CheckLoopClosureRecall(f.graph, f.frame_stops, f.truth, 0.5, 2.0).closed, 0);
  f.Close(0, 2, f.True(0, 2));
  recall = CheckLoopClosureRecall(f.graph, f.frame_stops, f.truth, 0.5, 2.0);
  EXPECT_EQ(recall.opportunities, 1);
  EXPECT_EQ(recall.closed, 1);
  EXPECT_EQ(CheckLoopClosureRecall(f.graph, f.frame_stops, f.truth, 0.5, 5.0).opportunities, 0);
  EXPECT_EQ(CheckLoopClosureRecall(f.graph, f.frame_stops, f.truth, 0.1, 2.0).opportunities, 0);
  f.truth.resize(4);  // stop 2's truth unknown
  EXPECT_EQ(CheckLoopClosureRecall(f.graph, f.frame_stops, f.truth, 0.5, 2.0).opportunities, 0);
}

}  // namespace
}  // namespace pirouette::eval
