#pragma once

#include <cstdint>
#include <vector>

#include "pirouette/core/odometry_noise.h"
#include "pirouette/core/pose2.h"

namespace pirouette::sim {

// The odometry a robot with `noise` would have reported along `truth` (the
// poses of its frames in order, as a run log recorded without noise holds
// them): SimRobot's motion model turned round, so that a recorded run can be
// mapped again under odometry error with the truth known (`pirouette map
// --log --odometry-noise`). Each step between frames is taken as the robot's
// piecewise-linear motion, a turn, a straight move and a turn; the robot made
// each part with the error 1 + b + ε (b the bias, ε ~ N(0, σ) drawn per
// part from `seed`, as SimRobot draws them), so its odometry reports the part
// divided by that (a factor under 0.1 is taken as 0.1). The first pose is
// the truth's. The same truth, noise and seed give the same odometry.
std::vector<core::Pose2> DriftedOdometry(const std::vector<core::Pose2>& truth,
                                         const core::OdometryNoise& noise, std::uint64_t seed);

}  // namespace pirouette::sim
