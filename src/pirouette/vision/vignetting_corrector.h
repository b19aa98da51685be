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
//
// For a frame reduced by an integer factor (each pixel the mean of a block of
// scale × scale raw pixels) the factor of a pixel is the mean of its block's,
// so that correcting the reduced frame equals reducing the corrected one up to
// the (tiny) covariance of the factors and the colours within a block.
class VignettingCorrector {
 public:
  explicit VignettingCorrector(const camera::CameraModel& camera)
      : VignettingCorrector(camera, 1) {}
  // For frames reduced by `scale` >= 1: (width / scale) × (height / scale)
  // pixels, the partial blocks at the right and the bottom dropped.
  VignettingCorrector(const camera::CameraModel& camera, int scale);

  int width() const { return width_; }  // of the (reduced) frames it corrects
  int height() const { return height_; }
  int scale() const { return scale_; }

  // The corrected copy of a raw BGR frame; values saturate at 255.
  // The frame's size must be the camera's (a bug otherwise: callers check input).
  cv::Mat3b Apply(const cv::Mat3b& bgr_raw) const;
  // The same into `out`, (re)allocated unless it has the frame's size already,
  // so that a caller that keeps it allocates once. `out` may be `bgr_raw`.
  void Apply(const cv::Mat3b& bgr_raw, cv::Mat3b& out) const;

  // A raw frame of the camera's full size reduced by the scale (block means,
  // ReduceByBlockMean) and corrected, in one pass, into `out` (reallocated
  // unless it has the reduced size already). At scale 1 this is Apply.
  void ReduceAndApply(const cv::Mat3b& bgr_raw, cv::Mat3b& out) const;

  // The factor applied to channel c (0 B, 1 G, 2 R: OpenCV's order) at pixel (u, v).
  double Factor(int u, int v, int c) const;

 private:
  static constexpr int kShift = 12;  // fixed point: factor = gain_q_ / 2^kShift
  int scale_;
  int width_;
  int height_;
  std::vector<std::uint16_t> gain_q_;  // row-major, 3 per pixel, B G R
};

// `bgr` reduced by the integer factor `scale` >= 1: each pixel of `out` the
// mean of a scale × scale block (rounded to nearest), the partial blocks at
// the right and the bottom dropped. `out` is reallocated unless it has the
// reduced size already; it must not alias `bgr` unless scale is 1.
void ReduceByBlockMean(const cv::Mat3b& bgr, int scale, cv::Mat3b& out);

}  // namespace pirouette::vision
