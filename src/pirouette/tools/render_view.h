#pragma once

#include <string>

#include "pirouette/core/pose2.h"

namespace pirouette::tools {

struct RenderViewRequest {
  std::string world_path;
  core::Pose2 world_T_robot;
  std::string out_path;  // a PNG
  std::uint64_t seed = 1;
};

// `pirouette render`: what the world's camera sees with the robot at a pose,
// with the camera's distortion, vignetting and noise, written as a PNG.
// Throws core::InputError for a bad world or pose (exit code 2),
// sim::RenderError or std::runtime_error when it cannot render or write (1).
void RenderView(const RenderViewRequest& request);

}  // namespace pirouette::tools
