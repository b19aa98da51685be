#include "pirouette/sim/simulated_robot.h"

#include <chrono>
#include <cmath>

#include "pirouette/core/input_error.h"

namespace pirouette::sim {

core::OdometryNoise OdometryNoiseWith(const core::OdometryNoise& base,
                                      const std::optional<std::array<double, 2>>& deviations,
                                      const std::optional<std::array<double, 2>>& biases) {
  core::OdometryNoise noise = base;
  if (deviations) {
    noise.translation = (*deviations)[0];
    noise.rotation = (*deviations)[1];
  }
  if (biases) {
    noise.translation_bias = (*biases)[0];
    noise.rotation_bias = (*biases)[1];
  }
  return noise;
}

void CheckOdometryNoise(const core::OdometryNoise& noise) {
  if (!(noise.translation >= 0.0 && noise.translation <= 1.0 && noise.rotation >= 0.0 &&
        noise.rotation <= 1.0)) {
    throw core::InputError("--odometry-noise", 0, "",
                           "the standard deviations are fractions in [0, 1]");
  }
  if (!(std::abs(noise.translation_bias) <= 0.5 && std::abs(noise.rotation_bias) <= 0.5)) {
    throw core::InputError("--odometry-bias", 0, "", "the biases are fractions in [-0.5, 0.5]");
  }
}

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
