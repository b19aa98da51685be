#pragma once

#include <Eigen/Core>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "pirouette/app/look_ahead.h"
#include "pirouette/camera/camera_model.h"
#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/robot/robot.h"
#include "pirouette/vision/profile_extractor.h"

namespace pirouette::app {

// What the map of a run depends on besides its frames.
struct MapperSetup {
  camera::CameraModel camera;
  double radius_m = 0.0;     // the robot's disc
  double cell_m = 0.0;       // the map's cell (> 0)
  double max_range_m = 0.0;  // readings are trusted out to this range (> 0)
  mapping::OccupancyOptions occupancy;
};

// The floor mask (255 floor) of a raw BGR frame, from a segmenter that sees
// the frames in the order they were taken.
using MaskFunction = std::function<cv::Mat1b(const cv::Mat3b& bgr_raw)>;

// Builds the occupancy grid of a run from its frames, the same way whether
// they come live from a robot or from a recorded log, so that a log maps to
// the map the run made. Each frame's obstacle profile goes into the grid
// through the paper's range sensor model (mapping::InsertProfile), with the
// robot's footprint free; a straight move that ended at contact adds a hit
// in front of the robot (its bumper); a look that found the way blocked
// confirms the blocking hits (ConfirmBlocking).
class FrameMapper {
 public:
  // The grid starts as 2 m square around `start` (odometry frame) and grows.
  FrameMapper(const MapperSetup& setup, MaskFunction mask, const core::Pose2& start);

  struct Seen {
    cv::Mat3b bgr;   // the raw frame, BGR
    cv::Mat1b mask;  // its floor, 255
    core::ObstacleProfile profile;
  };
  // Perceives a frame and puts what it shows in the map at its odometry.
  Seen AddFrame(const robot::Frame& frame);

  // A straight move stopped at contact with the robot at odom_T_robot.
  void AddContact(const core::Pose2& odom_T_robot);

  // The look from odom_T_robot (profile) found a forward move of leg_m
  // blocked: its hits in the corridor are made occupied in the map, so that
  // the next plan goes another way (a cell seen free once takes several
  // hits to read occupied).
  void ConfirmBlocking(const core::ObstacleProfile& profile, const core::Pose2& odom_T_robot,
                       double leg_m);

  const mapping::OccupancyGrid& grid() const { return grid_; }
  mapping::OccupancyGrid TakeGrid() { return std::move(grid_); }
  const MapperSetup& setup() const { return setup_; }
  const camera::InversePerspectiveMap& ipm() const { return ipm_; }
  const LookAhead& look_ahead() const { return look_; }

  // Seconds spent segmenting and reading profiles, and updating the grid.
  double perceive_s() const { return perceive_s_; }
  double update_s() const { return update_s_; }

 private:
  MapperSetup setup_;
  MaskFunction mask_;
  camera::InversePerspectiveMap ipm_;
  vision::ProfileExtractor extractor_;  // the profile tables, built once
  LookAhead look_;
  mapping::OccupancyGrid grid_;
  double perceive_s_ = 0.0;
  double update_s_ = 0.0;
};

}  // namespace pirouette::app
