#include "pirouette/localize/graph_tracker.h"

#include <Eigen/Cholesky>
#include <Eigen/LU>
#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <unordered_map>
#include <utility>

#include "pirouette/core/angle.h"

namespace pirouette::localize {

void OdometryModel::Check() const {
  if (!(translation_fraction >= 0.0) || !(rotation_fraction >= 0.0) ||
      !std::isfinite(translation_fraction) || !std::isfinite(rotation_fraction) ||
      !(min_translation_m > 0.0) || !(min_rotation_rad > 0.0) ||
      !std::isfinite(min_translation_m) || !std::isfinite(min_rotation_rad)) {
    throw std::invalid_argument(
        "OdometryModel: the fractions must be finite and >= 0, the floors finite and > 0");
  }
}

void GraphTrackerOptions::Check() const {
  odometry.Check();
  stop.Check();
  if (!(match_turn_sigma_rad > 0.0) || !(overlap_range_factor > 0.0) ||
      !(min_response >= 0.0 && min_response <= 1.0) || !(loop_path_m >= 0.0) ||
      !(edge_floor_m > 0.0) || !(edge_floor_rad > 0.0)) {
    throw std::invalid_argument(
        "GraphTrackerOptions: match_turn_sigma_rad, overlap_range_factor and the edge floors "
        "must be > 0, loop_path_m >= 0, min_response in [0, 1]");
  }
}

namespace {

// The stop tracker's options: its matching of a stop's frames only.
TrackerOptions StopOptions(const GraphTrackerOptions& options) {
  TrackerOptions stop = options.stop;
  stop.scan_match_frames = 0;
  stop.min_frames_for_map_turn = std::numeric_limits<std::size_t>::max();
  // The heading match's prior: the odometry's turn error, never quite zero
  // (a match must be able to move a frame by a step).
  constexpr double kMinRotationFraction = 0.01;
  stop.rotation_fraction = std::max(options.odometry.rotation_fraction, kMinRotationFraction);
  return stop;
}

// The rotation of (dx, dy) by θ, the heading untouched: a covariance between
// a frame turned by θ and the map.
Eigen::Matrix3d Rotation(double theta) {
  Eigen::Matrix3d r = Eigen::Matrix3d::Identity();
  r.topLeftCorner<2, 2>() << std::cos(theta), -std::sin(theta), std::sin(theta), std::cos(theta);
  return r;
}

// Whether two poses differ by more than a tenth of a millimetre or a
// hundredth of a degree: what moves a frame's hits by nothing a map shows.
bool Moved(const core::Pose2& a, const core::Pose2& b) {
  constexpr double kMoveM = 1e-4;
  constexpr double kTurnRad = 1.7e-4;
  return (a.translation() - b.translation()).norm() > kMoveM ||
         std::abs(core::NormalizeAngle(a.heading() - b.heading())) > kTurnRad;
}

}  // namespace

GraphTracker::GraphTracker(const GraphTrackerOptions& options)
    : options_(options), stop_((options.Check(), StopOptions(options))) {}

core::Pose2 GraphTracker::ToMap(const core::Pose2& odom_T_robot) const {
  if (stops_.empty()) return odom_T_robot;
  return graph_.pose(static_cast<int>(stops_.size()) - 1) * stops_.back().inner_T_stop.Inverse() *
         stop_.ToMap(odom_T_robot);
}

core::Pose2 GraphTracker::FramePose(std::size_t k) const {
  const Frame& f = frames_.at(k);
  return graph_.pose(f.node) * f.node_T_frame;
}

int GraphTracker::Track(const mapping::OccupancyGrid& map, const core::ObstacleProfile& profile,
                        double map_range_m, const core::Pose2& odom_T_robot) {
  map_range_m_ = map_range_m;
  int moved = -1;
  const bool starts = StartsStop(odom_T_robot);
  const double step_turn =
      frames_.empty()
          ? 0.0
          : std::abs(core::NormalizeAngle(odom_T_robot.heading() - last_odom_.heading()));
  if (starts && !stops_.empty() && !stops_.back().matched) {
    moved = MatchAndOptimise(static_cast<int>(stops_.size()) - 1);
  }
  if (starts && !stops_.empty()) {
    const int last = static_cast<int>(stops_.size()) - 1;
    stops_.back().hits = HitsOf(last);
    ReleaseProfiles(last);
  }
  const int accepted_before = stop_.accepted();
  const std::vector<core::Pose2> inner = stop_.Track(map, profile, map_range_m, odom_T_robot);
  // A turn the stop's heading match corrected leaves the match's error; one
  // it did not, the odometry's.
  if (!starts) {
    turn_rad_ += step_turn;
    if (stop_.accepted() > accepted_before) {
      ++matched_turns_;
    } else {
      unmatched_turn_rad_ += step_turn;
    }
  } else {
    turn_rad_ += step_turn;
    unmatched_turn_rad_ += step_turn;
  }
  last_odom_ = odom_T_robot;
  if (starts) {
    Stop stop;
    stop.inner_T_stop = inner.back();
    stop.odom_T_stop = odom_T_robot;
    stop.first_frame = frames_.size();
    if (stops_.empty()) {
      graph_.AddNode(stop.inner_T_stop);
    } else {
      const int before = static_cast<int>(stops_.size()) - 1;
      const core::Pose2 step = AddOdometryEdge(before + 1, stop);
      graph_.AddNode(graph_.pose(before) * step);
      stop.path_m = stops_.back().path_m + step.translation().norm();
      graph_.AddEdge(pending_odometry_);
    }
    matched_turns_ = 0;
    unmatched_turn_rad_ = 0.0;
    turn_rad_ = 0.0;
    stops_.push_back(std::move(stop));
  }
  const int node = static_cast<int>(stops_.size()) - 1;
  frames_.push_back({node, core::Pose2(), profile});
  // The stop's frames in its frame (the stop tracker turns the new one only,
  // but says them all).
  const Stop& stop = stops_.back();
  for (std::size_t i = 0; i < inner.size(); ++i) {
    frames_[stop.first_frame + i].node_T_frame = stop.inner_T_stop.Inverse() * inner[i];
  }
  const std::size_t match_frames = options_.stop.scan_match_frames;
  if (match_frames > 0 && inner.size() == match_frames && !stops_.back().matched) {
    const int m = MatchAndOptimise(node);
    if (m >= 0) moved = moved < 0 ? m : std::min(moved, m);
  }
  return moved;
}

int GraphTracker::Finish() {
  if (stops_.empty() || stops_.back().matched) return -1;
  const int node = static_cast<int>(stops_.size()) - 1;
  const int moved = MatchAndOptimise(node);
  stops_.back().hits = HitsOf(node);
  return moved;
}

void GraphTracker::ReleaseProfiles(int node) {
  const Stop& stop = stops_.at(static_cast<std::size_t>(node));
  for (std::size_t k = stop.first_frame; k < frames_.size() && frames_[k].node == node; ++k) {
    frames_[k].profile = core::ObstacleProfile();
  }
}

std::vector<Eigen::Vector2d> GraphTracker::HitsOf(int node) const {
  const Stop& stop = stops_.at(static_cast<std::size_t>(node));
  std::vector<HeadedView> views;
  for (std::size_t k = stop.first_frame; k < frames_.size() && frames_[k].node == node; ++k) {
    views.push_back({&frames_[k].profile, frames_[k].node_T_frame.heading()});
  }
  return NearestHitEachDegree(views, options_.stop.hit_range_factor * map_range_m_);
}

core::Pose2 GraphTracker::AddOdometryEdge(int to, const Stop& stop) {
  const OdometryModel& m = options_.odometry;
  const Stop& last = stops_.back();
  // Two measures of the step from the last stop: the odometry's own, and the
  // stop tracker's, whose headings the stop's heading matches corrected.
  // Each heading's variance: the odometry's error on every turn since the
  // last stop (vo), or on the turns no match corrected and a match's error
  // on those it did (vm); the step is their inverse-variance blend, so a
  // perfect odometry (the noise-free simulator) keeps its own step and a
  // noisy one takes the matches'.
  const core::Pose2 by_odometry = last.odom_T_stop.Inverse() * stop.odom_T_stop;
  const core::Pose2 by_matches = last.inner_T_stop.Inverse() * stop.inner_T_stop;
  const double floor_var = m.min_rotation_rad * m.min_rotation_rad;
  const double vo = std::pow(m.rotation_fraction * turn_rad_, 2) + floor_var;
  const double vm = std::pow(m.rotation_fraction * unmatched_turn_rad_, 2) +
                    matched_turns_ * options_.match_turn_sigma_rad * options_.match_turn_sigma_rad +
                    floor_var;
  const double w = vo / (vo + vm);  // the matches' weight
  const Eigen::Vector2d t =
      by_odometry.translation() + w * (by_matches.translation() - by_odometry.translation());
  const double heading = by_odometry.heading() +
                         w * core::NormalizeAngle(by_matches.heading() - by_odometry.heading());
  core::Pose2 step(t.x(), t.y(), heading);
  const double heading_var = vo * vm / (vo + vm);
  // The position: the move's own error along it, and the heading's error
  // swung over its length across it (isotropic: the larger of the two each way).
  const double d = t.norm();
  const double position_var = std::pow(m.translation_fraction * d, 2) + d * d * heading_var +
                              m.min_translation_m * m.min_translation_m;
  Eigen::Matrix3d covariance = Eigen::Matrix3d::Zero();
  covariance(0, 0) = covariance(1, 1) = position_var;
  covariance(2, 2) = heading_var;
  pending_odometry_ = {to - 1, to, step, covariance.inverse(), EdgeKind::kOdometry};
  position_variance_ += position_var;
  heading_variance_ += heading_var;
  return step;
}

int GraphTracker::AgreeingStop(const HitStore& reference, const std::vector<PlacedHit>& placed,
                               int to, const core::Pose2& map_T_to) const {
  // Which reference stops have a hit in each cell: (cell, stop) pairs,
  // sorted (a hash map of vectors cost as much as the match's own store).
  std::vector<std::pair<std::int64_t, int>> owners;
  owners.reserve(placed.size());
  for (const PlacedHit& h : placed) {
    owners.emplace_back(HitStore::KeyOf(reference.CellOf(h.p_map)), h.stop);
  }
  std::sort(owners.begin(), owners.end());
  owners.erase(std::unique(owners.begin(), owners.end()), owners.end());
  const double cell = reference.cell_m();
  const int reach = static_cast<int>(std::ceil(options_.stop.scan.sigma_m / cell));
  std::unordered_map<int, int> agreeing;
  std::vector<int> near;
  for (const Eigen::Vector2d& q : stops_[static_cast<std::size_t>(to)].hits) {
    const Eigen::Vector2i c = reference.CellOf(map_T_to * q);
    near.clear();
    for (int dx = -reach; dx <= reach; ++dx) {
      for (int dy = -reach; dy <= reach; ++dy) {
        const std::int64_t k = HitStore::KeyOf(c + Eigen::Vector2i(dx, dy));
        auto it = std::lower_bound(owners.begin(), owners.end(),
                                   std::make_pair(k, std::numeric_limits<int>::min()));
        for (; it != owners.end() && it->first == k; ++it) {
          if (std::find(near.begin(), near.end(), it->second) == near.end()) {
            near.push_back(it->second);
          }
        }
      }
    }
    for (const int j : near) ++agreeing[j];
  }
  int best = -1;
  int most = 0;
  for (const auto& [j, n] : agreeing) {
    if (n > most || (n == most && j > best)) {
      best = j;
      most = n;
    }
  }
  return best;
}

std::optional<PoseGraphEdge> GraphTracker::MatchStop(int nearest,
                                                     const std::vector<int>& references, int to,
                                                     const Eigen::Matrix3d& prior) {
  const core::Pose2& map_T_to = graph_.pose(to);
  // No overlap asked at the prior's mean (a drive's error may have moved
  // every hit off there): the response at the best correction decides.
  ScanMatchOptions scan = options_.stop.scan;
  scan.min_overlap = 0;
  HitStore reference(scan.cell_m);
  std::vector<PlacedHit> placed;  // the same hits with their stops, for AgreeingStop
  for (const int j : references) {
    const core::Pose2& map_T_j = graph_.pose(j);
    for (const Eigen::Vector2d& q : stops_[static_cast<std::size_t>(j)].hits) {
      placed.push_back({map_T_j * q, j});
      reference.Add(placed.back().p_map);
    }
  }
  std::vector<Eigen::Vector2d> offsets;
  const Eigen::Matrix2d r_to = Rotation(map_T_to.heading()).topLeftCorner<2, 2>();
  for (const Eigen::Vector2d& q : stops_[static_cast<std::size_t>(to)].hits) {
    offsets.emplace_back(r_to * q);
  }
  if (offsets.empty() || reference.size() == 0) return std::nullopt;
  const ScanMatch match = MatchScan(reference, map_T_to.translation(), offsets, prior, scan);
  if (!match.accepted || match.response < options_.min_response) return std::nullopt;
  // The match's own measurement (its likelihood, not the prior the graph's
  // odometry edges already hold), in `from`'s frame.
  const Eigen::Vector3d& o = match.likelihood_offset;
  const core::Pose2 corrected(map_T_to.x() + o.x(), map_T_to.y() + o.y(),
                              map_T_to.heading() + o.z());
  const int agreeing = AgreeingStop(reference, placed, to, corrected);
  const int from = agreeing >= 0 ? agreeing : nearest;
  const bool loop =
      stops_[static_cast<std::size_t>(to)].path_m - stops_[static_cast<std::size_t>(from)].path_m >
      options_.loop_path_m;
  const core::Pose2& map_T_from = graph_.pose(from);
  Eigen::Matrix3d covariance = match.likelihood_covariance;
  covariance(0, 0) += options_.edge_floor_m * options_.edge_floor_m;
  covariance(1, 1) += options_.edge_floor_m * options_.edge_floor_m;
  covariance(2, 2) += options_.edge_floor_rad * options_.edge_floor_rad;
  const Eigen::Matrix3d r_from = Rotation(map_T_from.heading());
  covariance = r_from.transpose() * covariance * r_from;
  Eigen::Matrix3d information = covariance.inverse();
  information = 0.5 * (information + information.transpose());
  const PoseGraphEdge edge{from, to, map_T_from.Inverse() * corrected, information,
                           loop ? EdgeKind::kLoopClosure : EdgeKind::kScanMatch};
  if (loop) {
    if (graph_.MahalanobisSquared(from, to, edge.from_T_to, information) > kGate99) {
      ++loops_rejected_;
      return std::nullopt;
    }
    ++loops_accepted_;
  }
  // The stop is now known relative to the map around it as well as the match says.
  position_variance_ = 0.5 * (match.covariance(0, 0) + match.covariance(1, 1));
  heading_variance_ = match.covariance(2, 2);
  return edge;
}

int GraphTracker::MatchAndOptimise(int node) {
  const auto start = std::chrono::steady_clock::now();
  Stop& stop = stops_[static_cast<std::size_t>(node)];
  stop.matched = true;
  stop.hits = HitsOf(node);
  int moved = -1;
  // The earlier stops whose views may overlap this one's, as one local map;
  // the edge from the nearest of them.
  const double reach = OverlapReachM();
  const Eigen::Vector2d here = graph_.pose(node).translation();
  std::vector<int> references;
  int nearest = -1;
  double nearest_m = std::numeric_limits<double>::infinity();
  for (int j = 0; j < node && !stop.hits.empty(); ++j) {
    const double d = (graph_.pose(j).translation() - here).norm();
    if (d > reach || stops_[static_cast<std::size_t>(j)].hits.empty()) continue;
    references.push_back(j);
    if (d < nearest_m) {
      nearest_m = d;
      nearest = j;
    }
  }
  if (nearest >= 0) {
    // The prior: the odometry's error since the last accepted match (the
    // heading's never under the scan tracker's heading prior).
    const double cell = options_.stop.scan.cell_m;
    Eigen::Matrix3d prior = Eigen::Matrix3d::Zero();
    prior(0, 0) = prior(1, 1) = std::max(position_variance_, cell * cell);
    prior(2, 2) = std::max(heading_variance_, std::pow(options_.stop.heading_prior_rad, 2));
    if (const auto edge = MatchStop(nearest, references, node, prior)) {
      ++scan_matches_;
      graph_.AddEdge(*edge);
      const std::vector<core::Pose2> before = graph_.poses();
      const auto opt_start = std::chrono::steady_clock::now();
      graph_.Optimise(options_.optimiser);
      optimise_s_ +=
          std::chrono::duration<double>(std::chrono::steady_clock::now() - opt_start).count();
      for (std::size_t i = 0; i < before.size(); ++i) {
        if (Moved(before[i], graph_.poses()[i])) {
          moved = static_cast<int>(i);
          break;
        }
      }
    }
  }
  per_stop_s_.push_back(
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  return moved;
}

}  // namespace pirouette::localize
