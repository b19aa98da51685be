#include "pirouette/vision/binomial_blur.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pirouette::vision {
namespace {

// OpenCV's BORDER_REFLECT_101 (…cb|abcd|cb…) for an index that may lie
// outside [0, n); n >= 2.
int Reflect101(int i, int n) {
  while (i < 0 || i >= n) i = i < 0 ? -i : 2 * (n - 1) - i;
  return i;
}

// One pass of order 2 or 4. Vertical sums go to a row of 16-bit values with
// `radius` reflected pixels either side, then the horizontal taps: at most
// 255 · 2^order · 2^order = 65280, so 16 bits hold every sum.
void BlurPass(const cv::Mat& src, cv::Mat& dst, int order, std::vector<std::uint16_t>& row) {
  const int channels = src.channels();
  const int width = src.cols;
  const int height = src.rows;
  const int radius = order / 2;
  const int n = width * channels;
  row.resize(static_cast<std::size_t>(width + 2 * radius) * channels);
  std::uint16_t* acc = row.data() + static_cast<std::ptrdiff_t>(radius) * channels;
  for (int y = 0; y < height; ++y) {
    auto* out = dst.ptr<std::uint8_t>(y);
    if (order == 2) {
      const auto* r0 = src.ptr<std::uint8_t>(Reflect101(y - 1, height));
      const auto* r1 = src.ptr<std::uint8_t>(y);
      const auto* r2 = src.ptr<std::uint8_t>(Reflect101(y + 1, height));
      for (int i = 0; i < n; ++i) {
        acc[i] = static_cast<std::uint16_t>(r0[i] + 2 * r1[i] + r2[i]);
      }
    } else {
      const auto* r0 = src.ptr<std::uint8_t>(Reflect101(y - 2, height));
      const auto* r1 = src.ptr<std::uint8_t>(Reflect101(y - 1, height));
      const auto* r2 = src.ptr<std::uint8_t>(y);
      const auto* r3 = src.ptr<std::uint8_t>(Reflect101(y + 1, height));
      const auto* r4 = src.ptr<std::uint8_t>(Reflect101(y + 2, height));
      for (int i = 0; i < n; ++i) {
        acc[i] = static_cast<std::uint16_t>(r0[i] + r4[i] + 4 * (r1[i] + r3[i]) + 6 * r2[i]);
      }
    }
    for (int k = 1; k <= radius; ++k) {
      for (int c = 0; c < channels; ++c) {
        acc[-k * channels + c] = acc[Reflect101(-k, width) * channels + c];
        acc[(width - 1 + k) * channels + c] = acc[Reflect101(width - 1 + k, width) * channels + c];
      }
    }
    const std::uint16_t* m1 = acc - channels;
    const std::uint16_t* p1 = acc + channels;
    if (order == 2) {
      for (int i = 0; i < n; ++i) {
        out[i] = static_cast<std::uint8_t>((m1[i] + 2 * acc[i] + p1[i] + 8) >> 4);
      }
    } else {
      const std::uint16_t* m2 = acc - static_cast<std::ptrdiff_t>(2) * channels;
      const std::uint16_t* p2 = acc + static_cast<std::ptrdiff_t>(2) * channels;
      for (int i = 0; i < n; ++i) {
        out[i] = static_cast<std::uint8_t>(
            (m2[i] + p2[i] + 4 * (m1[i] + p1[i]) + 6 * acc[i] + 128) >> 8);
      }
    }
  }
}

}  // namespace

int BinomialOrder(double sigma) {
  if (!(sigma > 0.0)) return 0;
  return 2 * static_cast<int>(std::lround(2.0 * sigma * sigma));
}

void BinomialBlur(const cv::Mat& src, cv::Mat& dst, int order) {
  CV_Assert(src.depth() == CV_8U && (src.channels() == 1 || src.channels() == 3));
  CV_Assert(order >= 0 && order % 2 == 0);
  CV_Assert(dst.data == nullptr || dst.data != src.data);
  dst.create(src.size(), src.type());
  if (order == 0) {
    src.copyTo(dst);
    return;
  }
  CV_Assert(src.cols >= 2 && src.rows >= 2);
  std::vector<std::uint16_t> row;
  // Passes before the last go to two scratch images in turn; the last to dst.
  std::array<cv::Mat, 2> between;
  cv::Mat from = src;
  for (int remaining = order, i = 0; remaining > 0; ++i) {
    const int pass = std::min(4, remaining);
    remaining -= pass;
    cv::Mat& to = remaining > 0 ? between[i % 2] : dst;
    to.create(src.size(), src.type());
    BlurPass(from, to, pass, row);
    from = to;
  }
}

}  // namespace pirouette::vision
