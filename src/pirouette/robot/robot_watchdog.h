#pragma once

#include <optional>
#include <string>

#include "pirouette/robot/robot.h"

namespace pirouette::robot {

// What a robot may do before the watchdog calls it broken. Each bound is far
// past what a working robot does (odometry drifts by millimetres a move, a
// camera's frames differ in their noise), so that only a broken one trips it.
struct RobotWatchdogOptions {
  // Odometry may change by at most a move's length plus this (metres) over a
  // move, and by this between a move and the frame after it (the robot
  // stands still): more is a jump no wheel made (a teleport).
  double max_jump_m = 0.25;
  // A drive may turn the robot, a turn may differ from the angle it says it
  // made, and a frame's heading from the last move's, by at most this
  // (radians, 45°): more is a heading that flipped.
  double max_jump_rad = 0.7853981633974483;
  // Moves in a row that made nothing (under the thresholds below) without
  // touching anything before the robot counts as not moving at all.
  int max_idle_moves = 3;
  double idle_m = 0.002;
  double idle_rad = 0.009;  // 0.5°
  // Moves in a row that made less than `min_fraction` of what was asked
  // without touching anything: the robot moves less than told (a wrong unit
  // or scale in its adapter, a slipping drive).
  int max_short_moves = 3;
  double min_fraction = 0.5;
  // Moves asked for less than this are too small to judge by either count
  // (within what a base's controller resolves: a turn of 0.2° may end at
  // 0.1°): they neither count nor break a count.
  double min_judged_m = 0.01;
  double min_judged_rad = 0.035;  // 2°
  // Frames in a row with the very same bytes, the robot having moved between
  // each: the camera is frozen.
  int max_identical_frames = 3;
};

// A Robot that passes every call to another and checks what comes back for
// what no working robot does. A robot that fails a check has lost the
// run's trust: the call throws RobotError with a reason that names the
// fault and its numbers, and the run ends "stuck" with the map so far
// (run/explorer.cc), as for a robot that stops answering:
//
//  - odometry that jumps: farther over a move than the move could take it,
//    or between a move and the next frame; a drive that turns, a turn that
//    turned otherwise than it says, a heading that flipped. Carrying on is
//    not safe: the map is built on odometry, every later reading would be
//    put off by the jump, and a robot whose encoders lie may drive into what
//    the map does not show.
//  - a clock that goes backwards: a frame stamped before the one before it
//    (frames out of order); and a late frame: one stamped no later than the
//    frame before it though the robot moved between them, so taken before
//    the move.
//  - a frozen camera: the same bytes max_identical_frames times in a row,
//    the robot having moved between each (at rest two frames may be equal).
//  - a robot that does not move (max_idle_moves moves in a row made
//    nothing) or moves less than told (max_short_moves in a row made under
//    min_fraction of the move). A move stopped at contact is neither.
//
// The wrapped robot's own errors pass through unchanged. Not thread-safe;
// one run's loop calls it.
class RobotWatchdog : public Robot {
 public:
  // `robot` must outlive this; `name` begins every reason ("the robot at
  // 127.0.0.1:5555").
  RobotWatchdog(Robot& robot, std::string name, const RobotWatchdogOptions& options = {});

  core::MoveOutcome Execute(const core::Move& move) override;
  Frame Capture() override;
  core::Pose2 Odometry() const override { return robot_.Odometry(); }

 private:
  [[noreturn]] void Fail(const std::string& what) const;
  void CheckMove(const core::Move& move, const core::MoveOutcome& outcome,
                 const core::Pose2& before);
  void CheckMotionMade(const core::Move& move, const core::MoveOutcome& outcome);
  void CheckFrame(const Frame& frame);

  Robot& robot_;
  std::string name_;
  RobotWatchdogOptions options_;
  core::Pose2 odometry_;  // after the last move (or at the start)
  int idle_moves_ = 0;
  int short_moves_ = 0;
  bool moved_since_frame_ = false;
  std::optional<Frame> last_frame_;
  int identical_frames_ = 1;  // the last frame's bytes, seen this many times in a row
};

}  // namespace pirouette::robot
