#pragma once

#include <cstdint>
#include <opencv2/core.hpp>
#include <opencv2/imgproc.hpp>

#include "pirouette/core/image.h"

namespace pirouette::testing {

// A rendered frame (RGB) as the segmenters take it: a cv::Mat3b in OpenCV's
// BGR order, a copy. For tests of vision/ on the simulator's frames (the
// run's own conversion is io::ToBgrMat; vision/ does not reach up to io/).
inline cv::Mat3b BgrFrame(const core::ImageRgb8& rgb) {
  const cv::Mat wrapped(rgb.height(), rgb.width(), CV_8UC3,
                        const_cast<std::uint8_t*>(rgb.data()));  // NOLINT: read only
  cv::Mat3b bgr;
  cv::cvtColor(wrapped, bgr, cv::COLOR_RGB2BGR);
  return bgr;
}

}  // namespace pirouette::testing
