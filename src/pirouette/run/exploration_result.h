#pragma once

#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/move.h"
#include "pirouette/core/pose2.h"
#include "pirouette/eval/loop_closure_check.h"
#include "pirouette/eval/pose_error.h"
#include "pirouette/localize/colour_map.h"
#include "pirouette/localize/pose_graph.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/robot/robot.h"

namespace pirouette::run {

// Where the wall time of a run went, seconds.
struct StageTimes {
  double render_s = 0.0;    // the simulator's camera (0 for a real robot)
  double perceive_s = 0.0;  // segmentation and obstacle profile
  double update_s = 0.0;    // the occupancy grid
  double plan_s = 0.0;      // configuration space, distance transform, path
  double localize_s = 0.0;  // matching frames against the map
};

// What a camera frame taken during the run showed, for the video.
struct FrameEvent {
  const cv::Mat3b& bgr;         // the camera's raw frame
  const cv::Mat1b& floor_mask;  // 255 floor
  const core::Pose2& odom_T_robot;
  const mapping::OccupancyGrid& grid;
};

// A goal the run gave up (no planner offers it again), for run.json's
// `given_up`: where the goal was and the robot stood, in the map frame, and
// why. Unknown cells near a stop given up together are one entry: `goal`
// their centroid, `cells` how many (0 for a planner's goal).
struct GivenUpGoal {
  Eigen::Vector2d goal_world = Eigen::Vector2d::Zero();
  Eigen::Vector2d robot_world = Eigen::Vector2d::Zero();
  std::string why;
  int cells = 0;
};

// The whole run, as the robot knows it (odometry frame = world frame at the
// start) and, for the report, the simulator's truth.
struct ExplorationResult {
  std::string status;  // "complete", "step-limit", "stuck", "interrupted"
  std::string reason;  // why, when stuck
  // The map, in the odometry frame (placeholder 1 × 1 until the run starts).
  mapping::OccupancyGrid grid{core::GridGeometry(0.01, Eigen::Vector2d::Zero(), 1, 1)};
  // The map's colour layer on the grid's geometry: what the frames saw
  // standing on the floor (FrameMapper::MakeColourMap).
  localize::ColourMap colour_map;
  std::vector<core::Pose2> path;   // odometry poses after every move, from the start
  std::vector<core::Pose2> stops;  // where the robot pirouetted
  int moves = 0;                   // straight moves
  int turns = 0;                   // turns on the spot, pirouettes' included
  int pirouettes = 0;
  int frames = 0;
  int blocked_looks = 0;     // looks that found the way blocked
  int backups = 0;           // backing up to see a blind area's base or off a contact
  int contacts = 0;          // straight moves the robot's disc stopped by touching something
  int contact_backoffs = 0;  // of them, off a contact that stopped a move at once
  int probes = 0;            // legs across the camera's blind ring (ProbeAcrossTheBlindRing)
  // The goals given up, in order: a run that ends `complete` with floor
  // unseen gave up the goals that led there.
  std::vector<GivenUpGoal> given_up;
  double path_length_m = 0.0;
  double rotation_deg = 0.0;
  double wall_time_s = 0.0;
  // Where the robot believed it was at the end (its odometry, corrected by
  // the tracker); none when the robot stopped answering.
  std::optional<core::Pose2> final_pose;
  // The simulator's truth at the end; none for a real robot.
  std::optional<core::Pose2> final_true_pose;
  // Against the truth, over the frames; none for a real robot.
  std::optional<eval::PoseError> pose_error;
  // Where the robot believed each frame was taken when it took it (the
  // tracker may move a stop's earlier frames later, in the map only).
  std::vector<core::Pose2> frame_poses;
  // Where every frame is in the map at the end (the tracker or the graph may
  // have moved it since it was taken).
  std::vector<core::Pose2> final_frame_poses;
  // With the graph: the graph itself (DIR/graph.g2o), its loop closures,
  // and the time it took.
  std::optional<localize::PoseGraph> graph;
  std::vector<int> frame_stops;  // the graph's stop of each frame
  // Its loop closures against the truth; none for a real robot.
  std::optional<eval::LoopClosureCheck> loop_closure_check;
  std::optional<eval::LoopClosureRecall> loop_closure_recall;  // in the simulator
  // The graph's overlap reach (GraphTracker::OverlapReachM), for the recall.
  double loop_reach_m = 0.0;
  int loop_closures_accepted = 0;
  int loop_closures_rejected = 0;
  double optimise_s = 0.0;
  std::vector<double> per_stop_s;  // matching + optimising, per stop
  double rebuild_s = 0.0;          // making the map again when stops moved
  int rebuilds = 0;
  int matches = 0;       // frames the tracker saw
  int corrections = 0;   // of them, those turned by a match with their stop's earlier frames
  int scan_matches = 0;  // stops moved by a scan match against the stops before
  StageTimes times;
};

// Progress after every step, for the terminal.
struct ExplorationProgress {
  int moves = 0;
  int pirouettes = 0;
  double known_area_m2 = 0.0;
  double elapsed_s = 0.0;
};

// The run as it stands after every pirouette, move and plan, for live views
// (ROS 2, the browser). The references hold during the call only.
struct RunSnapshot {
  const mapping::OccupancyGrid& grid;        // the map, in the map frame
  const std::vector<core::Pose2>& path;      // where the robot went (map frame)
  const std::vector<core::Pose2>& stops;     // where it pirouetted
  const std::vector<Eigen::Vector2d>& plan;  // where it goes next; empty: no plan
  core::Pose2 map_T_robot;
  core::Pose2 map_T_odom;       // the correction the tracker or the graph makes
  const cv::Mat3b& bgr;         // the last frame (empty before the first)
  const cv::Mat1b& floor_mask;  // its floor, 255
  int frames = 0;               // frames mapped: the map changed when this did
  ExplorationProgress progress;
};

struct ExplorationObserver {
  std::function<void(const ExplorationProgress&)> on_progress;
  std::function<void(const FrameEvent&)> on_frame;
  // Every frame as the robot gave it, with the motions made since the one
  // before (a run log records them), before it is mapped.
  std::function<void(const robot::Frame&, const std::vector<core::MoveOutcome>& motions)>
      on_capture;
  // The frame just captured showed a forward move of leg_m blocked (the
  // mapper confirmed the blocking hits).
  std::function<void(double leg_m)> on_blocked;
  std::function<void(const RunSnapshot&)> on_snapshot;
};

// What the explorer must know of its robot.
struct RobotDescription {
  camera::CameraModel camera;
  double radius_m = 0.0;  // the footprint's disc
};

}  // namespace pirouette::run
