// Helpers shared by the benchmarks: the world they render and the camera
// scaled to other resolutions.

#pragma once

#include <string>

#include "pirouette/camera/camera_model.h"
#include "pirouette/io/world_file.h"
#include "pirouette/sim/world.h"

namespace pirouette::bench {

inline const sim::World& SoccerField() {
  static const sim::World world =
      io::LoadWorldFile(std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml");
  return world;
}

// The paper's camera scaled to another resolution (same field of view).
inline camera::CameraModel Scaled(const camera::CameraModel& camera, int width, int height) {
  const double s = static_cast<double>(width) / camera.width();
  auto k = camera.intrinsics();
  k.fx *= s;
  k.fy *= s;
  k.cx = (k.cx + 0.5) * s - 0.5;
  k.cy = (k.cy + 0.5) * s - 0.5;
  return {camera.name(),      width, height, k, camera.distortion(), camera.mount(),
          camera.vignetting()};
}

}  // namespace pirouette::bench
