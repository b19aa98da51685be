#include "pirouette/vision/texture_feature.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/imgproc.hpp>

#include "pirouette/vision/binomial_blur.h"

namespace pirouette::vision {
namespace {

constexpr int kGainShift = 14;              // the grey factor in fixed point, below 4
constexpr int kMaxMagnitude = 2 * 4 * 255;  // |Sobel_x| + |Sobel_y| of 8-bit grey

int Reflect101(int i, int n) {
  while (i < 0 || i >= n) i = i < 0 ? -i : 2 * (n - 1) - i;
  return i;
}

}  // namespace

TextureFeature::TextureFeature(int scale, int window, int blur_order,
                               const std::optional<VignettingCorrector>& corrector)
    : scale_(scale), before_(window / 2), after_(window - 1 - window / 2), blur_order_(blur_order) {
  CV_Assert(scale >= 1 && window >= 1 && blur_order >= 0 && blur_order % 2 == 0);
  const int side = scale + window - 1;
  // A column of the window sums at most `side` magnitudes in 16 bits.
  CV_Assert(side * kMaxMagnitude <= 65535);
  const int pixels = side * side;
  // The bin of a window's sum S (m = S / (8 · pixels)), and the least sum of
  // each bin: looked up on m to 1/64 grey level, then one comparison with the
  // next bin's least sum makes it exact (the bins' bounds lie further apart).
  const auto bin_of_sum = [&](double sum) {
    return static_cast<int>(std::min(kBins - 1.0, 3.0 * std::log2(1.0 + sum / (8.0 * pixels))));
  };
  for (int b = 1; b < kBins; ++b) {
    auto least = static_cast<std::uint32_t>(std::ceil(8.0 * pixels * (std::exp2(b / 3.0) - 1.0)));
    while (least > 0 && bin_of_sum(least - 1.0) >= b) --least;
    while (bin_of_sum(least) < b) ++least;
    least_sum_[b] = least;
  }
  least_sum_[kBins] = std::numeric_limits<std::uint32_t>::max();
  mean_scale_ = static_cast<std::uint32_t>(std::floor(64.0 * 65536.0 / (8.0 * pixels)));
  for (std::size_t i = 0; i < bin_of_mean_.size(); ++i) {
    // The bin of the least sum whose quantised mean is i.
    bin_of_mean_[i] = static_cast<std::uint8_t>(
        bin_of_sum(std::ceil(static_cast<double>(i) * 65536.0 / mean_scale_)));
  }
  if (corrector) {
    gain_size_ = cv::Size(corrector->width(), corrector->height());
    grey_gain_q_.resize(static_cast<std::size_t>(gain_size_.area()));
    std::size_t i = 0;
    for (int v = 0; v < gain_size_.height; ++v) {
      for (int u = 0; u < gain_size_.width; ++u) {
        // cv::COLOR_BGR2GRAY's weights on the factors of B, G, R.
        const double factor = 0.114 * corrector->Factor(u, v, 0) +
                              0.587 * corrector->Factor(u, v, 1) +
                              0.299 * corrector->Factor(u, v, 2);
        grey_gain_q_[i++] = static_cast<std::uint16_t>(
            std::min(65535.0, std::round(factor * static_cast<double>(1 << kGainShift))));
        // (factors of 4 and more, a lens passing under a quarter of the light, saturate)
      }
    }
  }
}

const cv::Mat1b& TextureFeature::Bins(const cv::Mat3b& bgr_raw) {
  const int width = bgr_raw.cols;
  const int height = bgr_raw.rows;
  CV_Assert(width >= scale_ && height >= scale_ && width >= 2 && height >= 2);
  cv::cvtColor(bgr_raw, grey_, cv::COLOR_BGR2GRAY);
  if (!grey_gain_q_.empty()) {
    CV_Assert(bgr_raw.size() == gain_size_ && grey_.isContinuous());
    // grey · factor: the high half of (grey · 256) · (factor · 2^14), over 64.
    auto* g = grey_.ptr<std::uint8_t>(0);
    const std::uint16_t* gain = grey_gain_q_.data();
    const std::size_t n = grey_gain_q_.size();
    for (std::size_t i = 0; i < n; ++i) {
      const auto high = static_cast<std::uint16_t>(
          (static_cast<std::uint32_t>(static_cast<std::uint16_t>(g[i] << 8)) * gain[i]) >> 16);
      const auto value = static_cast<std::uint16_t>((high + 32) >> 6);
      g[i] = static_cast<std::uint8_t>(value < 255 ? value : 255);
    }
  }
  BinomialBlur(grey_, blurred_, blur_order_);

  // |Sobel_x| + |Sobel_y| (3×3, BORDER_REFLECT_101) of the low-passed grey,
  // at most 2040: 16-bit arithmetic throughout.
  magnitude_.create(bgr_raw.size());
  smooth_.resize(static_cast<std::size_t>(width) + 2);
  diff_.resize(static_cast<std::size_t>(width) + 2);
  std::int16_t* smooth = smooth_.data() + 1;  // [-1, width]
  std::int16_t* diff = diff_.data() + 1;
  for (int y = 0; y < height; ++y) {
    const auto* above = blurred_.ptr<std::uint8_t>(Reflect101(y - 1, height));
    const auto* here = blurred_.ptr<std::uint8_t>(y);
    const auto* below = blurred_.ptr<std::uint8_t>(Reflect101(y + 1, height));
    for (int x = 0; x < width; ++x) {
      smooth[x] = static_cast<std::int16_t>(above[x] + 2 * here[x] + below[x]);
      diff[x] = static_cast<std::int16_t>(below[x] - above[x]);
    }
    smooth[-1] = smooth[1];
    diff[-1] = diff[1];
    smooth[width] = smooth[width - 2];
    diff[width] = diff[width - 2];
    std::uint16_t* m = magnitude_[y];
    for (int x = 0; x < width; ++x) {
      const auto gx = static_cast<std::int16_t>(smooth[x + 1] - smooth[x - 1]);
      const auto gy = static_cast<std::int16_t>(diff[x - 1] + 2 * diff[x] + diff[x + 1]);
      const auto ax = static_cast<std::int16_t>(gx < 0 ? -gx : gx);
      const auto ay = static_cast<std::int16_t>(gy < 0 ? -gy : gy);
      m[x] = static_cast<std::uint16_t>(ax + ay);
    }
  }

  // Each cell's window: the columns' sums over its rows, then the sum of
  // those over its columns by a running sum along the row, reflected at its
  // ends into the padding of `before_` and `after_` columns.
  const int cells_x = width / scale_;
  const int cells_y = height / scale_;
  bins_.create(cells_y, cells_x);
  const int padded = width + before_ + after_;
  columns_.resize(static_cast<std::size_t>(padded));
  running_.resize(static_cast<std::size_t>(padded) + 1);
  std::uint16_t* columns = columns_.data() + before_;
  const auto top = static_cast<std::uint32_t>(bin_of_mean_.size() - 1);
  for (int cy = 0; cy < cells_y; ++cy) {
    const int first_row = cy * scale_ - before_;
    const std::uint16_t* m0 = magnitude_[Reflect101(first_row, height)];
    std::copy(m0, m0 + width, columns);
    for (int y = first_row + 1; y <= cy * scale_ + scale_ - 1 + after_; ++y) {
      const std::uint16_t* m = magnitude_[Reflect101(y, height)];
      for (int x = 0; x < width; ++x) columns[x] = static_cast<std::uint16_t>(columns[x] + m[x]);
    }
    for (int k = 1; k <= before_; ++k) columns[-k] = columns[Reflect101(-k, width)];
    for (int k = 0; k < after_; ++k) columns[width + k] = columns[Reflect101(width + k, width)];
    running_[0] = 0;
    const std::uint16_t* padded_columns = columns - before_;
    for (int k = 0; k < padded; ++k) running_[k + 1] = running_[k] + padded_columns[k];
    std::uint8_t* out = bins_[cy];
    const int span = scale_ + before_ + after_;
    for (int cx = 0; cx < cells_x; ++cx) {
      const std::size_t first = static_cast<std::size_t>(cx) * scale_;
      const std::uint32_t sum = running_[first + span] - running_[first];
      const std::uint8_t bin = bin_of_mean_[std::min((sum * mean_scale_) >> 16, top)];
      out[cx] = sum >= least_sum_[bin + 1] ? bin + 1 : bin;
    }
  }
  return bins_;
}

}  // namespace pirouette::vision
