#pragma once

#include <array>
#include <optional>

namespace pirouette::core {

// A robot's motion error, as fractions of each move (the simulator's, or a
// real robot's odometry model): a straight
// move of d drives d·(1 + translation_bias + ε_t), a turn by θ turns
// θ·(1 + rotation_bias + ε_r), ε ~ N(0, translation | rotation). The biases
// model wheels that drift one way (a wheel a little larger than the other).
struct OdometryNoise {
  double translation = 0.0;       // standard deviation, >= 0
  double rotation = 0.0;          // standard deviation, >= 0
  double translation_bias = 0.0;  // in [-0.5, 0.5]
  double rotation_bias = 0.0;     // in [-0.5, 0.5]
};

// The command line's motion error: `base` (a world file's) with the standard
// deviations {translation, rotation} and the biases {translation, rotation}
// given, each where given.
OdometryNoise OdometryNoiseWith(const OdometryNoise& base,
                                const std::optional<std::array<double, 2>>& deviations,
                                const std::optional<std::array<double, 2>>& biases);

// Throws core::InputError naming --odometry-noise (deviations outside
// [0, 1]) or --odometry-bias (biases outside [-0.5, 0.5]).
void CheckOdometryNoise(const OdometryNoise& noise);

}  // namespace pirouette::core
