#pragma once

#include "pirouette/core/pose2.h"

namespace pirouette::core {

// The paper's pirouette (Taylor, Geva & Boles 2005): 12 turns of 30° with a
// frame before each, so that a camera of 60° field of view sees every
// bearing in two frames.
inline constexpr int kPirouetteTurns = 12;

// One piecewise-linear motion, the only kind the paper's robot makes: a turn
// on the spot (radians, counter-clockwise positive) or a straight drive
// (metres, negative backwards).
struct Move {
  enum class Kind { kTurn, kStraight };

  Kind kind = Kind::kTurn;
  double amount = 0.0;

  static Move Turn(double radians) { return {Kind::kTurn, radians}; }
  static Move Straight(double metres) { return {Kind::kStraight, metres}; }
};

// What a move did, as the robot knows it.
struct MoveOutcome {
  Move requested;
  // The part of the move made, by odometry, in the move's unit; equal to
  // requested.amount unless the robot stopped early.
  double achieved = 0.0;
  // True when a straight move stopped because the robot touched something.
  bool stopped_at_contact = false;
  Pose2 odometry;  // odom_T_robot after the move
};

}  // namespace pirouette::core
