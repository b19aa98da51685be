#include "pirouette/vision/floor_colour_model.h"

#include <algorithm>
#include <array>
#include <cstdint>
#include <opencv2/imgproc.hpp>

namespace pirouette::vision {
namespace {

constexpr int kL = FloorColourModel::kLightnessBins;
constexpr int kC = FloorColourModel::kChromaBins;
// a* and b* (OpenCV's 8-bit encoding, 128 = grey) are binned over [kChromaLow,
// kChromaLow + kC * kChromaWidth) and clamped outside it: real floors are
// rarely saturated, so the bins are spent near grey.
constexpr int kChromaLow = 64;
constexpr int kChromaWidth = 4;

int Index(int l, int a, int b) { return (l * kC + a) * kC + b; }

// Bin of each colour quantised to 5 bits per channel, index (b >> 3) << 10 | (g >> 3) << 5 | r
// >> 3.
const std::vector<std::uint16_t>& BinTable() {
  static const std::vector<std::uint16_t> table = [] {
    cv::Mat3b colours(1, 32 * 32 * 32);
    for (int i = 0; i < colours.cols; ++i) {
      colours(0, i) = cv::Vec3b(static_cast<std::uint8_t>(((i >> 10) & 31) * 8 + 4),
                                static_cast<std::uint8_t>(((i >> 5) & 31) * 8 + 4),
                                static_cast<std::uint8_t>((i & 31) * 8 + 4));
    }
    cv::Mat3b lab;
    cv::cvtColor(colours, lab, cv::COLOR_BGR2Lab);
    std::vector<std::uint16_t> bins(colours.cols);
    for (int i = 0; i < colours.cols; ++i) {
      const cv::Vec3b p = lab(0, i);
      const int l = std::min(kL - 1, p[0] * kL / 256);
      const int a = std::clamp((p[1] - kChromaLow) / kChromaWidth, 0, kC - 1);
      const int b = std::clamp((p[2] - kChromaLow) / kChromaWidth, 0, kC - 1);
      bins[i] = static_cast<std::uint16_t>(Index(l, a, b));
    }
    return bins;
  }();
  return table;
}

// One [1 2 1] / 4 pass along each axis of the L × C × C histogram, edges clamped.
std::vector<double> Smooth(const std::vector<double>& h) {
  std::vector<double> out = h;
  const std::array<int, 3> sizes = {kL, kC, kC};
  const std::array<int, 3> strides = {kC * kC, kC, 1};
  for (int axis = 0; axis < 3; ++axis) {
    const std::vector<double> in = out;
    for (int l = 0; l < kL; ++l) {
      for (int a = 0; a < kC; ++a) {
        for (int b = 0; b < kC; ++b) {
          const std::array<int, 3> at = {l, a, b};
          const int i = Index(l, a, b);
          const int lo = at[axis] > 0 ? i - strides[axis] : i;
          const int hi = at[axis] < sizes[axis] - 1 ? i + strides[axis] : i;
          out[i] = 0.25 * in[lo] + 0.5 * in[i] + 0.25 * in[hi];
        }
      }
    }
  }
  return out;
}

}  // namespace

FloorColourModel::FloorColourModel(const FloorColourModelOptions& options)
    : options_(options), histogram_(kBins, 0.0), density_(kBins, 0.0f), likelihood_(kBins, 0.0f) {
  CV_Assert(options.forgetting >= 0.0 && options.forgetting <= 1.0);
  CV_Assert(options.smoothing_passes >= 0);
}

int FloorColourModel::Bin(const cv::Vec3b& bgr) {
  return BinTable()[((bgr[0] >> 3) << 10) | ((bgr[1] >> 3) << 5) | (bgr[2] >> 3)];
}

std::vector<double> FloorColourModel::Histogram(const cv::Mat3b& bgr, const cv::Mat1b& region) {
  CV_Assert(bgr.size() == region.size());
  std::vector<double> frame(kBins, 0.0);
  double count = 0.0;
  for (int v = 0; v < bgr.rows; ++v) {
    const cv::Vec3b* p = bgr[v];
    const std::uint8_t* m = region[v];
    for (int u = 0; u < bgr.cols; ++u) {
      if (m[u] == 0) continue;
      frame[Bin(p[u])] += 1.0;
      count += 1.0;
    }
  }
  if (count == 0.0) return {};
  for (double& h : frame) h /= count;
  return frame;
}

void FloorColourModel::Learn(const cv::Mat3b& bgr, const cv::Mat1b& region) {
  Learn(Histogram(bgr, region));
}

void FloorColourModel::Learn(const std::vector<double>& histogram) {
  if (histogram.empty()) return;
  CV_Assert(histogram.size() == static_cast<std::size_t>(kBins));
  const double keep = learnt_ ? 1.0 - options_.forgetting : 0.0;
  for (int i = 0; i < kBins; ++i) {
    histogram_[i] = keep * histogram_[i] + (1.0 - keep) * histogram[i];
  }
  learnt_ = true;
  UpdateLikelihood();
}

double FloorColourModel::Coverage(const std::vector<double>& histogram, float threshold) const {
  if (!learnt_ || histogram.empty()) return 0.0;
  CV_Assert(histogram.size() == static_cast<std::size_t>(kBins));
  double covered = 0.0;
  for (int i = 0; i < kBins; ++i) {
    if (histogram[i] > 0.0 && likelihood_[i] >= threshold) covered += histogram[i];
  }
  return covered;
}

void FloorColourModel::UpdateLikelihood() {
  std::vector<double> smoothed = histogram_;
  for (int pass = 0; pass < options_.smoothing_passes; ++pass) smoothed = Smooth(smoothed);
  const double peak = *std::max_element(smoothed.begin(), smoothed.end());
  for (int i = 0; i < kBins; ++i) {
    density_[i] = static_cast<float>(smoothed[i]);
    likelihood_[i] = peak > 0.0 ? static_cast<float>(smoothed[i] / peak) : 0.0f;
  }
}

cv::Mat1f FloorColourModel::Likelihood(const cv::Mat3b& bgr) const {
  cv::Mat1f out(bgr.size());
  for (int v = 0; v < bgr.rows; ++v) {
    const cv::Vec3b* p = bgr[v];
    float* o = out[v];
    for (int u = 0; u < bgr.cols; ++u) o[u] = likelihood_[Bin(p[u])];
  }
  return out;
}

cv::Mat1f FloorColourModel::Density(const cv::Mat3b& bgr) const {
  cv::Mat1f out(bgr.size());
  for (int v = 0; v < bgr.rows; ++v) {
    const cv::Vec3b* p = bgr[v];
    float* o = out[v];
    for (int u = 0; u < bgr.cols; ++u) o[u] = density_[Bin(p[u])];
  }
  return out;
}

}  // namespace pirouette::vision
