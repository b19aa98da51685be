#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/core/pose2.h"
#include "pirouette/eval/floor_masker.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::tools {

struct RopRequest {
  std::string world_path;
  core::Pose2 world_T_robot;
  std::string out_path;  // a PNG
  vision::MaskSource method = vision::MaskSource::kDefault;
  std::uint64_t seed = 1;             // the sensor noise and the odometry noise
  double cell_m = 0.01;               // the max range is derived for this cell size...
  std::optional<double> max_range_m;  // ...unless given
};

struct RopResult {
  mapping::RadialProfile rop;
  std::vector<double> low_pass;  // the ROP's ranges through the DCT low-pass
  // The world's geometry at each bin's centre bearing from the robot's centre
  // (sim::World::RayCast), capped at the max range: what the ROP should be.
  std::vector<double> truth;
};

// `pirouette rop`: the simulated robot, placed at the pose, makes one
// pirouette (12 turns of 30°); each frame is segmented (`method`), its
// obstacle profile extracted, the profiles merged into the Radial Obstacle
// Profile, and the ROP, its DCT low-pass (20 coefficients) and the truth are
// drawn as a polar plot like the paper's Fig. 2 into out_path. Throws
// core::InputError for a bad world, pose or max range (exit code 2),
// sim::RenderError or std::runtime_error when it cannot render or write (1).
RopResult MakeRop(const RopRequest& request);

}  // namespace pirouette::tools
