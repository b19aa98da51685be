#pragma once

#include <string>
#include <string_view>

namespace pirouette::sim {

// A way for the simulated robot to misbehave, for testing what pirouette does
// with a robot that does (sim-serve --fault KIND[@N]; docs/robot-protocol.md
// and docs/ros2.md list what each gives).
struct RobotFault {
  enum class Kind {
    kNone,
    kTeleport,    // odometry jumps 1 m ahead (kTeleportM)
    kFlip,        // the odometry's heading flips by π
    kClockBack,   // frame stamps go back by kClockBackS
    kSameFrame,   // every frame has the bytes of the first faulty one
    kLate,        // each frame is the one taken before the last move (its stamp too)
    kOutOfOrder,  // frames come in pairs swapped: the later first
    kShortMoves,  // the robot moves kShortFraction of what it is told
    kStalled,     // the robot does not move at all, and says so
    kHalfFrame,   // TCP only: the header and half a frame's bytes, then nothing
  };

  Kind kind = Kind::kNone;
  // The fault starts at the Nth request over TCP (HELLO and ODOM are not
  // counted; 1: the first TURN, MOVE or CAPTURE), at N seconds of simulated
  // time after the first cmd_vel over DDS.
  int from = 1;

  static constexpr double kTeleportM = 1.0;
  static constexpr double kClockBackS = 5.0;
  static constexpr double kShortFraction = 0.3;
};

// "teleport", "flip", "clock-back", "same-frame", "late", "out-of-order",
// "short-moves", "stalled", "half-frame", each optionally "@N" (N ≥ 1).
// Throws core::InputError naming `option` for anything else.
RobotFault ParseRobotFault(std::string_view text, const std::string& option = "--fault");
// The kinds, for help texts: "teleport, flip, ...".
std::string RobotFaultKinds();
// The kind's name as ParseRobotFault reads it.
std::string_view RobotFaultName(RobotFault::Kind kind);

}  // namespace pirouette::sim
