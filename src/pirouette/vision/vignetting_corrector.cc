#include "pirouette/vision/vignetting_corrector.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace pirouette::vision {

VignettingCorrector::VignettingCorrector(const camera::CameraModel& camera, int scale)
    : scale_(scale),
      width_(camera.width() / std::max(scale, 1)),
      height_(camera.height() / std::max(scale, 1)) {
  CV_Assert(scale >= 1 && width_ >= 1 && height_ >= 1);
  gain_q_.resize(static_cast<std::size_t>(width_) * height_ * 3);
  std::size_t i = 0;
  for (int v = 0; v < height_; ++v) {
    for (int u = 0; u < width_; ++u) {
      for (int c = 0; c < 3; ++c) {
        double sum = 0.0;
        for (int dv = 0; dv < scale; ++dv) {
          for (int du = 0; du < scale; ++du) {
            // OpenCV's channel c (B, G, R) is the camera's channel 2 - c (R, G, B).
            const Eigen::Vector2d pixel(u * scale + du, v * scale + dv);
            sum += 1.0 / std::max(camera.VignettingGain(2 - c, pixel), 1e-3);
          }
        }
        const double factor = sum / (scale * scale);
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
  cv::Mat3b out;
  Apply(bgr_raw, out);
  return out;
}

void VignettingCorrector::Apply(const cv::Mat3b& bgr_raw, cv::Mat3b& out) const {
  CV_Assert(bgr_raw.cols == width_ && bgr_raw.rows == height_);
  out.create(bgr_raw.size());
  const std::uint16_t* gain = gain_q_.data();
  constexpr std::uint32_t kHalf = 1u << (kShift - 1);
  // The bounds in locals: the byte stores may alias the members, which would
  // keep the loop from vectorising.
  const int n = 3 * width_;
  const int height = height_;
  for (int v = 0; v < height; ++v) {
    const auto* in = bgr_raw.ptr<std::uint8_t>(v);
    auto* o = out.ptr<std::uint8_t>(v);
    for (int i = 0; i < n; ++i) {
      const std::uint32_t value = (in[i] * static_cast<std::uint32_t>(gain[i]) + kHalf) >> kShift;
      o[i] = static_cast<std::uint8_t>(std::min<std::uint32_t>(value, 255));
    }
    gain += n;
  }
}

namespace {

// The block sums of `bgr`: `scale` rows summed by column, then `scale`
// pixels along the row (Scale: the scale known when compiling, 0 if not).
// The sums of a reduced row, 3 · width values in its order, are handed to
// `finish(sums, v, out_row)`.
template <int Scale, typename Finish>
void ReduceBlocks(const cv::Mat3b& bgr, int scale, cv::Mat3b& out,
                  std::vector<std::uint16_t>& buffer, Finish finish) {
  if constexpr (Scale > 0) scale = Scale;
  const int width = bgr.cols / scale;
  const int height = bgr.rows / scale;
  const int n = width * scale * 3;
  buffer.resize(static_cast<std::size_t>(n) + 3 * static_cast<std::size_t>(width));
  std::uint16_t* columns = buffer.data();
  std::uint16_t* sums = columns + n;
  for (int v = 0; v < height; ++v) {
    const auto* first = bgr.ptr<std::uint8_t>(v * scale);
    for (int i = 0; i < n; ++i) columns[i] = first[i];
    for (int k = 1; k < scale; ++k) {
      const auto* row = bgr.ptr<std::uint8_t>(v * scale + k);
      for (int i = 0; i < n; ++i) columns[i] = static_cast<std::uint16_t>(columns[i] + row[i]);
    }
    // Along the row, for a power of two: neighbours 3, then 6, … values apart
    // summed in place (a block's sum ends at its first pixel), then gathered.
    if ((scale & (scale - 1)) == 0) {
      for (int span = 1; span < scale; span *= 2) {
        const int offset = 3 * span;
        for (int i = 0; i + offset < n; ++i) {
          columns[i] = static_cast<std::uint16_t>(columns[i] + columns[i + offset]);
        }
      }
      for (int u = 0; u < width; ++u) {
        for (int c = 0; c < 3; ++c) sums[3 * u + c] = columns[3 * u * scale + c];
      }
    } else {
      for (int u = 0; u < width; ++u) {
        for (int c = 0; c < 3; ++c) {
          std::uint32_t sum = 0;
          for (int k = 0; k < scale; ++k) sum += columns[3 * (u * scale + k) + c];
          sums[3 * u + c] = static_cast<std::uint16_t>(sum);
        }
      }
    }
    finish(sums, v, out.ptr<std::uint8_t>(v));
  }
}

template <typename Finish>
void Reduce(const cv::Mat3b& bgr, int scale, cv::Mat3b& out, Finish finish) {
  CV_Assert(scale >= 1 && bgr.cols / scale >= 1 && bgr.rows / scale >= 1);
  CV_Assert(255 * scale * scale <= 65535 && (scale == 1 || out.data != bgr.data));
  out.create(bgr.rows / scale, bgr.cols / scale);
  std::vector<std::uint16_t> buffer;
  switch (scale) {
    case 2:
      ReduceBlocks<2>(bgr, scale, out, buffer, finish);
      break;
    case 4:
      ReduceBlocks<4>(bgr, scale, out, buffer, finish);
      break;
    default:
      ReduceBlocks<0>(bgr, scale, out, buffer, finish);
  }
}

}  // namespace

void VignettingCorrector::ReduceAndApply(const cv::Mat3b& bgr_raw, cv::Mat3b& out) const {
  if (scale_ == 1) {
    Apply(bgr_raw, out);
    return;
  }
  CV_Assert(bgr_raw.cols / scale_ == width_ && bgr_raw.rows / scale_ == height_);
  // The mean times the factor: sum · gain / (scale² · 2^kShift), rounded. In
  // 32 bits while the product fits (scale 4 and factors up to 16).
  const std::uint64_t divisor = static_cast<std::uint64_t>(scale_) * scale_ << kShift;
  const std::uint16_t* gain = gain_q_.data();
  const bool power_of_two = (scale_ & (scale_ - 1)) == 0;
  const int n = 3 * width_;
  if (power_of_two && 255ull * scale_ * scale_ * 65535ull + divisor / 2 < (1ull << 32)) {
    int shift = 0;
    while ((std::uint64_t{1} << shift) < divisor) ++shift;
    const auto half = static_cast<std::uint32_t>(divisor / 2);
    Reduce(bgr_raw, scale_, out, [&](const std::uint16_t* sums, int v, std::uint8_t* o) {
      const std::uint16_t* g = gain + static_cast<std::ptrdiff_t>(v) * n;
      for (int i = 0; i < n; ++i) {
        const std::uint32_t value = (sums[i] * static_cast<std::uint32_t>(g[i]) + half) >> shift;
        o[i] = static_cast<std::uint8_t>(value < 255 ? value : 255);
      }
    });
    return;
  }
  Reduce(bgr_raw, scale_, out, [&](const std::uint16_t* sums, int v, std::uint8_t* o) {
    const std::uint16_t* g = gain + static_cast<std::ptrdiff_t>(v) * n;
    for (int i = 0; i < n; ++i) {
      const std::uint64_t value =
          (static_cast<std::uint64_t>(sums[i]) * g[i] + divisor / 2) / divisor;
      o[i] = static_cast<std::uint8_t>(std::min<std::uint64_t>(value, 255));
    }
  });
}

void ReduceByBlockMean(const cv::Mat3b& bgr, int scale, cv::Mat3b& out) {
  if (scale == 1) {
    if (out.data != bgr.data) bgr.copyTo(out);
    return;
  }
  const auto area = static_cast<std::uint32_t>(scale * scale);
  const int n = 3 * (bgr.cols / scale);
  Reduce(bgr, scale, out, [&](const std::uint16_t* sums, int, std::uint8_t* o) {
    for (int i = 0; i < n; ++i) o[i] = static_cast<std::uint8_t>((sums[i] + area / 2) / area);
  });
}

}  // namespace pirouette::vision
