#pragma once

#include <cstdint>
#include <string>
#include <vector>

#include "pirouette/core/move.h"
#include "pirouette/core/pose2.h"
#include "pirouette/robot/robot.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/sim/world.h"

namespace pirouette::sim {

// A frame of a simulated pirouette and where the robot truly was.
struct SimulatedFrame {
  robot::Frame frame;  // image, odometry (odom_T_robot) and time
  core::Pose2 world_T_robot;
};

// A copy of `world` whose robot starts at world_T_robot. Throws
// core::InputError (naming `what`, e.g. "--pose") when the robot's disc does
// not fit there.
sim::World PlaceRobot(const sim::World& world, const core::Pose2& world_T_robot,
                      const std::string& what);

// Tries, per pose asked for, that RandomRobotPoses makes before it gives up.
inline constexpr long kRandomPoseTries = 100000;

// `count` (>= 0) random poses where the robot's disc fits the world
// (sim::World::DiscFits): each try draws a position uniform over the floor and
// a heading uniform in [-π, π) from one std::mt19937_64 seeded with `seed`, and
// a try that does not fit is dropped. The same world and seed give the same
// poses, and a smaller count a prefix of them. Throws core::InputError
// (naming `what`, e.g. the world file) when kRandomPoseTries × count tries
// found fewer: a world where the robot fits almost nowhere is bad input, not a
// hang.
std::vector<core::Pose2> RandomRobotPoses(const sim::World& world, int count, std::uint64_t seed,
                                          const std::string& what);

// One pirouette of the simulated robot (sim::SimRobot, with the world's
// odometry noise drawn from `seed`) starting at world's robot start: a frame,
// a turn of 360°/turns, and so on, `turns` frames in all. The odometry frame
// is the world frame at the start. `renderer` must render `world`.
std::vector<SimulatedFrame> SimulatePirouette(const sim::World& world, sim::Renderer& renderer,
                                              std::uint64_t seed,
                                              int turns = core::kPirouetteTurns);

}  // namespace pirouette::sim
