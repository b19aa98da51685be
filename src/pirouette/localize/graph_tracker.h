#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <numbers>
#include <optional>
#include <vector>

#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/localize/pose_graph.h"
#include "pirouette/localize/pose_tracker.h"
#include "pirouette/localize/scan_matcher.h"
#include "pirouette/mapping/occupancy_grid.h"

namespace pirouette::localize {

// What the odometry's error is believed to be, for the odometry edges: the
// standard deviation of a move's error as a fraction of its length and of a
// turn's as a fraction of its angle, each no less than its floor (so that a
// perfect odometry still gives a finite information). A real robot's is a
// setting; in the simulator it is the world's noise. The floors, 0.2 mm and
// 0.02°, are far below a match edge's (GraphTrackerOptions::edge_floor_m,
// 1 cm and 0.25°), so that a perfect odometry outweighs the matches and the
// graph leaves a noise-free run's map as the odometry makes it; at 2 mm and
// 0.2° the matches moved noise-free stops, up to 1.2% false free cells in the
// apartment (docs/measurements.md, "Pose graph").
struct OdometryModel {
  double translation_fraction = 0.08;
  double rotation_fraction = 0.08;
  double min_translation_m = 0.0002;
  double min_rotation_rad = 0.02 * std::numbers::pi / 180.0;

  // Throws std::invalid_argument unless every field is finite and > 0.
  void Check() const;
};

struct GraphTrackerOptions {
  OdometryModel odometry;
  // The frames of one stop: their headings relative to each other by the
  // scan tracker's matching along shared bearings (PoseTracker, with its map
  // turn and scan match off: the graph does their work). Its
  // rotation_fraction is the odometry model's; its hit_range_factor, scan
  // options and heading_prior_rad serve the stop's scan match here.
  TrackerOptions stop;
  // The error a heading match within a stop leaves on a turn: 1.0° measured
  // under 5% turn noise (docs/measurements.md, "Pose graph"); the odometry
  // edge blends the stop's matched turns with the odometry's own by it.
  double match_turn_sigma_rad = 1.0 * std::numbers::pi / 180.0;
  // A stop is matched against the earlier stops within this many times the
  // hits' range (stop.hit_range_factor times the map's) of it, as one local
  // map: beyond, their views cannot overlap. The match is accepted when at
  // least min_response of the stop's hits lie near the local map's
  // (ScanMatch::response).
  double overlap_range_factor = 2.0;
  double min_response = 0.3;
  // The edge goes from the nearest of those stops; when the path along the
  // graph from it is longer than loop_path_m it is a loop closure: accepted
  // only within the Mahalanobis gate (kGate99) of the graph's own
  // prediction, and weighted by a Huber loss.
  double loop_path_m = 2.0;
  // An edge's covariance is the match's likelihood's plus this floor: 1 cm
  // and 0.25°, the errors of matches between stops measured without
  // odometry noise (docs/measurements.md, "Pose graph"); a match is never
  // surer than the perception that made its hits.
  double edge_floor_m = 0.01;
  double edge_floor_rad = 0.25 * std::numbers::pi / 180.0;
  PoseGraphOptions optimiser;

  // Throws std::invalid_argument for a value out of range.
  void Check() const;
};

// Graph SLAM over the robot's stops (Lu & Milios 1997; Grisetti et al. 2010;
// the design of Karto / slam_toolbox): a node per stop (where the robot
// stood and looked: a pirouette, a look before a move, a look after
// contact), holding its frames' headings relative to the stop and its hits in
// the stop's own frame; an odometry edge between consecutive stops
// (OdometryModel, blended with the stop's own heading matches); and a
// scan-match edge from each stop to the earlier stops its view overlaps, by
// correlative scan matching (Olson 2009; MatchScan) of the stop's hits
// against theirs at their current poses, its covariance that of the match's
// likelihood over its window (as Karto computes it from the response
// surface). The edge goes from the earlier stop whose hits the match aligned
// most of the new stop's hits with (AgreeingStop), not from the nearest: the
// match measured the pose relative to those hits. The match's prior is the
// odometry's error since the stop's last accepted match, as the scan
// tracker's, so a stop that comes back near stops far along the graph
// matches them in the same small window, and when it is their hits it
// aligned with, the edge is a gated, robust loop closure. The graph is
// optimised (Ceres) whenever a stop has been matched: when its pirouette is
// whole (stop.scan_match_frames frames), or when the next stop starts.
// The map's frame is the odometry's at the start; the first stop is fixed.
// Not yet: a wider search for loop closures after long drift (larger
// windows, or candidates from the place signatures).
class GraphTracker {
 public:
  // Throws std::invalid_argument for bad options.
  explicit GraphTracker(const GraphTrackerOptions& options = {});

  // Whether a frame at odom_T_robot starts a new stop (the robot moved).
  bool StartsStop(const core::Pose2& odom_T_robot) const { return stop_.StartsStop(odom_T_robot); }

  // Tracks a frame taken at odom_T_robot that showed `profile` (read out to
  // stop.view_range_factor times map_range_m). Returns the first stop the
  // graph moved (then the poses of its frames and of every later one's may
  // have changed: FramePose), or -1 when only the new frame was placed.
  int Track(const mapping::OccupancyGrid& map, const core::ObstacleProfile& profile,
            double map_range_m, const core::Pose2& odom_T_robot);

  // Ends the last stop (matches it, if not yet, and optimises): at the end of
  // a run, so that the graph holds every stop's edges. Returns the first
  // stop moved, or -1.
  int Finish();

  // The map pose of an odometry pose: through the latest stop.
  core::Pose2 ToMap(const core::Pose2& odom_T_robot) const;
  // The map pose of the k-th frame tracked (0-based), where the graph now puts it.
  core::Pose2 FramePose(std::size_t k) const;
  std::size_t FrameCount() const { return frames_.size(); }
  // The stop (graph node) of the k-th frame.
  int StopOf(std::size_t k) const { return frames_.at(k).node; }

  const PoseGraph& graph() const { return graph_; }
  // How near an earlier stop must be for its views to overlap a new one's
  // (it joins the new stop's local map), metres: overlap_range_factor times
  // the hits' range; 0 before the first frame.
  double OverlapReachM() const {
    return options_.overlap_range_factor * options_.stop.hit_range_factor * map_range_m_;
  }
  int loop_closures_accepted() const { return loops_accepted_; }
  int loop_closures_rejected() const { return loops_rejected_; }
  int scan_matches() const { return scan_matches_; }
  // Seconds spent optimising, and per matched stop (matching + optimising).
  double optimise_s() const { return optimise_s_; }
  const std::vector<double>& per_stop_s() const { return per_stop_s_; }

 private:
  struct Frame {
    int node = 0;
    core::Pose2 node_T_frame;  // the frame in its stop's frame (a heading only)
    // Read only while its stop is the last; emptied when the next starts
    // (the stop's hits hold what the graph needs of it from then on).
    core::ObstacleProfile profile;
  };
  struct Stop {
    core::Pose2 inner_T_stop;  // in the stop tracker's frame
    core::Pose2 odom_T_stop;   // the odometry's
    std::size_t first_frame = 0;
    double path_m = 0.0;  // along the graph from the first stop
    bool matched = false;
    std::vector<Eigen::Vector2d> hits;  // in the stop's frame
  };

  // The hits of a stop's frames in its frame: the nearest in each degree of
  // bearing, out to the hits' range.
  std::vector<Eigen::Vector2d> HitsOf(int node) const;
  // Frees the profiles of a stop whose hits are final (a noisy apartment's
  // 7,000 frames held 100 MB of them).
  void ReleaseProfiles(int node);
  // The odometry edge into the new stop `to` (pending_odometry_) from the
  // one before; returns its relative pose.
  core::Pose2 AddOdometryEdge(int to, const Stop& stop);
  // Matches the stop against earlier ones and optimises; the first stop
  // moved, or -1.
  int MatchAndOptimise(int node);
  // A scan match of stop `to` against the hits of the stops `references`
  // (at their poses) with `prior` (dx, dy, dθ in the map's orientation), as
  // an edge from the reference stop the match agrees with (AgreeingStop,
  // else `nearest`) when accepted: a loop closure when that stop lies more
  // than loop_path_m back along the graph.
  std::optional<PoseGraphEdge> MatchStop(int nearest, const std::vector<int>& references, int to,
                                         const Eigen::Matrix3d& prior);
  // A reference stop's hit where the graph now puts it.
  struct PlacedHit {
    Eigen::Vector2d p_map;
    int stop = 0;
  };
  // Of the reference stops (their hits `placed`, as `reference` holds them),
  // the stop the most of stop `to`'s hits, at map_T_to, lie within the scan
  // match's σ of a hit of (ties: the latest); -1 when none does. The edge goes from it: the match
  // measured the pose relative to the hits it aligned, and booked from another stop (the nearest,
  // say, far back along the graph while the hits aligned were the last stops') it would tell the
  // graph that the drift between the two is true (docs/measurements.md, "Pose graph").
  int AgreeingStop(const HitStore& reference, const std::vector<PlacedHit>& placed, int to,
                   const core::Pose2& map_T_to) const;

  GraphTrackerOptions options_;
  PoseTracker stop_;  // the frames' headings within each stop
  PoseGraph graph_;
  std::vector<Stop> stops_;
  std::vector<Frame> frames_;
  core::Pose2 last_odom_;
  // Since the stop's first frame: turns its heading match corrected, and the
  // sum of |turn| of the others (the next odometry edge's heading error).
  int matched_turns_ = 0;
  double unmatched_turn_rad_ = 0.0;
  double turn_rad_ = 0.0;  // every turn's
  PoseGraphEdge pending_odometry_;
  double map_range_m_ = 0.0;
  int scan_matches_ = 0;
  int loops_accepted_ = 0;
  int loops_rejected_ = 0;
  double optimise_s_ = 0.0;
  std::vector<double> per_stop_s_;
  // The variance of the stop's pose relative to the map around it: grown by
  // each odometry edge, set to the posterior's by each accepted match.
  double position_variance_ = 0.0;
  double heading_variance_ = 0.0;
};

}  // namespace pirouette::localize
