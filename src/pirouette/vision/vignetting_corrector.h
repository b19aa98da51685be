#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "pirouette/camera/camera_model.h"

namespace pirouette::vision {

// Anti-vignetting (Taylor, Geva & Boles 2005, §4.1): each raw pixel is
// multiplied, per channel R, G, B, by the inverse of the camera's vignetting
// gain at that pixel, which grows with the square of its distance from the
// principal point and also removes the lens's colour tint. The gains are a
// lookup table built once (16-bit fixed point, one per pixel and channel), so
// a frame costs one multiply-shift per byte. The image is not undistorted:
// segmentation runs on the raw image and the IPM lookup maps its pixels to the floor.
class VignettingCorrector {
 public:
  explicit VignettingCorrector(const camera::CameraModel& camera);

  int width() const { return width_; }
  int height() const { return height_; }

  // The corrected copy of a raw BGR frame; values saturate at 255.
  // The frame's size must be the camera's (a bug otherwise: callers check input).
  cv::Mat3b Apply(const cv::Mat3b& bgr_raw) const;

  // The factor applied to channel c (0 B, 1 G, 2 R: OpenCV's order) at pixel (u, v).
  double Factor(int u, int v, int c) const;

 private:
  static constexpr int kShift = 12;  // fixed point: factor = gain_q_ / 2^kShift
  int width_;
  int height_;
  std::vector<std::uint16_t> gain_q_;  // row-major, 3 per pixel, B G R
};

}  // namespace pirouette::vision
