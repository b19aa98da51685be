#pragma once

#include <optional>
#include <vector>

#include "pirouette/core/pose2.h"

namespace pirouette::eval {

// How far the robot's belief was from the simulator's truth (translation in
// metres, heading in degrees, absolute): the mean and largest over the
// frames (each where the caller says it is believed: the explorer gives
// where the map puts it at the end), and at the end of the run.
struct PoseError {
  double final_m = 0.0;
  double final_deg = 0.0;
  double mean_m = 0.0;
  double mean_deg = 0.0;
  double max_m = 0.0;
  // The root mean square over the frames: the absolute trajectory error
  // (Sturm et al. 2012, without an alignment: the map frame is the start's).
  double ate_rms_m = 0.0;
  double heading_rms_deg = 0.0;
};

// The error of the believed poses against the true ones, frame by frame
// (their counts may differ by a frame taken as the run was stopped), with the
// final error that of the last frames; none without frames.
std::optional<PoseError> PoseErrorOf(const std::vector<core::Pose2>& believed,
                                     const std::vector<core::Pose2>& truth);

// Sets the error's final_m and final_deg to those of `believed` against `truth`.
void SetFinalError(PoseError& error, const core::Pose2& believed, const core::Pose2& truth);

}  // namespace pirouette::eval
