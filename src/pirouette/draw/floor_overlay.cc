#include "pirouette/draw/floor_overlay.h"

#include <cstdint>
#include <opencv2/imgproc.hpp>

#include "pirouette/draw/palette.h"

namespace pirouette::draw {

cv::Mat3b DrawFloorOverlay(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask) {
  CV_Assert(bgr.size() == floor_mask.size());
  cv::Mat3b out = bgr.clone();
  cv::Mat1b inner;
  cv::erode(floor_mask, inner, cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3)));
  for (int v = 0; v < out.rows; ++v) {
    for (int u = 0; u < out.cols; ++u) {
      if (floor_mask(v, u) == 0) continue;
      cv::Vec3b& p = out(v, u);
      if (inner(v, u) == 0) {
        p = kFloorEdgeColour;
      } else {
        p = cv::Vec3b(static_cast<std::uint8_t>(p[0] / 2),
                      static_cast<std::uint8_t>(p[1] / 2 + kFloorTintGreen),
                      static_cast<std::uint8_t>(p[2] / 2));
      }
    }
  }
  return out;
}

}  // namespace pirouette::draw
