#pragma once

#include <Eigen/Core>
#include <deque>
#include <functional>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/packed_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/explore/look_ahead.h"
#include "pirouette/localize/colour_map.h"
#include "pirouette/localize/graph_tracker.h"
#include "pirouette/localize/pose_tracker.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/robot/robot.h"
#include "pirouette/vision/floor_segmenter.h"
#include "pirouette/vision/profile_extractor.h"

namespace pirouette::run {

// What the map of a run depends on besides its frames.
struct MapperSetup {
  camera::CameraModel camera;
  double radius_m = 0.0;     // the robot's disc
  double cell_m = 0.0;       // the map's cell (> 0)
  double max_range_m = 0.0;  // readings are trusted out to this range (> 0)
  mapping::OccupancyOptions occupancy;
  // Pose tracking (localize::PoseTracker, frame by frame); none: the map is
  // made at the odometry's poses.
  std::optional<localize::TrackerOptions> tracking;
  // Graph SLAM over the stops (localize::GraphTracker), instead of `tracking`.
  std::optional<localize::GraphTrackerOptions> graph;
  // The longest side the map may grow to, metres; 0: kDefaultMaxMapCells cells.
  double max_map_m = 0.0;
  // With the graph: how far (in cells, at the map's range) the optimisation
  // may move a frame's readings before the map is made again with it; 0:
  // after every move, so that the map is always the one made from nothing.
  double remap_cells = 0.25;
};

// The map's longest side by default, in cells: 41 m at 1 cm, 82 m at 2 cm,
// larger than any floor the explorer has mapped (docs/measurements.md), and a
// grid of 4096² cells takes 256 MiB (16 bytes a cell).
inline constexpr int kDefaultMaxMapCells = 4096;

// The side limit of a setup's map, metres.
double MaxMapSide(const MapperSetup& setup);

// The floor mask (255 floor) of a raw BGR frame, from a segmenter that sees
// the frames in the order they were taken.
using MaskFunction = std::function<cv::Mat1b(const cv::Mat3b& bgr_raw)>;

// A run's floor masks: the function, and how many of the first frames the
// segmenter behind it learns from before its masks hold
// (vision::FloorSegmenter::SettlingFrames; 0 for a segmenter that does not
// learn). Those frames are masked twice: once to learn, then again, in the
// same order, to be mapped.
struct FrameMasks {
  MaskFunction mask;
  int settling_frames = 0;
  // Where the last mask's floor may go on unresolved
  // (vision::FloorSegmenter::Unresolved); none when empty.
  std::function<const cv::Mat1b&()> unresolved;
};

// The masks of `segmenter` (its Segment, SettlingFrames and Unresolved),
// which must outlive them.
FrameMasks MasksOf(vision::FloorSegmenter& segmenter);

// Builds the occupancy grid of a run from its frames, the same way whether
// they come live from a robot or from a recorded log, so that a log maps to
// the map the run made. Each frame's obstacle profile goes into the grid
// through the paper's range sensor model (mapping::InsertProfile), with the
// robot's footprint free; a straight move that ended at contact adds a hit
// in front of the robot (its bumper); a look that found the way blocked
// confirms the blocking hits (ConfirmBlocking). With tracking, each frame's
// pose is first corrected by the tracker (against the stop's earlier frames,
// with a second profile of the frame read out to the tracker's
// view_range_factor times max_range_m, and once the stop has 4 frames
// against the map before the stop) and the
// stop's frames, which the tracker may move, are put again in the map as it
// was before the stop: the map's frame is the odometry's at the start, and
// ToMap turns any later odometry pose into it.
// With the graph (setup.graph), every frame, bump and confirmation is kept
// with its stop, and whenever the graph's optimisation moves a frame's
// readings by more than a quarter of a cell the map is made again from that
// frame's stop on, at the stops' new poses, so a hit moves with its stop and
// nothing is frozen (Grisetti et al. 2010: the map is a function of the
// poses); Finish makes it from every frame at its final pose.
class FrameMapper {
 public:
  // The grid starts as 2 m square around `start` (odometry frame) and grows.
  FrameMapper(const MapperSetup& setup, FrameMasks masks, const core::Pose2& start);

  struct Seen {
    cv::Mat3b bgr;         // the raw frame, BGR
    cv::Mat1b mask;        // its floor, 255
    cv::Mat1b unresolved;  // where its floor may go on unresolved (empty: nowhere)
    core::ObstacleProfile profile;
    core::Pose2 pose;  // where it went in the map (the odometry's, corrected)
  };
  // Perceives a frame and puts what it shows in the map at its odometry,
  // corrected by the tracker. Throws mapping::MapTooLarge, with nothing
  // changed, when what the frame can see (its odometry ± the range) would
  // make the map's extent pass MaxMapSide: the odometry jumped, or the floor
  // is larger than the limit.
  // The masks' settling frames (the first pirouette) are kept, not mapped,
  // until the last of them: then all are masked again, with what the
  // segmenter learnt from all of them, and mapped in order (a first frame
  // that sees only a wall would otherwise be mapped with the wall's colour
  // taken for the floor's). Until then the Seen's mask and profile are the
  // learning pass's and its pose the odometry's in the map.
  Seen AddFrame(const robot::Frame& frame);

  // The map pose of an odometry pose (the same without tracking).
  core::Pose2 ToMap(const core::Pose2& odom_T_robot) const {
    if (graph_) return graph_->ToMap(odom_T_robot);
    return tracker_ ? tracker_->ToMap(odom_T_robot) : odom_T_robot;
  }
  // The tracker; none without tracking.
  const std::optional<localize::PoseTracker>& tracker() const { return tracker_; }
  // The graph; none without it.
  const std::optional<localize::GraphTracker>& graph() const { return graph_; }

  // Ends the run's mapping: settling frames still kept are mapped; with the
  // graph, its last stop is matched and the map made again if stops moved.
  void Finish();
  // Where every frame is now in the map (the odometry's without tracking;
  // the tracker's or the graph's latest).
  std::vector<core::Pose2> FramePoses() const;
  // With the graph: the map made again from nothing, every frame, bump and
  // confirmation at the graph's poses now. It is what grid() is after
  // Finish, and during a run grid() keeps each frame within a quarter cell
  // of it (a check on the incremental rebuild; it copies the mapper). Without
  // the graph: grid().
  mapping::OccupancyGrid MapAgain() const;
  // Seconds spent making the map again after the graph moved stops, and how
  // many times.
  double rebuild_s() const { return rebuild_s_; }
  int rebuilds() const { return rebuilds_; }

  // A straight move stopped at contact with the robot at odom_T_robot.
  void AddContact(const core::Pose2& odom_T_robot);

  // The look from map_T_robot (profile) found a forward move of leg_m
  // blocked: its hits in the corridor are made occupied in the map, so that
  // the next plan goes another way (a cell seen free once takes several
  // hits to read occupied).
  void ConfirmBlocking(const core::ObstacleProfile& profile, const core::Pose2& map_T_robot,
                       double leg_m);

  // The map's colour layer on the map's geometry: where the frames saw the
  // bases of obstacles and their colours (vision::ColumnColour of each hit's
  // column), at the frames' map poses (with tracking, where the tracker last
  // put them), voted as localize::ColourMap::FromSightings says.
  localize::ColourMap MakeColourMap() const;

  const mapping::OccupancyGrid& grid() const { return grid_; }
  mapping::OccupancyGrid TakeGrid() { return std::move(grid_); }
  const MapperSetup& setup() const { return setup_; }
  const camera::InversePerspectiveMap& ipm() const { return ipm_; }
  const explore::LookAhead& look_ahead() const { return look_; }

  // Seconds spent segmenting and reading profiles, and updating the grid.
  double perceive_s() const { return perceive_s_; }
  double update_s() const { return update_s_; }
  // Seconds spent tracking (matching frames).
  double localize_s() const { return localize_s_; }

 private:
  // Throws MapTooLarge when the frame at `odometry` would pass the limit;
  // else widens extent_lo_/extent_hi_ to it.
  void CheckExtent(const core::Pose2& odometry);

  MapperSetup setup_;
  // The extent of what the frames so far can see (odometry ± the range).
  Eigen::Vector2d extent_lo_ = Eigen::Vector2d::Constant(1e300);
  Eigen::Vector2d extent_hi_ = Eigen::Vector2d::Constant(-1e300);
  MaskFunction mask_;
  std::function<const cv::Mat1b&()> unresolved_;
  // The settling frames not yet mapped, and how many remain to be seen (0:
  // settled, every frame is mapped as it comes).
  std::vector<robot::Frame> settling_;
  int settling_left_ = 0;
  // Masks the settling frames again and maps them; the last one's Seen.
  std::optional<Seen> MapSettlingFrames();
  // Perceives a frame and maps it (AddFrame once settled).
  Seen MapFrame(const robot::Frame& frame);
  camera::InversePerspectiveMap ipm_;
  vision::ProfileExtractor extractor_;  // the profile tables, built once
  // With tracking: the longer profile the tracker matches the frames with.
  std::optional<vision::ProfileExtractor> view_extractor_;
  explore::LookAhead look_;
  // Puts a frame (or a confirmation) in grid_ at its map pose.
  void Insert(const core::ObstacleProfile& profile, const core::Pose2& map_T_robot);
  void Confirm(const core::ObstacleProfile& profile, const core::Pose2& map_T_robot, double leg_m);

  // With the graph: what went into the map, in order, to make it again.
  struct MapEvent {
    enum class Kind { kFrame, kConfirm, kContact };
    explicit MapEvent(Kind k, std::size_t f = 0) : kind(k), frame(f) {}
    Kind kind;
    std::size_t frame = 0;     // the frame (kFrame, kConfirm) or the one a bump goes with
    double leg_m = 0.0;        // kConfirm
    core::Pose2 frame_T_bump;  // kContact: the bump's pose in its frame's
    bool resolved = true;      // kContact: false until its frame is known
    core::Pose2 map_T_bump;    // kContact: where it went when unresolved
  };
  void AddFrameToGraph(Seen& seen, const robot::Frame& frame);
  // Puts the map's events in again from events_[from] on, on grid_ as it is.
  void Replay(std::size_t from);
  // Makes the map again from stop from_stop's first event on, on the map
  // kept from before it (or before an earlier stop), else all of it.
  void Rebuild(int from_stop);
  void Apply(const MapEvent& event);
  // The first frame whose readings the graph has moved by more than
  // tolerance_m at the map's range (its shift plus the range times its turn)
  // since it went into the map, or none. A map kept while the graph nudges
  // stops by less than setup.remap_cells of a cell differs from one made
  // again by less than the map shows, and costs no rebuild (a rebuild from
  // nothing replays every frame: 0.12 s at 5,700 frames, a quarter of a
  // noisy apartment's run).
  std::optional<std::size_t> FirstDisplacedFrame(double tolerance_m) const;
  void UpdateColourPoses();  // to the graph's latest frame poses
  static void InsertBump(mapping::OccupancyGrid& grid, const core::Pose2& map_T_robot,
                         double radius_m, double cell_m);
  std::optional<localize::GraphTracker> graph_;
  std::vector<MapEvent> events_;
  std::vector<core::PackedProfile> frame_profiles_;  // each frame's, at the map's range
  std::vector<core::Pose2> frame_odometry_;
  std::vector<core::Pose2> mapped_poses_;  // each frame's pose when it last went into grid_
  // The map before each of the last kRecentSnapshots stops, and before
  // every kNearStride-th stop of the last kNearSpan and every kFarStride-th
  // of the rest: the graph moves mostly the last stop or two (a noisy run's
  // rebuilds: 101 of 125 within two stops), and a loop closure the stops
  // from the loop's start on, often hundreds back; a rebuild starts from
  // the latest map kept before the first stop moved, not from the first
  // frame (a recorded noisy run of the shipped apartment mapped again:
  // map update 3.0 -> 1.4 s against the recent four alone). Each is the
  // known part of the grid (OccupancyGrid::CroppedToKnown), made (again)
  // when a replay passes its first event.
  struct StopSnapshot {
    int stop = 0;
    std::size_t first_event = 0;
    std::optional<mapping::OccupancyGrid> grid;
  };
  static constexpr int kRecentSnapshots = 4;
  static constexpr int kNearStride = 32;
  static constexpr int kNearSpan = 256;
  static constexpr int kFarStride = 256;
  // Drops the snapshots the rule above no longer keeps, `stop` the newest.
  void ThinSnapshots(int stop);
  std::deque<StopSnapshot> snapshots_;
  core::Pose2 start_;
  double rebuild_s_ = 0.0;
  int rebuilds_ = 0;

  mapping::OccupancyGrid grid_;
  std::optional<localize::PoseTracker> tracker_;
  // With tracking: the map before the current stop, and what went into the
  // map since, to put in again when the tracker moves the stop's frames.
  struct StopEvent {
    core::ObstacleProfile profile;
    std::optional<double> blocked_leg_m;  // a ConfirmBlocking of the frame before
  };
  // Every frame's coloured hits in the robot's frame (as floats: 12 bytes a
  // hit, not a ColourSighting's 24, for a few hundred a frame), and its map pose.
  struct ColourHit {
    Eigen::Vector2f p_robot;
    core::ColourClass colour = core::ColourClass::kNone;
  };
  struct ColourFrame {
    core::Pose2 pose;
    std::vector<ColourHit> hits_robot;
  };
  // Each hit's reading in the frame's robot frame, with its column's colour
  // (vision::ColumnColour); columns without a colour are left out.
  static std::vector<ColourHit> ColouredHits(const cv::Mat3b& bgr, const cv::Mat1b& mask,
                                             const core::ObstacleProfile& profile);
  std::vector<ColourFrame> colour_frames_;
  std::optional<mapping::OccupancyGrid> before_stop_;
  std::vector<StopEvent> stop_events_;
  std::vector<core::Pose2> stop_poses_;
  double localize_s_ = 0.0;
  double perceive_s_ = 0.0;
  double update_s_ = 0.0;
};

}  // namespace pirouette::run
