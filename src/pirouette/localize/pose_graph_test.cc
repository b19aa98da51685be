#include "pirouette/localize/pose_graph.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <vector>

#include "pirouette/core/angle.h"

// Its own namespace: the unit tests compile together (unity batches).
namespace pirouette::localize::pose_graph_test {
namespace {

using core::DegToRad;
using core::Pose2;

Eigen::Matrix3d Information(double sigma_m, double sigma_deg) {
  return Eigen::Vector3d(1.0 / (sigma_m * sigma_m), 1.0 / (sigma_m * sigma_m),
                         1.0 / (DegToRad(sigma_deg) * DegToRad(sigma_deg)))
      .asDiagonal();
}

TEST(PoseGraphTest, TheErrorIsZeroAtTheMeasuredRelativePoseAndInTheFromFrame) {
  const Pose2 a(1.0, 2.0, DegToRad(90.0));
  const Pose2 a_T_b(0.5, 0.1, DegToRad(30.0));
  const Pose2 b = a * a_T_b;
  EXPECT_LT(EdgeError(a, b, a_T_b).norm(), 1e-12);
  // b moved 0.1 m along the world's -x: in a's frame (turned 90°) that is -y.
  const Pose2 b_moved(b.x() - 0.1, b.y(), b.heading() + DegToRad(2.0));
  const Eigen::Vector3d e = EdgeError(a, b_moved, a_T_b);
  EXPECT_NEAR(e.x(), 0.0, 1e-12);
  EXPECT_NEAR(e.y(), 0.1, 1e-12);
  EXPECT_NEAR(e.z(), DegToRad(2.0), 1e-12);
  // Headings wrap: 179° against -179° is 2° apart.
  EXPECT_NEAR(EdgeError(Pose2(0, 0, DegToRad(179.0)), Pose2(0, 0, DegToRad(-179.0)), Pose2()).z(),
              DegToRad(2.0), 1e-12);
}

TEST(PoseGraphTest, RefusesEdgesTheGraphCannotHold) {
  PoseGraph graph;
  graph.AddNode(Pose2());
  graph.AddNode(Pose2(1, 0, 0));
  EXPECT_THROW(graph.AddEdge({0, 2, Pose2(), Eigen::Matrix3d::Identity(), EdgeKind::kOdometry}),
               std::invalid_argument);
  EXPECT_THROW(graph.AddEdge({1, 1, Pose2(), Eigen::Matrix3d::Identity(), EdgeKind::kOdometry}),
               std::invalid_argument);
  EXPECT_THROW(graph.AddEdge({0, 1, Pose2(), -Eigen::Matrix3d::Identity(), EdgeKind::kOdometry}),
               std::invalid_argument);
}

// A square of 2 m sides, a stop every 0.5 m, driven with odometry that
// over-reads distance by 3% and turns 2° too far at each corner and 0.2° a
// leg: dead reckoning ends far from the start. One loop closure, the true
// relative pose of the last stop (back at the start) to the first, brings
// it back to within a centimetre.
struct Square {
  std::vector<Pose2> truth;
  PoseGraph graph;
};

Square DriftingSquare() {
  Square square;
  Pose2 pose;
  square.truth.push_back(pose);
  Pose2 odom;
  square.graph.AddNode(odom);
  for (int side = 0; side < 4; ++side) {
    for (int leg = 0; leg < 4; ++leg) {
      const bool corner = leg == 3;
      const Pose2 step(0.5, 0.0, corner ? DegToRad(90.0) : 0.0);
      const Pose2 measured(0.5 * 1.03, 0.0, (corner ? DegToRad(92.0) : 0.0) + DegToRad(0.2));
      pose = pose * step;
      odom = odom * measured;
      square.truth.push_back(pose);
      const int id = square.graph.AddNode(odom);
      square.graph.AddEdge({id - 1, id, measured, Information(0.02, 1.5), EdgeKind::kOdometry});
    }
  }
  return square;
}

TEST(PoseGraphTest, ASquareLoopWithDriftingOdometryClosesToWithinACentimetre) {
  Square square = DriftingSquare();
  const int last = static_cast<int>(square.truth.size()) - 1;
  const Pose2 last_T_first = square.truth[last].Inverse() * square.truth[0];
  const double before =
      (square.graph.pose(last).translation() - square.graph.pose(0).translation()).norm();
  EXPECT_GT(before, 0.2);
  square.graph.AddEdge({last, 0, last_T_first, Information(0.005, 0.5), EdgeKind::kLoopClosure});
  const OptimiseSummary summary = square.graph.Optimise();
  EXPECT_TRUE(summary.converged);
  EXPECT_LT(summary.final_cost, summary.initial_cost);
  EXPECT_EQ(square.graph.pose(0).translation(), Eigen::Vector2d::Zero());  // the anchor stays
  const Eigen::Vector3d closure =
      EdgeError(square.graph.pose(last), square.graph.pose(0), last_T_first);
  EXPECT_LT(closure.head<2>().norm(), 0.01);
  EXPECT_LT(std::abs(closure.z()), DegToRad(1.0));
  // And every stop is nearer the truth than dead reckoning left it.
  double worst = 0.0;
  for (std::size_t i = 0; i < square.truth.size(); ++i) {
    worst = std::max(
        worst, (square.graph.poses()[i].translation() - square.truth[i].translation()).norm());
  }
  EXPECT_LT(worst, before / 2.0);
}

TEST(PoseGraphTest, TheGateRefusesAFalseClosureAndPassesTheTrueOne) {
  const Square square = DriftingSquare();
  const int last = static_cast<int>(square.truth.size()) - 1;
  const Pose2 truth = square.truth[last].Inverse() * square.truth[0];
  const Eigen::Matrix3d info = Information(0.005, 0.5);
  // The drift is within what the odometry's noise model allows.
  EXPECT_LT(square.graph.MahalanobisSquared(last, 0, truth, info), kGate99);
  // A closure onto another place, 1.5 m away: refused.
  const Pose2 wrong = truth * Pose2(1.5, 0.0, 0.0);
  EXPECT_GT(square.graph.MahalanobisSquared(last, 0, wrong, info), kGate99);
  // A neighbouring stop agrees closely with its odometry edge.
  EXPECT_LT(square.graph.MahalanobisSquared(1, 2, Pose2(0.515, 0.0, DegToRad(0.2)), info), 1.0);
}

TEST(PoseGraphTest, ThePredictedCovarianceGrowsAlongTheChainAndAcrossItMostAfterTurning) {
  const Square square = DriftingSquare();
  const Eigen::Matrix3d one = square.graph.PredictedCovariance(0, 1);
  const Eigen::Matrix3d four = square.graph.PredictedCovariance(0, 4);
  EXPECT_NEAR(one(0, 0), 0.02 * 0.02, 1e-12);
  EXPECT_GT(four(0, 0), 3.5 * one(0, 0));
  // Heading error turns into error across the leg: y grows faster than x.
  EXPECT_GT(four(1, 1), four(0, 0));
  // Either way round the heading is as uncertain; seen from the far end the
  // position is more so (the heading's error has the leg's lever arm).
  const Eigen::Matrix3d back = square.graph.PredictedCovariance(4, 0);
  EXPECT_NEAR(back(2, 2), four(2, 2), 1e-12);
  EXPECT_GE(back.trace(), four.trace());
  EXPECT_EQ(square.graph.PredictedCovariance(2, 2), Eigen::Matrix3d::Zero());
}

// A corridor of stops 0.5 m apart with exact odometry, and a false closure
// forced in (the last stop said to be 1 m nearer the first than it is): the
// robust loss keeps it from pulling the stops together as a plain least
// squares edge does.
TEST(PoseGraphTest, TheRobustLossKeepsAForcedFalseClosureFromBendingTheRest) {
  const auto max_shift = [](EdgeKind closure_kind) {
    PoseGraph graph;
    std::vector<Pose2> truth;
    for (int i = 0; i < 12; ++i) {
      truth.emplace_back(0.5 * i, 0.0, 0.0);
      graph.AddNode(truth.back());
      if (i > 0) {
        graph.AddEdge({i - 1, i, Pose2(0.5, 0, 0), Information(0.01, 0.5), EdgeKind::kOdometry});
        graph.AddEdge({i - 1, i, Pose2(0.5, 0, 0), Information(0.01, 0.5), EdgeKind::kScanMatch});
      }
    }
    graph.AddEdge({11, 0, Pose2(-4.5, 0, 0), Information(0.02, 1.0), closure_kind});
    graph.Optimise();
    double shift = 0.0;
    for (int i = 0; i < 12; ++i) {
      shift = std::max(shift, (graph.pose(i).translation() - truth[i].translation()).norm());
    }
    return shift;
  };
  const double plain = max_shift(EdgeKind::kScanMatch);
  const double robust = max_shift(EdgeKind::kLoopClosure);
  EXPECT_GT(plain, 0.5);
  EXPECT_LT(robust, plain / 5.0);
}

}  // namespace
}  // namespace pirouette::localize::pose_graph_test
