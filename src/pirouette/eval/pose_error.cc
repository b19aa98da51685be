#include "pirouette/eval/pose_error.h"

#include <algorithm>
#include <cmath>
#include <numbers>

#include "pirouette/core/angle.h"

namespace pirouette::eval {

std::optional<PoseError> PoseErrorOf(const std::vector<core::Pose2>& believed,
                                     const std::vector<core::Pose2>& truth) {
  const std::size_t n = std::min(believed.size(), truth.size());
  if (n == 0) return std::nullopt;
  PoseError error;
  for (std::size_t i = 0; i < n; ++i) {
    const double m = (believed[i].translation() - truth[i].translation()).norm();
    const double deg = std::abs(core::NormalizeAngle(believed[i].heading() - truth[i].heading())) *
                       180.0 / std::numbers::pi;
    error.mean_m += m;
    error.mean_deg += deg;
    error.ate_rms_m += m * m;
    error.heading_rms_deg += deg * deg;
    error.max_m = std::max(error.max_m, m);
    error.final_m = m;
    error.final_deg = deg;
  }
  error.mean_m /= static_cast<double>(n);
  error.mean_deg /= static_cast<double>(n);
  error.ate_rms_m = std::sqrt(error.ate_rms_m / static_cast<double>(n));
  error.heading_rms_deg = std::sqrt(error.heading_rms_deg / static_cast<double>(n));
  return error;
}

void SetFinalError(PoseError& error, const core::Pose2& believed, const core::Pose2& truth) {
  error.final_m = (believed.translation() - truth.translation()).norm();
  error.final_deg = std::abs(core::NormalizeAngle(believed.heading() - truth.heading())) * 180.0 /
                    std::numbers::pi;
}

}  // namespace pirouette::eval
