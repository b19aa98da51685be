#include "pirouette/sim/drifted_odometry.h"

#include <algorithm>
#include <cmath>
#include <random>

#include "pirouette/core/angle.h"
#include "pirouette/sim/seeded_random.h"

namespace pirouette::sim {

std::vector<core::Pose2> DriftedOdometry(const std::vector<core::Pose2>& truth,
                                         const core::OdometryNoise& noise, std::uint64_t seed) {
  std::vector<core::Pose2> odometry;
  if (truth.empty()) return odometry;
  odometry.reserve(truth.size());
  odometry.push_back(truth.front());
  std::mt19937_64 rng(seed);
  // What the encoders say of a part the robot made: the part over its error.
  constexpr double kMinFactor = 0.1;
  const auto reported = [&](double made, double bias, double sigma) {
    const double factor = std::max(1.0 + bias + sigma * StandardNormal(rng), kMinFactor);
    return made / factor;
  };
  // A step shorter than this is a turn on the spot.
  constexpr double kSamePlaceM = 1e-6;
  for (std::size_t k = 1; k < truth.size(); ++k) {
    const core::Pose2 step = truth[k - 1].Inverse() * truth[k];
    const double distance = step.translation().norm();
    core::Pose2 said;
    if (distance > kSamePlaceM) {
      const double first = std::atan2(step.y(), step.x());
      const double second = core::NormalizeAngle(step.heading() - first);
      said = core::Pose2(0.0, 0.0, reported(first, noise.rotation_bias, noise.rotation)) *
             core::Pose2(reported(distance, noise.translation_bias, noise.translation), 0.0, 0.0) *
             core::Pose2(0.0, 0.0, reported(second, noise.rotation_bias, noise.rotation));
    } else {
      said = core::Pose2(0.0, 0.0, reported(step.heading(), noise.rotation_bias, noise.rotation));
    }
    odometry.push_back(odometry.back() * said);
  }
  return odometry;
}

}  // namespace pirouette::sim
