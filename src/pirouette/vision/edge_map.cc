#include "pirouette/vision/edge_map.h"

#include <cmath>
#include <cstring>
#include <numbers>
#include <opencv2/imgproc.hpp>
#include <utility>

namespace pirouette::vision {
namespace {

int Reflect101(int i, int n) {
  while (i < 0 || i >= n) i = i < 0 ? -i : 2 * (n - 1) - i;
  return i;
}

// Per pixel u of a row, the gradient of the channel whose squared gradient
// is largest (the first on a tie), into out_x[u], out_y[u]: `g` holds the
// rows gx, gy of channel 0, then of 1 and 2, `stride` apart. Selects only, no
// branch, and unaliased pointers, so that the loop vectorises.
void PickStrongest(const std::int16_t* __restrict g, std::size_t stride, int width,
                   std::int16_t* __restrict out_x, std::int16_t* __restrict out_y) {
  const std::int16_t* x0 = g;
  const std::int16_t* y0 = g + stride;
  const std::int16_t* x1 = g + 2 * stride;
  const std::int16_t* y1 = g + 3 * stride;
  const std::int16_t* x2 = g + 4 * stride;
  const std::int16_t* y2 = g + 5 * stride;
  for (int u = 0; u < width; ++u) {
    const int n0 = x0[u] * x0[u] + y0[u] * y0[u];
    const int n1 = x1[u] * x1[u] + y1[u] * y1[u];
    const int n2 = x2[u] * x2[u] + y2[u] * y2[u];
    const bool first_two = n1 > n0;
    const int n01 = first_two ? n1 : n0;
    const std::int16_t sx01 = first_two ? x1[u] : x0[u];
    const std::int16_t sy01 = first_two ? y1[u] : y0[u];
    const bool last = n2 > n01;
    out_x[u] = last ? x2[u] : sx01;
    out_y[u] = last ? y2[u] : sy01;
  }
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
  dx_.create(bgr.size());
  dy_.create(bgr.size());
  // 3×3 Sobel of each channel (cv::Sobel's, BORDER_REFLECT_101): the
  // vertical [1 2 1] sums and [-1 0 1] differences of the three rows, one
  // pixel reflected either side, then the horizontal taps. The channel with the
  // largest squared gradient wins (the first on a tie), as in OpenCV's Canny.
  // The channels are split first (cv::split, OpenCV's SIMD deinterleave) so
  // that every loop below runs at unit stride and vectorises: picking the
  // channel from interleaved B, G, R took 40% of the paper's segmenter.
  cv::split(bgr, planes_.data());
  const std::size_t stride = static_cast<std::size_t>(width) + 2;
  rows_.resize(8 * stride);
  // Per channel c: gx and gy, [0, width); then the scratch sums, [-1, width].
  std::array<std::int16_t*, 3> gx{};
  std::array<std::int16_t*, 3> gy{};
  for (int c = 0; c < 3; ++c) {
    gx[c] = rows_.data() + 2 * c * stride;
    gy[c] = gx[c] + stride;
  }
  std::int16_t* smooth = rows_.data() + 6 * stride + 1;
  std::int16_t* diff = smooth + stride;
  for (int y = 0; y < height; ++y) {
    for (int c = 0; c < 3; ++c) {
      const cv::Mat& plane = planes_[c];
      const auto* above = plane.ptr<std::uint8_t>(Reflect101(y - 1, height));
      const auto* here = plane.ptr<std::uint8_t>(y);
      const auto* below = plane.ptr<std::uint8_t>(Reflect101(y + 1, height));
      for (int x = 0; x < width; ++x) {
        smooth[x] = static_cast<std::int16_t>(above[x] + 2 * here[x] + below[x]);
        diff[x] = static_cast<std::int16_t>(below[x] - above[x]);
      }
      smooth[-1] = smooth[1];
      diff[-1] = diff[1];
      smooth[width] = smooth[width - 2];
      diff[width] = diff[width - 2];
      std::int16_t* cx = gx[c];
      std::int16_t* cy = gy[c];
      for (int x = 0; x < width; ++x) {
        cx[x] = static_cast<std::int16_t>(smooth[x + 1] - smooth[x - 1]);
        cy[x] = static_cast<std::int16_t>(diff[x - 1] + 2 * diff[x] + diff[x + 1]);
      }
    }
    PickStrongest(rows_.data(), stride, width, dx_[y], dy_[y]);
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
    // Every edge pixel (Canny writes 255) a barrier, none vertical; then the edge pixels (few)
    // are tested one by one, eight non-edge pixels skipped at a time.
    std::memcpy(bar, e, static_cast<std::size_t>(width));
    std::memset(out, 0, static_cast<std::size_t>(width));
    for (int u = 0; u < width; ++u) {
      if (u + 8 <= width) {
        std::uint64_t eight = 0;
        std::memcpy(&eight, e + u, sizeof(eight));
        if (eight == 0) {
          u += 7;
          continue;
        }
      }
      if (e[u] == 0) continue;
      const float x = sx[u];
      const float y = sy[u];
      const float along = std::abs(x * up[u][0] + y * up[u][1]);
      if (along <= sin_tolerance_ * std::sqrt(x * x + y * y)) {
        out[u] = 255;
        bar[u] = 0;
      }
    }
  }
  return map_;
}

}  // namespace pirouette::vision
