#pragma once

#include <array>
#include <cstdint>
#include <fstream>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/image.h"
#include "pirouette/core/pose2.h"
#include "pirouette/robot/robot.h"

namespace pirouette::io {

// A run log, `pirouette-log/1` (docs/run-log.md): a folder holding
//   log.yaml     format, the robot's radius, how the run mapped (cell, max
//                range, segmentation), and for a simulated run its world and seed
//   camera.yaml  the camera file (SPEC.md)
//   frames/NNNNNN.png  the frames, as taken (raw: distortion, vignetting)
//   frames.csv   index,time_s,x,y,heading_deg,motion,blocked_leg_m
// one row per frame: its odometry (odom_T_robot, degrees), the motions made
// since the frame before (`turn DEG`, `straight M`, `straight M contact`,
// joined by `;`; empty for the first), and, when the explorer found a
// forward move of that length blocked in this frame, blocked_leg_m.

// What log.yaml holds besides its format.
struct RunLogInfo {
  double radius_m = 0.0;     // the robot's disc
  double cell_m = 0.0;       // the map's cell the run used (0: not said)
  double max_range_m = 0.0;  // the readings' trusted range (0: not said)
  std::string method;        // segmentation: "default", "paper" (empty: not said)
  std::string localize;      // pose tracking: "graph", "scan", "none" (empty: not said, graph)
  // The pose graph's odometry model (standard deviations as fractions of a
  // move and of a turn: localize::OdometryModel); none: not said.
  std::optional<std::array<double, 2>> odometry_model;
  std::string world;       // the simulated world's file, as given (empty: a real robot)
  std::uint64_t seed = 0;  // the simulator's seed
};

struct RunLogRow {
  int index = 0;
  double time_s = 0.0;
  core::Pose2 odometry;  // odom_T_robot
  std::string motion;    // as in frames.csv
  bool contact = false;  // the last straight move before it stopped at contact
  std::optional<double> blocked_leg_m;
};

struct RunLog {
  std::string dir;
  RunLogInfo info;
  camera::CameraModel camera;
  std::vector<RunLogRow> rows;
  // Where the log stops short, when it does: frames.csv's last line without
  // its line end (a run killed while it wrote it); the rows before it are
  // whole and in `rows`. Empty for a whole log.
  std::string cut;
};

// The motions column for a list of motions.
std::string MotionText(const std::vector<core::MoveOutcome>& motions);

// Writes a run log as the frames come. The folder is made (with frames/),
// log.yaml and camera.yaml written at once; each frame's PNG is written
// atomically and its row appended to frames.csv when the next frame comes or
// on Close (a row waits so that MarkBlocked can fill its last column).
// Throws core::InputError when the folder cannot be made or already holds a
// log, std::runtime_error when a write fails.
class RunLogWriter {
 public:
  RunLogWriter(const std::string& dir, const camera::CameraModel& camera, const RunLogInfo& info);
  ~RunLogWriter();
  RunLogWriter(const RunLogWriter&) = delete;
  RunLogWriter& operator=(const RunLogWriter&) = delete;

  void AddFrame(const robot::Frame& frame, const std::vector<core::MoveOutcome>& motions);
  // The last frame added found a forward move of leg_m blocked.
  void MarkBlocked(double leg_m);
  // Writes the last row; later frames are refused.
  void Close();

  int frames() const { return next_index_; }

 private:
  void FlushRow();

  std::string dir_;
  std::ofstream csv_;
  std::optional<std::string> pending_;  // the last row, without its blocked_leg_m
  std::optional<double> pending_blocked_;
  int next_index_ = 0;
  bool closed_ = false;
};

// Reads a run log's log.yaml (optional: without it info is all zero),
// camera.yaml and frames.csv. A last row without its line end is a cut, not
// an error (RunLog::cut). Throws core::InputError naming the file, line and
// field of anything missing or malformed, and for a log without a whole row.
RunLog ReadRunLog(const std::string& dir);

// The frame of a row, with its odometry and time. Throws core::InputError
// for a missing or unreadable image, or one whose size is not the camera's.
robot::Frame ReadLogFrame(const RunLog& log, const RunLogRow& row);

}  // namespace pirouette::io
