#include "pirouette/core/odometry_noise.h"

#include <cmath>

#include "pirouette/core/input_error.h"

namespace pirouette::core {

OdometryNoise OdometryNoiseWith(const OdometryNoise& base,
                                const std::optional<std::array<double, 2>>& deviations,
                                const std::optional<std::array<double, 2>>& biases) {
  OdometryNoise noise = base;
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

void CheckOdometryNoise(const OdometryNoise& noise) {
  if (!(noise.translation >= 0.0 && noise.translation <= 1.0 && noise.rotation >= 0.0 &&
        noise.rotation <= 1.0)) {
    throw InputError("--odometry-noise", 0, "", "the standard deviations are fractions in [0, 1]");
  }
  if (!(std::abs(noise.translation_bias) <= 0.5 && std::abs(noise.rotation_bias) <= 0.5)) {
    throw InputError("--odometry-bias", 0, "", "the biases are fractions in [-0.5, 0.5]");
  }
}

}  // namespace pirouette::core
