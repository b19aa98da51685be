#pragma once

#include <atomic>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pirouette/app/floor_masker.h"
#include "pirouette/app/frame_mapper.h"
#include "pirouette/camera/camera_model.h"
#include "pirouette/core/pose2.h"
#include "pirouette/localize/colour_map.h"
#include "pirouette/localize/pose_tracker.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/mapping/trinary_map.h"
#include "pirouette/robot/robot.h"
#include "pirouette/sim/world.h"

namespace pirouette::app {

enum class PlannerKind { kDistanceTransform, kFrontier };

// How the explorer keeps its pose: kNone trusts the odometry; kScan corrects
// each frame's heading against the earlier frames of its stop and the map
// (localize::PoseTracker; experimental, see the README).
enum class LocalizeKind { kNone, kScan };

// "none" | "scan", the command line's and run.json's names.
std::string_view LocalizeKindName(LocalizeKind kind);
std::optional<LocalizeKind> ParseLocalizeKind(std::string_view name);

// "dt" | "frontier", the command line's and run.json's names.
std::string_view PlannerKindName(PlannerKind kind);
// The planner of a name; nullopt for any other.
std::optional<PlannerKind> ParsePlannerKind(std::string_view name);

// How a simulated exploration runs. Zero for a length means "derive it".
struct ExplorationOptions {
  std::uint64_t seed = 1;
  PlannerKind planner = PlannerKind::kDistanceTransform;
  vision::MaskSource method = vision::MaskSource::kDefault;
  // Straight moves allowed before the run stops with status "step-limit".
  int max_steps = 2000;
  // The map's cell; 0: 1 cm for a robot of radius under 0.1 m (the paper's),
  // else 2 cm (the apartment robot).
  double cell_m = 0.0;
  // The range readings are trusted to; 0: the paper's rule for the camera
  // and the cell (camera::MaxRange).
  double max_range_m = 0.0;
  int pirouette_turns = 12;
  // The sensor model. OctoMap's defaults (hit 0.7, miss 0.4) need four
  // looks before floor reads free (below 0.196): too timid for a camera that
  // sees each bearing in two frames of a pirouette, so the explorer would
  // keep going back to floor it has seen. One look decides here: a miss
  // makes an unknown cell free, a hit occupied; a hit and a miss cancel
  // into unknown, two hits outvote a miss.
  mapping::OccupancyOptions occupancy{.hit_probability = 0.8, .miss_probability = 0.18};
  // Drive back to the start at the end.
  bool return_home = false;
  // Pose tracking, and what it assumes of the odometry.
  LocalizeKind localize = LocalizeKind::kNone;
  localize::TrackerOptions tracker;
  // The simulator's motion error; none: the world file's odometry_noise.
  std::optional<core::OdometryNoise> odometry_noise;
  // Checked between steps; when it becomes true the run ends with status
  // "interrupted" and the map so far.
  const std::atomic<bool>* stop_requested = nullptr;
};

// Throws core::InputError naming the option for a bad value.
void CheckExplorationOptions(const ExplorationOptions& options);

// Where the wall time of a run went, seconds.
struct StageTimes {
  double render_s = 0.0;    // the simulator's camera (0 for a real robot)
  double perceive_s = 0.0;  // segmentation and obstacle profile
  double update_s = 0.0;    // the occupancy grid
  double plan_s = 0.0;      // configuration space, distance transform, path
  double localize_s = 0.0;  // matching frames against the map
};

// How far the robot's belief was from the simulator's truth (translation in
// metres, heading in degrees, absolute): the mean and largest over the
// frames, each as believed when it was taken, and at the end of the run.
struct PoseError {
  double final_m = 0.0;
  double final_deg = 0.0;
  double mean_m = 0.0;
  double mean_deg = 0.0;
  double max_m = 0.0;
};

// What a camera frame taken during the run showed, for the video.
struct FrameEvent {
  const cv::Mat3b& bgr;         // the camera's raw frame
  const cv::Mat1b& floor_mask;  // 255 floor
  const core::Pose2& odom_T_robot;
  const mapping::OccupancyGrid& grid;
};

// The whole run, as the robot knows it (odometry frame = world frame at the
// start) and, for the report, the simulator's truth.
struct ExplorationResult {
  std::string status;  // "complete", "step-limit", "stuck", "interrupted"
  std::string reason;  // why, when stuck
  // The map, in the odometry frame (placeholder 1 × 1 until the run starts).
  mapping::OccupancyGrid grid{core::GridGeometry(0.01, Eigen::Vector2d::Zero(), 1, 1)};
  // The map's colour layer: what the frames saw standing on the floor
  // (FrameMapper::ColourSightings).
  std::vector<localize::ColourSighting> colour_sightings;
  std::vector<core::Pose2> path;   // odometry poses after every move, from the start
  std::vector<core::Pose2> stops;  // where the robot pirouetted
  int moves = 0;                   // straight moves
  int turns = 0;                   // turns on the spot, pirouettes' included
  int pirouettes = 0;
  int frames = 0;
  int blocked_looks = 0;     // looks that found the way blocked
  int backups = 0;           // backing up to see a blind area's base or off a contact
  int contact_backoffs = 0;  // of them, off a contact that stopped a move at once
  double path_length_m = 0.0;
  double rotation_deg = 0.0;
  double wall_time_s = 0.0;
  // Where the robot believed it was at the end (its odometry, corrected by
  // the tracker); none when the robot stopped answering.
  std::optional<core::Pose2> final_pose;
  // The simulator's truth at the end; none for a real robot.
  std::optional<core::Pose2> final_true_pose;
  // Against the truth, over the frames; none for a real robot.
  std::optional<PoseError> pose_error;
  // Where the robot believed each frame was taken when it took it (the
  // tracker may move a stop's earlier frames later, in the map only).
  std::vector<core::Pose2> frame_poses;
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
};

// What the explorer must know of its robot.
struct RobotDescription {
  camera::CameraModel camera;
  double radius_m = 0.0;  // the footprint's disc
};

// Explores with any robot from where it stands, knowing nothing (the loop of
// Explore below); the map is in the robot's odometry frame. `mask`
// segments the robot's frames in order. Throws core::InputError for bad
// options, and lets the robot's errors through (robot::RobotError...).
ExplorationResult ExploreWithRobot(robot::Robot& robot, const RobotDescription& description,
                                   const ExplorationOptions& options, MaskFunction mask,
                                   const ExplorationObserver& observer = {});

// Explores `world` in the simulator from its robot's start, knowing nothing
// (Taylor, Geva & Boles 2005, §4): a pirouette, then repeatedly: plan to the
// nearest unknown space, and for each straight move face it, look, check the
// floor is free for the whole move (else map what is there and plan again),
// drive, and pirouette at the goal; until no reachable unknown space is left.
// Throws core::InputError for bad options, sim::RenderError when no OpenGL.
ExplorationResult Explore(const sim::World& world, const ExplorationOptions& options,
                          const ExplorationObserver& observer = {});

}  // namespace pirouette::app
