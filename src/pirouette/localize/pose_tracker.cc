#include "pirouette/localize/pose_tracker.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "pirouette/core/angle.h"

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
    stop_.clear();
    stop_position_ = predicted.translation();
  }
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

  std::vector<core::Pose2> poses;
  for (const StopFrame& f : stop_) {
    poses.emplace_back(stop_position_.x(), stop_position_.y(), f.heading_rad);
  }
  map_T_odom_ = poses.back() * odom_T_robot.Inverse();
  return poses;
}

}  // namespace pirouette::localize
