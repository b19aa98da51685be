#include "pirouette/sim/simulated_robot.h"

#include <chrono>
#include <cmath>

namespace pirouette::sim {

sim::RenderOptions SimulatedRobot::RenderOptionsFor(std::uint64_t seed) {
  sim::RenderOptions options;
  options.seed = seed;
  return options;
}

SimulatedRobot::SimulatedRobot(const sim::World& world, std::uint64_t seed,
                               const std::optional<core::OdometryNoise>& noise)
    : renderer_(world, world.robot().camera, RenderOptionsFor(seed)),
      robot_(
          world, seed,
          [this](const core::Pose2& world_T_robot) {
            const auto begin = std::chrono::steady_clock::now();
            core::ImageRgb8 image = renderer_.Render(world_T_robot);
            render_s_ +=
                std::chrono::duration<double>(std::chrono::steady_clock::now() - begin).count();
            return image;
          },
          noise.value_or(world.robot().odometry_noise)) {}

}  // namespace pirouette::sim
