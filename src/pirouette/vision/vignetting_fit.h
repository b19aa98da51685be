#pragma once

#include <array>
#include <opencv2/core.hpp>

#include "pirouette/camera/camera_model.h"

namespace pirouette::vision {

// The vignetting of a lens measured from one raw photo of a uniform, evenly
// lit surface that fills the view (a sheet of paper, a wall, a plain floor).
struct VignettingFit {
  camera::Vignetting vignetting;  // per channel R, G, B: k >= 0
  // Per channel R, G, B: the level at the principal point, 0–255 (the
  // surface's colour as the camera sees it, with the lens's tint).
  std::array<double, 3> centre_level = {0.0, 0.0, 0.0};
  // Per channel R, G, B: the RMS of the blocks' relative deviation from the
  // fitted model (a few 0.001 for a good flat field; 0.02 and more means the
  // surface or its light was not uniform).
  std::array<double, 3> rms_relative = {0.0, 0.0, 0.0};
  // Per channel R, G, B: true where the fit gave k < 0 (the corners brighter
  // than the centre: uneven light) and k was set to 0.
  std::array<bool, 3> clamped = {false, false, false};
  int blocks = 0;       // blocks of pixels in the photo
  int blocks_used = 0;  // of them, neither saturated, too dark nor outliers, in every channel
};

// Fits the camera model's vignetting (SPEC.md camera file: the lens passes
// 1 / (1 + k·ρ²) of the light, ρ = r / r_max, r the distance from the
// principal point) per channel R, G, B, the paper's §2.1 (Taylor, Geva & Boles
// 2005), which also takes out the lens's colour tint. The photo is averaged in
// square blocks; a block's level I = I₀ / (1 + k·ρ²) gives 1 / I = a + b·ρ²
// with k = b / a, fitted by least squares on the blocks neither saturated
// (any pixel >= 250) nor dark (mean < 8), then again twice without the blocks
// whose relative residual exceeds 4 robust standard deviations (the MAD's).
// `bgr`: the raw photo (8-bit BGR, not de-vignetted), of the camera's size (a
// bug otherwise: callers check input); only the camera's principal point and
// size are used. Throws std::invalid_argument when fewer than 20 blocks are
// usable (an over- or under-exposed photo).
VignettingFit FitVignetting(const cv::Mat3b& bgr, const camera::CameraModel& camera);

}  // namespace pirouette::vision
