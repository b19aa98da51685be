#include "pirouette/localize/pose_tracker.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "pirouette/core/angle.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::localize {

void TrackerOptions::Check() const {
  if (!(rotation_fraction > 0.0) || !(same_stop_m >= 0.0) || !(map_turn_steps >= 0.0) ||
      !(view_range_factor >= 1.0) || !(map_turn_range_factor >= 1.0) ||
      !(map_turn_range_factor <= view_range_factor)) {
    throw std::invalid_argument(
        "TrackerOptions: rotation_fraction must be > 0, same_stop_m and map_turn_steps >= 0, "
        "view_range_factor >= 1, map_turn_range_factor in [1, view_range_factor]");
  }
  heading.Check();
  scan.Check();
  if (!(hit_range_factor >= 1.0) || !(translation_fraction >= 0.0) || !(heading_prior_rad > 0.0)) {
    throw std::invalid_argument(
        "TrackerOptions: hit_range_factor must be >= 1, translation_fraction >= 0, "
        "heading_prior_rad > 0");
  }
}

PoseTracker::PoseTracker(const TrackerOptions& options)
    : options_(options), hits_(options.scan.cell_m) {
  options_.Check();
}

bool PoseTracker::StartsStop(const core::Pose2& odom_T_robot) const {
  return stop_.empty() || (odom_T_robot.translation() - stop_.back().odom.translation()).norm() >
                              options_.same_stop_m;
}

namespace {

// The profile out to max_range_m: readings beyond it read clear there.
core::ObstacleProfile Within(core::ObstacleProfile profile, double max_range_m) {
  for (core::RangeReading& r : profile.readings) {
    if (r.kind != core::ReadingKind::kBlind && r.range_m > max_range_m) {
      r.kind = core::ReadingKind::kClear;
      r.range_m = max_range_m;
    }
  }
  profile.max_range_m = max_range_m;
  return profile;
}

}  // namespace

std::vector<core::Pose2> PoseTracker::Track(const mapping::OccupancyGrid& before,
                                            const core::ObstacleProfile& profile,
                                            double map_range_m, const core::Pose2& odom_T_robot) {
  ++matches_;
  const core::Pose2 predicted = ToMap(odom_T_robot);
  const bool starts = StartsStop(odom_T_robot);
  // How far the robot turned since the stop's frame before.
  const double turned =
      starts ? 0.0
             : std::abs(core::NormalizeAngle(odom_T_robot.heading() - stop_.back().odom.heading()));
  if (starts) {
    AddStopHits();
    if (!stop_.empty()) {  // the first stop moved from nowhere
      const Eigen::Vector2d moved = predicted.translation() - stop_position_;
      position_variance_ += std::pow(options_.translation_fraction * moved.norm(), 2);
    }
    stop_.clear();
    stop_position_ = predicted.translation();
  }
  map_range_m_ = map_range_m;
  // The map turn's range: map_turn_range_factor times the map's, or as far
  // as the profile was read if that is less (never less than the map's).
  const double turn_range_m = std::max(
      map_range_m, std::min(map_range_m * options_.map_turn_range_factor, profile.max_range_m));
  StopFrame frame{profile, Within(profile, turn_range_m), odom_T_robot, predicted.heading()};

  // The new frame's heading relative to the stop's earlier frames (odometry
  // says how far it turned, within rotation_fraction): its readings against
  // theirs along the same bearings.
  if (!starts) {
    const double sigma = options_.heading.step_rad + options_.rotation_fraction * turned;
    std::vector<HeadedView> views;
    for (const StopFrame& f : stop_) views.push_back({&f.profile, f.heading_rad});
    const HeadingMatch turn =
        MatchToViews(views, profile, frame.heading_rad, sigma, options_.heading);
    frame.heading_rad += turn.offset_rad;
    if (turn.accepted) ++accepted_;
  }
  stop_.push_back(std::move(frame));

  // Once the stop has looked a good part of the way round (4 frames or
  // more), all its frames together take a small common turn against the map
  // as it was before the stop, its readings along their bearings from the
  // stop's position.
  if (stop_.size() >= options_.min_frames_for_map_turn) {
    core::ObstacleProfile all;
    all.max_range_m = turn_range_m;
    const double reference = stop_.front().heading_rad;
    for (const StopFrame& f : stop_) {
      for (core::RangeReading r : f.map_profile.readings) {
        r.bearing_rad += f.heading_rad - reference;
        all.readings.push_back(r);
      }
    }
    const MapProfile map(before, stop_position_, turn_range_m);
    const HeadingMatch turn = MatchHeading(
        map, all, reference, options_.map_turn_steps * options_.heading.step_rad, options_.heading);
    for (StopFrame& f : stop_) f.heading_rad += turn.offset_rad;
  }

  if (options_.scan_match_frames > 0 && stop_.size() == options_.scan_match_frames) MatchStop();

  std::vector<core::Pose2> poses;
  for (const StopFrame& f : stop_) {
    poses.emplace_back(stop_position_.x(), stop_position_.y(), f.heading_rad);
  }
  map_T_odom_ = poses.back() * odom_T_robot.Inverse();
  return poses;
}

std::vector<Eigen::Vector2d> NearestHitEachDegree(const std::vector<HeadedView>& views,
                                                  double max_range_m) {
  // The ROP's bins: the frames overlap, and a bearing's nearest hit is the
  // one the others hide behind.
  constexpr int kBins = mapping::kRadialProfileBins;
  std::vector<Eigen::Vector2d> nearest(kBins, Eigen::Vector2d::Zero());
  std::vector<double> range(kBins, std::numeric_limits<double>::infinity());
  for (const HeadedView& view : views) {
    for (const core::RangeReading& r : view.profile->readings) {
      if (r.kind != core::ReadingKind::kHit || r.range_m > max_range_m) continue;
      const double bearing = core::NormalizeAngle(view.heading_rad + r.bearing_rad);
      const int bin = std::clamp(static_cast<int>(std::floor((bearing + std::numbers::pi) /
                                                             (2.0 * std::numbers::pi) * kBins)),
                                 0, kBins - 1);
      if (r.range_m < range[bin]) {
        range[bin] = r.range_m;
        nearest[bin] = r.range_m * Eigen::Vector2d(std::cos(bearing), std::sin(bearing));
      }
    }
  }
  std::vector<Eigen::Vector2d> out;
  for (int b = 0; b < kBins; ++b) {
    if (std::isfinite(range[b])) out.push_back(nearest[b]);
  }
  return out;
}

std::vector<Eigen::Vector2d> PoseTracker::StopHits() const {
  std::vector<HeadedView> views;
  for (const StopFrame& f : stop_) views.push_back({&f.profile, f.heading_rad});
  return NearestHitEachDegree(views, options_.hit_range_factor * map_range_m_);
}

void PoseTracker::AddStopHits() {
  for (const Eigen::Vector2d& q : StopHits()) hits_.Add(stop_position_ + q);
}

void PoseTracker::MatchStop() {
  Eigen::Matrix3d prior = Eigen::Matrix3d::Zero();
  prior(0, 0) = prior(1, 1) = std::max(position_variance_, std::pow(options_.scan.cell_m, 2));
  prior(2, 2) = std::pow(options_.heading_prior_rad, 2);
  const ScanMatch match = MatchScan(hits_, stop_position_, StopHits(), prior, options_.scan);
  if (!match.accepted) return;
  ++scan_matches_;
  stop_position_ += match.offset.head<2>();
  for (StopFrame& f : stop_) f.heading_rad += match.offset.z();
  position_variance_ = std::max(0.5 * (match.covariance(0, 0) + match.covariance(1, 1)), 0.0);
}

}  // namespace pirouette::localize
