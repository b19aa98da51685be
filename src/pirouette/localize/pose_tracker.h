#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <numbers>
#include <vector>

#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/localize/heading_matcher.h"
#include "pirouette/localize/scan_matcher.h"
#include "pirouette/mapping/occupancy_grid.h"

namespace pirouette::localize {

// What the tracker assumes of the odometry, and how it matches.
struct TrackerOptions {
  // The standard deviation of a turn's error as a fraction of its angle (a
  // real robot's is unknown; this is generous): the prior of each frame's
  // heading relative to the frame before.
  double rotation_fraction = 0.08;
  // Frames whose odometry positions are closer than this share a stop.
  double same_stop_m = 0.001;
  // From its this-many-th frame on, at every frame, a stop takes a common
  // turn against the map before it, each within ±3 × map_turn_steps angular
  // steps of where the last one left it.
  std::size_t min_frames_for_map_turn = 4;
  double map_turn_steps = 2.0;
  // The stop's frames are matched with each other out to this many times
  // the map's range (FrameMapper reads a second, longer profile of each
  // frame for it): with the map's range (0.41 m for the paper's robot) most
  // views of open floor read clear all round and tell no heading, while the
  // walls beyond tell it well. Two frames from one place see a far wall at
  // the same image rows, so the long range's coarse resolution does not
  // bias their match.
  // For the paper's camera 3 × 0.41 m lies beyond what the image's centre
  // columns see at their top row (1.10 m, camera::FloorSeenInEveryColumn),
  // so a wall between the two reads clear there; reading no farther
  // (camera::LongRange, as place recognition does) tracks worse
  // (docs/measurements.md, "Pose tracking").
  double view_range_factor = 3.0;
  // The stop's common turn against the map reads the stop's frames and the
  // map out to this many times the map's range (1 to view_range_factor):
  // the walls beyond the map's range, where the map has seen them, fix the
  // heading better than the near floor. Against 1 (docs/measurements.md,
  // "Pose tracking"): under 5% odometry noise the mean heading error falls
  // in every shipped world and false_free in three of five; without noise
  // false_free falls in four of five.
  double map_turn_range_factor = 3.0;
  HeadingMatcherOptions heading;
  // When a stop has this many frames (a whole pirouette), its position and
  // heading are matched against the hits of the stops before it (MatchScan),
  // read out to hit_range_factor times the map's range; 0 turns it off.
  std::size_t scan_match_frames = 12;
  double hit_range_factor = 2.0;
  // The scan match's prior: the position's standard deviation grows by this
  // fraction of each move (and shrinks to the match's posterior after each),
  // the heading's is heading_prior_rad (the stop's frames have already been
  // turned against the map: what is left is small). 3° against 1.5° and 5°
  // (docs/measurements.md, "Pose tracking"): 1.5° leaves heading error the
  // match could see.
  double translation_fraction = 0.08;
  double heading_prior_rad = 3.0 * std::numbers::pi / 180.0;
  ScanMatchOptions scan;

  // Throws std::invalid_argument unless rotation_fraction > 0, same_stop_m
  // >= 0, map_turn_steps >= 0, view_range_factor >= 1,
  // 1 <= map_turn_range_factor <= view_range_factor, hit_range_factor >= 1,
  // translation_fraction >= 0, heading_prior_rad > 0, and heading.Check()
  // and scan.Check() pass.
  void Check() const;
};

// A stop's hits from its frames' profiles (each turned by its heading), out
// to max_range_m: the nearest hit in each degree of bearing around the stop
// (mapping::kRadialProfileBins bins), as offsets from the stop's position.
std::vector<Eigen::Vector2d> NearestHitEachDegree(const std::vector<HeadedView>& views,
                                                  double max_range_m);

// Pose tracking by matching what the camera sees against what it saw, a
// stop at a time (Taylor, Geva & Boles 2005 name localization as the next
// step). The robot looks only while it stands (a
// pirouette, a look before a move) and turns on the spot between the frames
// of a stop, so they share its position and differ in heading alone: each
// new frame's heading relative to the stop's earlier frames comes from its
// readings against theirs along the same bearings (MatchToViews), around
// what the odometry says it turned, read out to view_range_factor times the
// map's range (the far walls tell the turn where the near floor is empty).
// The explorer makes every turn in steps of a pirouette's with a look after
// each, so that each frame overlaps one before it. Once the stop has 4
// frames, they take a small common turn against the map before the stop
// (MatchHeading, the beam model, out to map_turn_range_factor times the
// map's range). When the stop's pirouette is whole (scan_match_frames), its
// position and heading are corrected by correlative scan matching (Olson
// 2009; MatchScan) of its hits against the hits of the stops before (kept
// once per centimetre, not as the map's cells): this takes out the straight
// moves' error. The hits, not the occupancy grid, are matched: the grid's
// walls, made from readings at many ranges, do not sit exactly where a new
// view puts them, and matching against them makes the maps worse
// (docs/measurements.md, "Pose tracking").
// The map's frame is the odometry's at the start.
class PoseTracker {
 public:
  // Throws std::invalid_argument for bad options (TrackerOptions::Check).
  explicit PoseTracker(const TrackerOptions& options = {});

  // The map pose of an odometry pose.
  core::Pose2 ToMap(const core::Pose2& odom_T_robot) const { return map_T_odom_ * odom_T_robot; }
  const core::Pose2& map_T_odom() const { return map_T_odom_; }

  // Whether a frame at odom_T_robot starts a new stop (the robot moved).
  bool StartsStop(const core::Pose2& odom_T_robot) const;

  // Tracks a frame taken at odom_T_robot that showed `profile` (read out to
  // view_range_factor times map_range_m: the frames are matched with each
  // other over all of it, and with the map out to map_turn_range_factor
  // times map_range_m). `before` is the map as it was before the stop's
  // first frame (the caller keeps it when StartsStop). Returns the map poses
  // of all the stop's frames so far, in order (they may all move): the
  // caller puts them in `before` again.
  std::vector<core::Pose2> Track(const mapping::OccupancyGrid& before,
                                 const core::ObstacleProfile& profile, double map_range_m,
                                 const core::Pose2& odom_T_robot);

  int matches() const { return matches_; }            // frames tracked
  int accepted() const { return accepted_; }          // of them, turned by a match with their stop
  int scan_matches() const { return scan_matches_; }  // stops moved by a scan match

 private:
  struct StopFrame {
    core::ObstacleProfile profile;      // out to the view range
    core::ObstacleProfile map_profile;  // the same out to the map turn's range
    core::Pose2 odom;
    double heading_rad = 0.0;  // in the map
  };

  // The stop's hits (StopFrame::profile's, out to hit_range_factor times the
  // map's range) as offsets from its position, in the map's orientation.
  std::vector<Eigen::Vector2d> StopHits() const;
  void AddStopHits();
  // Moves the stop by a scan match against the stops before.
  void MatchStop();

  TrackerOptions options_;
  core::Pose2 map_T_odom_;
  // The stop: its frames and its position.
  std::vector<StopFrame> stop_;
  Eigen::Vector2d stop_position_ = Eigen::Vector2d::Zero();
  // The hits of the stops before, and the variance of the stop's position
  // relative to them.
  HitStore hits_;
  double position_variance_ = 0.0;
  double map_range_m_ = 0.0;
  int scan_matches_ = 0;
  int matches_ = 0;
  int accepted_ = 0;
};

}  // namespace pirouette::localize
