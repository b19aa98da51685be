#pragma once

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/angle.h"

namespace pirouette::testing {

// The paper's camera (worlds/yujin.yaml): 320×240, 60° across, barrel
// distortion, 0.11 m up, tilted 30° down, vignetting. For tests.
inline camera::CameraModel PaperCamera() {
  return camera::CameraModel("yujin", 320, 240, {277.128129211, 277.128129211, 159.5, 119.5},
                             {-0.20, 0.05, 0.0, 0.0, 0.0}, {0.11, core::DegToRad(30.0), 0.03},
                             {{0.35, 0.30, 0.40}});
}

}  // namespace pirouette::testing
