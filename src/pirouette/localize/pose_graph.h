#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <vector>

#include "pirouette/core/pose2.h"

namespace pirouette::localize {

// The χ² quantile of 3 degrees of freedom at 99%: the Mahalanobis gate.
inline constexpr double kGate99 = 11.345;

// Where an edge of the pose graph comes from.
enum class EdgeKind { kOdometry, kScanMatch, kLoopClosure };

// A measured relative pose between two stops: `to` seen from `from`
// (from_T_to), with the information matrix (the inverse covariance) of the
// measurement in (dx, dy, dθ), the translation in `from`'s frame.
struct PoseGraphEdge {
  int from = 0;
  int to = 0;
  core::Pose2 from_T_to;
  Eigen::Matrix3d information = Eigen::Matrix3d::Identity();
  EdgeKind kind = EdgeKind::kOdometry;
};

// The residual of one edge at the poses a and b: the measured relative pose's
// error, (R(θa)ᵀ (t_b − t_a) − t_ab, wrap(θb − θa − θab)), as Ceres'
// pose_graph_2d example (after Olson et al. 2006) writes it; unweighted.
Eigen::Vector3d EdgeError(const core::Pose2& world_T_a, const core::Pose2& world_T_b,
                          const core::Pose2& a_T_b);

struct PoseGraphOptions {
  // Loop-closure edges are weighted by a Huber loss of this scale (in units
  // of the whitened residual, i.e. standard deviations): beyond it an error
  // grows linearly, so that one false closure cannot bend the map
  // (Huber 1964; the robust kernels of g2o and Ceres).
  double loop_closure_huber = 1.0;
  // The same for scan-match edges (0: none, plain least squares).
  double scan_match_huber = 0.0;
  int max_iterations = 50;
};

struct OptimiseSummary {
  bool converged = false;
  int iterations = 0;
  double initial_cost = 0.0;
  double final_cost = 0.0;
};

// A pose graph over the robot's stops (Lu & Milios 1997; Grisetti et al.,
// "A tutorial on graph-based SLAM", 2010): a node a stop, holding its pose in
// the map frame, an edge a measured relative pose. Optimise() moves the
// nodes (the first stays fixed: it anchors the map frame) to the least
// squares of the whitened edge errors, with Ceres (sparse Cholesky; angles
// on the circle through a manifold).
class PoseGraph {
 public:
  // Adds a node at `map_T_stop` (its initial estimate); returns its id
  // (0, 1, 2, ... in order).
  int AddNode(const core::Pose2& map_T_stop);
  // Throws std::invalid_argument unless both ends are nodes, they differ and
  // the information matrix is symmetric positive definite.
  void AddEdge(const PoseGraphEdge& edge);

  std::size_t NodeCount() const { return poses_.size(); }
  const std::vector<core::Pose2>& poses() const { return poses_; }
  const core::Pose2& pose(int id) const { return poses_.at(static_cast<std::size_t>(id)); }
  const std::vector<PoseGraphEdge>& edges() const { return edges_; }

  // The covariance of the relative pose from_T_to as the odometry chain
  // between the two predicts it: the odometry edges k → k+1 between them
  // compounded to first order (Smith, Self & Cheeseman 1990), in `from`'s
  // frame at the current poses. Zero where the chain is broken or from == to.
  Eigen::Matrix3d PredictedCovariance(int from, int to) const;

  // The squared Mahalanobis distance between a measured from_T_to (with its
  // information) and what the graph predicts: eᵀ (Σ_pred + Ω⁻¹)⁻¹ e, e the
  // EdgeError at the current poses, Σ_pred PredictedCovariance. A loop
  // closure whose distance exceeds the χ² quantile of 3 degrees of freedom
  // (kGate99: 11.34 at 99%) disagrees with the graph's own prediction.
  // Throws std::out_of_range for an id that is no node.
  double MahalanobisSquared(int from, int to, const core::Pose2& from_T_to,
                            const Eigen::Matrix3d& information) const;

  // Optimises every node but the first from the current estimates.
  OptimiseSummary Optimise(const PoseGraphOptions& options = {});

 private:
  std::vector<core::Pose2> poses_;
  std::vector<PoseGraphEdge> edges_;
  // odometry_of_[k]: the index in edges_ of the first odometry edge k → k+1, or -1.
  std::vector<int> odometry_of_;
};

}  // namespace pirouette::localize
