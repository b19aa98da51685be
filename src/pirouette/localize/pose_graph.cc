#include "pirouette/localize/pose_graph.h"

#include <ceres/ceres.h>

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <array>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <utility>

#include "pirouette/core/angle.h"

namespace pirouette::localize {
namespace {

// θ wrapped into [-π, π), for Jets too.
template <typename T>
T WrapAngle(const T& angle) {
  const T two_pi(2.0 * M_PI);
  return angle - two_pi * ceres::floor((angle + T(M_PI)) / two_pi);
}

// The error of one edge, whitened by the square root of its information
// (upper Cholesky factor Lᵀ, so that rᵀr = eᵀ Ω e).
class EdgeResidual {
 public:
  EdgeResidual(const core::Pose2& a_T_b, Eigen::Matrix3d sqrt_information)
      : x_(a_T_b.x()),
        y_(a_T_b.y()),
        theta_(a_T_b.heading()),
        sqrt_information_(std::move(sqrt_information)) {}

  template <typename T>
  bool operator()(const T* a_xy, const T* a_theta, const T* b_xy, const T* b_theta,
                  T* residual) const {
    const T c = ceres::cos(*a_theta);
    const T s = ceres::sin(*a_theta);
    const T dx = b_xy[0] - a_xy[0];
    const T dy = b_xy[1] - a_xy[1];
    Eigen::Matrix<T, 3, 1> e;
    e(0) = c * dx + s * dy - T(x_);
    e(1) = -s * dx + c * dy - T(y_);
    e(2) = WrapAngle(*b_theta - *a_theta - T(theta_));
    const Eigen::Matrix<T, 3, 1> r = sqrt_information_.template cast<T>() * e;
    residual[0] = r(0);
    residual[1] = r(1);
    residual[2] = r(2);
    return true;
  }

 private:
  double x_;
  double y_;
  double theta_;
  Eigen::Matrix3d sqrt_information_;
};

// An angle on the circle: x ⊞ δ = wrap(x + δ), y ⊟ x = wrap(y - x).
struct AngleOnCircle {
  template <typename T>
  bool Plus(const T* x, const T* delta, T* x_plus_delta) const {
    *x_plus_delta = WrapAngle(*x + *delta);
    return true;
  }
  template <typename T>
  bool Minus(const T* y, const T* x, T* y_minus_x) const {
    *y_minus_x = WrapAngle(*y - *x);
    return true;
  }
};

}  // namespace

Eigen::Vector3d EdgeError(const core::Pose2& world_T_a, const core::Pose2& world_T_b,
                          const core::Pose2& a_T_b) {
  const Eigen::Vector2d d = world_T_b.translation() - world_T_a.translation();
  const double c = std::cos(world_T_a.heading());
  const double s = std::sin(world_T_a.heading());
  return {c * d.x() + s * d.y() - a_T_b.x(), -s * d.x() + c * d.y() - a_T_b.y(),
          core::NormalizeAngle(world_T_b.heading() - world_T_a.heading() - a_T_b.heading())};
}

int PoseGraph::AddNode(const core::Pose2& map_T_stop) {
  poses_.push_back(map_T_stop);
  return static_cast<int>(poses_.size()) - 1;
}

void PoseGraph::AddEdge(const PoseGraphEdge& edge) {
  const int n = static_cast<int>(poses_.size());
  if (edge.from < 0 || edge.to < 0 || edge.from >= n || edge.to >= n) {
    throw std::invalid_argument("PoseGraph::AddEdge: edge " + std::to_string(edge.from) + " -> " +
                                std::to_string(edge.to) + " names a node the graph lacks");
  }
  if (edge.from == edge.to) throw std::invalid_argument("PoseGraph::AddEdge: a loop on one node");
  const Eigen::Matrix3d& info = edge.information;
  if (!info.allFinite() || !info.isApprox(info.transpose(), 1e-9) ||
      Eigen::LLT<Eigen::Matrix3d>(info).info() != Eigen::Success) {
    throw std::invalid_argument(
        "PoseGraph::AddEdge: information is not symmetric positive definite");
  }
  if (edge.kind == EdgeKind::kOdometry && edge.to == edge.from + 1) {
    const auto k = static_cast<std::size_t>(edge.from);
    if (odometry_of_.size() <= k) odometry_of_.resize(k + 1, -1);
    if (odometry_of_[k] < 0) odometry_of_[k] = static_cast<int>(edges_.size());
  }
  edges_.push_back(edge);
}

Eigen::Matrix3d PoseGraph::PredictedCovariance(int from, int to) const {
  const int lo = std::min(from, to);
  const int hi = std::max(from, to);
  // lo_T_k and its covariance, k from lo to hi.
  core::Pose2 p;
  Eigen::Matrix3d sigma = Eigen::Matrix3d::Zero();
  for (int k = lo; k < hi; ++k) {
    const auto index = static_cast<std::size_t>(k);
    if (index >= odometry_of_.size() || odometry_of_[index] < 0) return Eigen::Matrix3d::Zero();
    const PoseGraphEdge* edge = &edges_[static_cast<std::size_t>(odometry_of_[index])];
    // The step at the current poses, with the measurement's covariance.
    const core::Pose2 step = pose(k).Inverse() * pose(k + 1);
    const double c = std::cos(p.heading());
    const double s = std::sin(p.heading());
    Eigen::Matrix3d j_p;
    j_p << 1, 0, -s * step.x() - c * step.y(), 0, 1, c * step.x() - s * step.y(), 0, 0, 1;
    Eigen::Matrix3d j_e;
    j_e << c, -s, 0, s, c, 0, 0, 0, 1;
    sigma = j_p * sigma * j_p.transpose() + j_e * edge->information.inverse() * j_e.transpose();
    p = p * step;
  }
  if (from <= to) return sigma;
  // from_T_to = (to_T_from)⁻¹, and to_T_from = lo_T_hi = p: the inverse's Jacobian at p.
  const double c = std::cos(p.heading());
  const double s = std::sin(p.heading());
  Eigen::Matrix3d j;
  j << -c, -s, s * p.x() - c * p.y(), s, -c, c * p.x() + s * p.y(), 0, 0, -1;
  return j * sigma * j.transpose();
}

double PoseGraph::MahalanobisSquared(int from, int to, const core::Pose2& from_T_to,
                                     const Eigen::Matrix3d& information) const {
  const Eigen::Vector3d e = EdgeError(poses_.at(static_cast<std::size_t>(from)),
                                      poses_.at(static_cast<std::size_t>(to)), from_T_to);
  const Eigen::Matrix3d sigma = PredictedCovariance(from, to) + information.inverse();
  return e.dot(sigma.ldlt().solve(e));
}

OptimiseSummary PoseGraph::Optimise(const PoseGraphOptions& options) {
  OptimiseSummary summary;
  if (poses_.size() < 2 || edges_.empty()) {
    summary.converged = true;
    return summary;
  }
  // Ceres optimises plain arrays: a node's position and heading apart, so
  // that the heading alone lives on the circle.
  std::vector<std::array<double, 2>> xy(poses_.size());
  std::vector<double> theta(poses_.size());
  for (std::size_t i = 0; i < poses_.size(); ++i) {
    xy[i] = {poses_[i].x(), poses_[i].y()};
    theta[i] = poses_[i].heading();
  }
  ceres::Problem problem;
  for (const PoseGraphEdge& edge : edges_) {
    // Ω = L Lᵀ; the whitening matrix is Lᵀ.
    const Eigen::Matrix3d sqrt_information =
        Eigen::LLT<Eigen::Matrix3d>(edge.information).matrixL().transpose();
    auto* cost = new ceres::AutoDiffCostFunction<EdgeResidual, 3, 2, 1, 2, 1>(
        new EdgeResidual(edge.from_T_to, sqrt_information));
    ceres::LossFunction* loss = nullptr;
    if (edge.kind == EdgeKind::kLoopClosure) {
      loss = new ceres::HuberLoss(options.loop_closure_huber);
    } else if (edge.kind == EdgeKind::kScanMatch && options.scan_match_huber > 0.0) {
      loss = new ceres::HuberLoss(options.scan_match_huber);
    }
    const auto a = static_cast<std::size_t>(edge.from);
    const auto b = static_cast<std::size_t>(edge.to);
    problem.AddResidualBlock(cost, loss, xy[a].data(), &theta[a], xy[b].data(), &theta[b]);
  }
  for (std::size_t i = 0; i < poses_.size(); ++i) {
    if (!problem.HasParameterBlock(&theta[i])) continue;
    problem.SetManifold(&theta[i], new ceres::AutoDiffManifold<AngleOnCircle, 1, 1>);
  }
  // The first node anchors the map frame.
  if (problem.HasParameterBlock(xy[0].data())) {
    problem.SetParameterBlockConstant(xy[0].data());
    problem.SetParameterBlockConstant(&theta[0]);
  }
  ceres::Solver::Options solver;
  solver.linear_solver_type = ceres::SPARSE_NORMAL_CHOLESKY;
  solver.max_num_iterations = options.max_iterations;
  solver.num_threads = 1;
  solver.logging_type = ceres::SILENT;
  ceres::Solver::Summary result;
  ceres::Solve(solver, &problem, &result);
  for (std::size_t i = 0; i < poses_.size(); ++i) poses_[i] = {xy[i][0], xy[i][1], theta[i]};
  summary.converged = result.termination_type == ceres::CONVERGENCE;
  summary.iterations = static_cast<int>(result.iterations.size());
  summary.initial_cost = result.initial_cost;
  summary.final_cost = result.final_cost;
  return summary;
}

}  // namespace pirouette::localize
