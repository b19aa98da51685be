#include "pirouette/vision/edge_map.h"

#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>

namespace pirouette::vision {

EdgeMap FindEdges(const cv::Mat3b& bgr, const VerticalDirectionField& vertical,
                  const EdgeMapOptions& options) {
  CV_Assert(bgr.cols == vertical.width() && bgr.rows == vertical.height());
  cv::Mat dx3;
  cv::Mat dy3;
  cv::Sobel(bgr, dx3, CV_16S, 1, 0, 3);
  cv::Sobel(bgr, dy3, CV_16S, 0, 1, 3);
  cv::Mat dx(bgr.size(), CV_16SC1);
  cv::Mat dy(bgr.size(), CV_16SC1);
  for (int v = 0; v < bgr.rows; ++v) {
    const auto* x3 = dx3.ptr<cv::Vec3s>(v);
    const auto* y3 = dy3.ptr<cv::Vec3s>(v);
    auto* x = dx.ptr<std::int16_t>(v);
    auto* y = dy.ptr<std::int16_t>(v);
    for (int u = 0; u < bgr.cols; ++u) {
      int best = 0;
      int best_norm = -1;
      for (int c = 0; c < 3; ++c) {
        const int norm = x3[u][c] * x3[u][c] + y3[u][c] * y3[u][c];
        if (norm > best_norm) {
          best_norm = norm;
          best = c;
        }
      }
      x[u] = x3[u][best];
      y[u] = y3[u][best];
    }
  }
  const cv::Size size = bgr.size();
  EdgeMap map;
  cv::Canny(dx, dy, map.edges, options.canny_low, options.canny_high, /*L2gradient=*/true);
  map.vertical = cv::Mat1b(size, std::uint8_t{0});
  const auto sin_tolerance =
      static_cast<float>(std::sin(options.vertical_tolerance_deg * std::numbers::pi / 180.0));
  for (int v = 0; v < size.height; ++v) {
    const std::uint8_t* e = map.edges[v];
    const auto* gx = dx.ptr<std::int16_t>(v);
    const auto* gy = dy.ptr<std::int16_t>(v);
    const cv::Vec2f* up = vertical.directions()[v];
    std::uint8_t* out = map.vertical[v];
    for (int u = 0; u < size.width; ++u) {
      if (e[u] == 0) continue;
      const float x = gx[u];
      const float y = gy[u];
      const float along = std::abs(x * up[u][0] + y * up[u][1]);
      if (along <= sin_tolerance * std::sqrt(x * x + y * y)) out[u] = 255;
    }
  }
  return map;
}

}  // namespace pirouette::vision
