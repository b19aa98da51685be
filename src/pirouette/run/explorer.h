#pragma once

#include "pirouette/run/exploration_options.h"
#include "pirouette/run/exploration_result.h"
#include "pirouette/run/frame_mapper.h"

namespace pirouette::run {

// Explores with any robot from where it stands, knowing nothing (Taylor, Geva & Boles 2005, §4: a
// pirouette, then repeatedly: plan to the nearest unknown space, and for each
// straight move face it, look, check the floor is free for the whole move
// (else map what is there and plan again), drive, and pirouette at the goal;
// until no reachable unknown space is left); the map is in the robot's odometry frame. `masks`
// segment the robot's frames in order. Throws core::InputError for bad
// options, and lets the robot's errors through (robot::RobotError...).
ExplorationResult ExploreWithRobot(robot::Robot& robot, const RobotDescription& description,
                                   const ExplorationOptions& options, FrameMasks masks,
                                   const ExplorationObserver& observer = {});

// What the mapper's pose graph (if it keeps one) did, into `result`: the
// graph, each frame's stop, the loop closures and scan matches, the overlap
// reach, and the times of optimising and of making the map again. After
// mapper.Finish(). Nothing without the graph.
void TakeGraphOutcome(const FrameMapper& mapper, ExplorationResult& result);

}  // namespace pirouette::run
