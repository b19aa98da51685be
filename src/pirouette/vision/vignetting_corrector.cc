#include "pirouette/vision/vignetting_corrector.h"

#include <algorithm>
#include <cmath>

namespace pirouette::vision {

VignettingCorrector::VignettingCorrector(const camera::CameraModel& camera)
    : width_(camera.width()),
      height_(camera.height()),
      gain_q_(static_cast<std::size_t>(camera.width()) * camera.height() * 3) {
  std::size_t i = 0;
  for (int v = 0; v < height_; ++v) {
    for (int u = 0; u < width_; ++u) {
      for (int c = 0; c < 3; ++c) {
        // OpenCV's channel c (B, G, R) is the camera's channel 2 - c (R, G, B).
        const double pass = camera.VignettingGain(2 - c, Eigen::Vector2d(u, v));
        const double factor = 1.0 / std::max(pass, 1e-3);
        gain_q_[i++] = static_cast<std::uint16_t>(
            std::min(65535.0, std::round(factor * static_cast<double>(1 << kShift))));
      }
    }
  }
}

double VignettingCorrector::Factor(int u, int v, int c) const {
  CV_Assert(u >= 0 && u < width_ && v >= 0 && v < height_ && c >= 0 && c < 3);
  return gain_q_[(static_cast<std::size_t>(v) * width_ + u) * 3 + c] /
         static_cast<double>(1 << kShift);
}

cv::Mat3b VignettingCorrector::Apply(const cv::Mat3b& bgr_raw) const {
  CV_Assert(bgr_raw.cols == width_ && bgr_raw.rows == height_);
  cv::Mat3b out(bgr_raw.size());
  const std::uint16_t* gain = gain_q_.data();
  constexpr std::uint32_t kHalf = 1u << (kShift - 1);
  for (int v = 0; v < height_; ++v) {
    const auto* in = bgr_raw.ptr<std::uint8_t>(v);
    auto* o = out.ptr<std::uint8_t>(v);
    for (int i = 0; i < width_ * 3; ++i) {
      const std::uint32_t value = (in[i] * static_cast<std::uint32_t>(gain[i]) + kHalf) >> kShift;
      o[i] = static_cast<std::uint8_t>(std::min<std::uint32_t>(value, 255));
    }
    gain += static_cast<std::size_t>(width_) * 3;
  }
  return out;
}

}  // namespace pirouette::vision
