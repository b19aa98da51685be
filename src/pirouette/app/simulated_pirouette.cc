#include "pirouette/app/simulated_pirouette.h"

#include <fmt/format.h>

#include <cassert>
#include <numbers>

#include "pirouette/core/input_error.h"
#include "pirouette/sim/sim_robot.h"

namespace pirouette::app {

sim::World PlaceRobot(const sim::World& world, const core::Pose2& world_T_robot,
                      const std::string& what) {
  const Eigen::Vector2d& p = world_T_robot.translation();
  if (!world.DiscFits(p, world.robot().radius)) {
    throw core::InputError(
        what, 0, "",
        fmt::format("the robot (radius {:.3f} m) does not fit at ({:.3f}, {:.3f}) in {}: it "
                    "overlaps an obstacle or leaves the floor",
                    world.robot().radius, p.x(), p.y(), world.name()));
  }
  sim::RobotSpec robot = world.robot();
  robot.start = world_T_robot;
  return {world.name(), world.floor(), world.walls(), world.obstacles(), world.light(), robot};
}

std::vector<SimulatedFrame> SimulatePirouette(const sim::World& world, sim::Renderer& renderer,
                                              std::uint64_t seed, int turns) {
  assert(turns >= 1);
  sim::SimRobot robot(world, seed, [&renderer](const core::Pose2& world_T_robot) {
    return renderer.Render(world_T_robot);
  });
  std::vector<SimulatedFrame> frames;
  frames.reserve(static_cast<std::size_t>(turns));
  for (int i = 0; i < turns; ++i) {
    const core::Pose2 world_T_robot = robot.TruePose();
    frames.push_back({robot.Capture(), world_T_robot});
    robot.Execute(robot::Move::Turn(2.0 * std::numbers::pi / turns));
  }
  return frames;
}

}  // namespace pirouette::app
