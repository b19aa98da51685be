#include "pirouette/vision/edge_map.h"

#include <cmath>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <utility>

namespace pirouette::vision {
namespace {

int Reflect101(int i, int n) {
  while (i < 0 || i >= n) i = i < 0 ? -i : 2 * (n - 1) - i;
  return i;
}

}  // namespace

EdgeMap FindEdges(const cv::Mat3b& bgr, const VerticalDirectionField& vertical,
                  const EdgeMapOptions& options) {
  EdgeDetector detector(vertical, options);
  return detector.Find(bgr);
}

EdgeDetector::EdgeDetector(VerticalDirectionField vertical, const EdgeMapOptions& options)
    : vertical_(std::move(vertical)),
      options_(options),
      sin_tolerance_(
          static_cast<float>(std::sin(options.vertical_tolerance_deg * std::numbers::pi / 180.0))) {
}

const EdgeMap& EdgeDetector::Find(const cv::Mat3b& bgr) {
  CV_Assert(bgr.cols == vertical_.width() && bgr.rows == vertical_.height());
  CV_Assert(bgr.cols >= 2 && bgr.rows >= 2);
  const int width = bgr.cols;
  const int height = bgr.rows;
  const int n = 3 * width;
  dx_.create(bgr.size());
  dy_.create(bgr.size());
  // 3×3 Sobel of each channel (cv::Sobel's, BORDER_REFLECT_101): the
  // vertical [1 2 1] sums and [-1 0 1] differences of the three rows, one
  // pixel reflected either side, then the horizontal taps. The channel with the
  // largest squared gradient wins (the first on a tie), as in OpenCV's Canny.
  rows_.resize(4 * (static_cast<std::size_t>(n) + 6));
  std::int16_t* smooth = rows_.data() + 3;  // [-3, n + 3)
  std::int16_t* diff = smooth + n + 6;      // [-3, n + 3)
  std::int16_t* gx = diff + n + 6;          // [0, n)
  std::int16_t* gy = gx + n + 6;
  for (int y = 0; y < height; ++y) {
    const auto* above = bgr.ptr<std::uint8_t>(Reflect101(y - 1, height));
    const auto* here = bgr.ptr<std::uint8_t>(y);
    const auto* below = bgr.ptr<std::uint8_t>(Reflect101(y + 1, height));
    for (int i = 0; i < n; ++i) {
      smooth[i] = static_cast<std::int16_t>(above[i] + 2 * here[i] + below[i]);
      diff[i] = static_cast<std::int16_t>(below[i] - above[i]);
    }
    for (int c = 0; c < 3; ++c) {
      smooth[c - 3] = smooth[3 + c];
      diff[c - 3] = diff[3 + c];
      smooth[n + c] = smooth[n - 6 + c];
      diff[n + c] = diff[n - 6 + c];
    }
    for (int i = 0; i < n; ++i) {
      gx[i] = static_cast<std::int16_t>(smooth[i + 3] - smooth[i - 3]);
      gy[i] = static_cast<std::int16_t>(diff[i - 3] + 2 * diff[i] + diff[i + 3]);
    }
    std::int16_t* out_x = dx_[y];
    std::int16_t* out_y = dy_[y];
    for (int u = 0; u < width; ++u) {
      const std::int16_t* x3 = gx + static_cast<std::ptrdiff_t>(3) * u;
      const std::int16_t* y3 = gy + static_cast<std::ptrdiff_t>(3) * u;
      const int n0 = x3[0] * x3[0] + y3[0] * y3[0];
      const int n1 = x3[1] * x3[1] + y3[1] * y3[1];
      const int n2 = x3[2] * x3[2] + y3[2] * y3[2];
      const bool first_two = n1 > n0;
      const bool last = n2 > (first_two ? n1 : n0);
      out_x[u] = last ? x3[2] : (first_two ? x3[1] : x3[0]);
      out_y[u] = last ? y3[2] : (first_two ? y3[1] : y3[0]);
    }
  }
  cv::Canny(dx_, dy_, map_.edges, options_.canny_low, options_.canny_high, /*L2gradient=*/true);
  map_.vertical.create(bgr.size());
  barrier_.create(bgr.size());
  for (int v = 0; v < height; ++v) {
    const std::uint8_t* e = map_.edges[v];
    const std::int16_t* sx = dx_[v];
    const std::int16_t* sy = dy_[v];
    const cv::Vec2f* up = vertical_.directions()[v];
    std::uint8_t* out = map_.vertical[v];
    std::uint8_t* bar = barrier_[v];
    for (int u = 0; u < width; ++u) {
      std::uint8_t is_vertical = 0;
      if (e[u] != 0) {
        const float x = sx[u];
        const float y = sy[u];
        const float along = std::abs(x * up[u][0] + y * up[u][1]);
        if (along <= sin_tolerance_ * std::sqrt(x * x + y * y)) is_vertical = 255;
      }
      out[u] = is_vertical;
      bar[u] = e[u] != 0 && is_vertical == 0 ? 255 : 0;
    }
  }
  return map_;
}

}  // namespace pirouette::vision
