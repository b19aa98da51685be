#pragma once

#include "pirouette/run/exploration_options.h"
#include "pirouette/run/exploration_result.h"

namespace pirouette::sim {
class World;
}  // namespace pirouette::sim

namespace pirouette::run {

// Explores `world` in the simulator from its robot's start, knowing nothing
// (ExploreWithRobot with the simulated robot, sim::SimulatedRobot, its frames
// segmented by an eval::FloorMasker), and fills the result's truth: the final
// true pose and the pose error (eval::PoseErrorOf).
// Throws core::InputError for bad options, sim::RenderError when no OpenGL.
ExplorationResult Explore(const sim::World& world, const ExplorationOptions& options,
                          const ExplorationObserver& observer = {});

}  // namespace pirouette::run
