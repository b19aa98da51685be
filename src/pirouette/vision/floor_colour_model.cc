#include "pirouette/vision/floor_colour_model.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numeric>
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

// One [1 2 1] / 4 pass along one axis of the L × C × C histogram, edges
// clamped: `count` blocks of `size` steps of `stride` values.
void SmoothAxis(const double* in, double* out, int count, int size, int stride) {
  for (int block = 0; block < count; ++block) {
    const std::ptrdiff_t base = static_cast<std::ptrdiff_t>(block) * size * stride;
    for (int k = 0; k < size; ++k) {
      const double* lo = in + base + static_cast<std::ptrdiff_t>(k > 0 ? k - 1 : k) * stride;
      const double* at = in + base + static_cast<std::ptrdiff_t>(k) * stride;
      const double* hi = in + base + static_cast<std::ptrdiff_t>(k < size - 1 ? k + 1 : k) * stride;
      double* o = out + base + static_cast<std::ptrdiff_t>(k) * stride;
      for (int j = 0; j < stride; ++j) o[j] = 0.25 * lo[j] + 0.5 * at[j] + 0.25 * hi[j];
    }
  }
}

// `passes` [1 2 1] / 4 passes along L* of `h`, in place; `scratch` holds kBins values.
void SmoothLightness(std::vector<double>& h, std::vector<double>& scratch, int passes) {
  for (int pass = 0; pass < passes; ++pass) {
    SmoothAxis(h.data(), scratch.data(), 1, kL, kC * kC);
    h.swap(scratch);
  }
}

// One [1 2 1] / 4 pass along each chroma axis (a*, then b*) of `h`, in
// place; `scratch` holds kBins values.
void SmoothChroma(std::vector<double>& h, std::vector<double>& scratch) {
  SmoothAxis(h.data(), scratch.data(), kL, kC, kC);
  h.swap(scratch);
  // Along b* (stride 1): the rows of kC values, their interiors at once.
  const double* in = h.data();
  double* out = scratch.data();
  for (int row = 0; row < kL * kC; ++row, in += kC, out += kC) {
    out[0] = 0.25 * in[0] + 0.5 * in[0] + 0.25 * in[1];
    for (int k = 1; k < kC - 1; ++k) out[k] = 0.25 * in[k - 1] + 0.5 * in[k] + 0.25 * in[k + 1];
    out[kC - 1] = 0.25 * in[kC - 2] + 0.5 * in[kC - 1] + 0.25 * in[kC - 1];
  }
  h.swap(scratch);
}

// The normalised histogram of counts over `total` pixels; empty when none.
std::vector<double> Normalised(const std::vector<std::uint32_t>& counts, std::uint64_t total) {
  if (total == 0) return {};
  std::vector<double> frame(counts.size());
  const auto n = static_cast<double>(total);
  for (std::size_t i = 0; i < counts.size(); ++i) frame[i] = counts[i] / n;
  return frame;
}

}  // namespace

FloorColourModel::FloorColourModel(const FloorColourModelOptions& options)
    : options_(options), histogram_(kBins, 0.0), density_(kBins, 0.0f), likelihood_(kBins, 0.0f) {
  CV_Assert(options.forgetting >= 0.0 && options.forgetting <= 1.0);
  CV_Assert(options.smoothing_passes >= 0);
  CV_Assert(options.lightness_spread >= 0.0);
}

int FloorColourModel::Bin(const cv::Vec3b& bgr) {
  return BinTable()[((bgr[0] >> 3) << 10) | ((bgr[1] >> 3) << 5) | (bgr[2] >> 3)];
}

void FloorColourModel::Bins(const cv::Mat3b& bgr, cv::Mat1w& bins) {
  bins.create(bgr.size());
  const std::uint16_t* table = BinTable().data();
  for (int v = 0; v < bgr.rows; ++v) {
    const auto* p = bgr.ptr<std::uint8_t>(v);
    std::uint16_t* b = bins[v];
    for (int u = 0; u < bgr.cols; ++u, p += 3) {
      b[u] = table[((p[0] >> 3) << 10) | ((p[1] >> 3) << 5) | (p[2] >> 3)];
    }
  }
}

std::vector<double> FloorColourModel::Histogram(const cv::Mat3b& bgr, const cv::Mat1b& region) {
  CV_Assert(bgr.size() == region.size());
  std::vector<std::uint32_t> counts(kBins, 0);
  std::uint64_t total = 0;
  for (int v = 0; v < bgr.rows; ++v) {
    const cv::Vec3b* p = bgr[v];
    const std::uint8_t* m = region[v];
    for (int u = 0; u < bgr.cols; ++u) {
      if (m[u] == 0) continue;
      ++counts[Bin(p[u])];
      ++total;
    }
  }
  return Normalised(counts, total);
}

std::vector<double> FloorColourModel::Histogram(const cv::Mat1w& bins, const cv::Mat1b& region) {
  CV_Assert(bins.size() == region.size());
  std::vector<std::uint32_t> counts(kBins, 0);
  std::uint64_t total = 0;
  for (int v = 0; v < bins.rows; ++v) {
    const std::uint16_t* b = bins[v];
    const std::uint8_t* m = region[v];
    // Neighbours share a bin more often than not: count runs, not pixels.
    int run_bin = -1;
    std::uint32_t run = 0;
    for (int u = 0; u < bins.cols; ++u) {
      if (m[u] == 0) continue;
      if (b[u] != run_bin) {
        if (run > 0) counts[run_bin] += run;
        total += run;
        run_bin = b[u];
        run = 0;
      }
      ++run;
    }
    if (run > 0) counts[run_bin] += run;
    total += run;
  }
  return Normalised(counts, total);
}

std::array<std::vector<double>, 2> FloorColourModel::Histograms(const cv::Mat1w& bins,
                                                                const cv::Mat1b& region) {
  CV_Assert(bins.size() == region.size());
  std::array<std::vector<std::uint32_t>, 2> counts = {std::vector<std::uint32_t>(kBins, 0),
                                                      std::vector<std::uint32_t>(kBins, 0)};
  std::uint64_t inside = 0;
  for (int v = 0; v < bins.rows; ++v) {
    const std::uint16_t* b = bins[v];
    const std::uint8_t* m = region[v];
    int run_bin = b[0];
    int run_class = m[0] != 0 ? 1 : 0;
    std::uint32_t run = 0;
    for (int u = 0; u < bins.cols; ++u) {
      const int k = m[u] != 0 ? 1 : 0;
      inside += static_cast<std::uint64_t>(k);
      if (b[u] != run_bin || k != run_class) {
        counts[run_class][run_bin] += run;
        run_bin = b[u];
        run_class = k;
        run = 0;
      }
      ++run;
    }
    counts[run_class][run_bin] += run;
  }
  const auto all = static_cast<std::uint64_t>(bins.total());
  return {Normalised(counts[1], inside), Normalised(counts[0], all - inside)};
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

void FloorColourModel::Relearn(const std::vector<double>& histogram) {
  if (histogram.empty()) return;
  learnt_ = false;
  Learn(histogram);
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

int FloorColourModel::LightnessPasses() const {
  if (options_.lightness_spread == 0.0) return options_.smoothing_passes;
  // The variance of the histogram's L* marginal, in bins².
  double mean = 0.0;
  double square = 0.0;
  constexpr std::ptrdiff_t kPlane = static_cast<std::ptrdiff_t>(kC) * kC;
  const auto* h = histogram_.data();
  for (int l = 0; l < kL; ++l, h += kPlane) {
    const double mass = std::accumulate(h, h + kPlane, 0.0);
    mean += l * mass;
    square += static_cast<double>(l) * l * mass;
  }
  const double variance = std::max(0.0, square - mean * mean);
  const auto passes = static_cast<int>(std::lround(2.0 * options_.lightness_spread * variance));
  // (At most 2 · lightness_spread · 64 passes: a floor half black, half white.)
  return std::max(passes, options_.smoothing_passes);
}

void FloorColourModel::UpdateLikelihood() {
  std::vector<double>& smoothed = smoothed_;
  smoothed = histogram_;
  scratch_.resize(kBins);
  SmoothLightness(smoothed, scratch_, LightnessPasses());
  for (int pass = 0; pass < options_.smoothing_passes; ++pass) SmoothChroma(smoothed, scratch_);
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
