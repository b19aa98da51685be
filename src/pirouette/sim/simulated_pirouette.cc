#include "pirouette/sim/simulated_pirouette.h"

#include <fmt/format.h>

#include <Eigen/Core>
#include <cassert>
#include <numbers>
#include <random>

#include "pirouette/core/input_error.h"
#include "pirouette/sim/sim_robot.h"

namespace pirouette::sim {

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

std::vector<core::Pose2> RandomRobotPoses(const sim::World& world, int count, std::uint64_t seed,
                                          const std::string& what) {
  std::vector<core::Pose2> poses;
  if (count <= 0) return poses;
  std::mt19937_64 rng(seed);
  std::uniform_real_distribution<double> ux(0.0, world.floor().size.x());
  std::uniform_real_distribution<double> uy(0.0, world.floor().size.y());
  std::uniform_real_distribution<double> uh(-std::numbers::pi, std::numbers::pi);
  const long max_tries = kRandomPoseTries * count;
  for (long tries = 0; static_cast<int>(poses.size()) < count; ++tries) {
    if (tries >= max_tries) {
      throw core::InputError(what, 0, "",
                             "the robot fits almost nowhere on this floor: no random poses");
    }
    // The order of ux's and uy's draws is the compiler's (an argument list);
    // this expression is kept as the reports' poses were drawn with it.
    const Eigen::Vector2d p(ux(rng), uy(rng));
    const double h = uh(rng);
    if (world.DiscFits(p, world.robot().radius)) poses.emplace_back(p.x(), p.y(), h);
  }
  return poses;
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
    robot.Execute(core::Move::Turn(2.0 * std::numbers::pi / turns));
  }
  return frames;
}

}  // namespace pirouette::sim
