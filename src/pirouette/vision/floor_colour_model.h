#pragma once

#include <array>
#include <opencv2/core.hpp>
#include <vector>

namespace pirouette::vision {

struct FloorColourModelOptions {
  // The weight of a new frame's histogram when the model learns from it
  // (exponential forgetting): 1 forgets everything before, 0 never adapts.
  double forgetting = 0.3;
  // Histogram smoothing: passes of a [1 2 1] / 4 kernel along each axis, so
  // that colours near those seen also count as floor.
  int smoothing_passes = 1;
  // Along L*, the smoothing is as wide as the floor's own lightness spread:
  // round(2 · lightness_spread · σ²) passes (σ² the variance of the learnt
  // histogram's L* marginal, in bins; each pass adds half a bin² of
  // variance), at least smoothing_passes. A plain floor then refuses a thing
  // a shade darker or lighter, while a patterned or unevenly lit one keeps
  // the tolerance its own spread shows. 0: smoothing_passes along L* too.
  double lightness_spread = 1.0;
};

// The floor's colour, learnt online and never configured: a joint histogram
// in CIE L*a*b* with fine chroma bins (a*, b*) and lightness bins (L*) of
// 6.25 L* units, smoothed along L* as widely as the floor's own lightness
// varies (options.lightness_spread), so that shading and light changes, which
// move mostly L*, stay within the floor's model while a plain floor's model
// refuses a thing a shade off it (with bins of 12.5 L* units and one smoothing
// pass it did not: docs/worlds.md, fix 15). The first Learn sets it; later ones
// blend in with exponential forgetting so the model follows the light. A pure
// function of the frames given (deterministic).
class FloorColourModel {
 public:
  static constexpr int kLightnessBins = 16;
  static constexpr int kChromaBins = 32;
  static constexpr int kBins = kLightnessBins * kChromaBins * kChromaBins;

  explicit FloorColourModel(const FloorColourModelOptions& options = {});

  bool learnt() const { return learnt_; }
  // The normalised histogram learnt (kBins values; all zeros before learning).
  const std::vector<double>& histogram() const { return histogram_; }

  // Learns the colours of `bgr` where `region` is non-zero (same size). A
  // region with no pixel leaves the model as it was.
  void Learn(const cv::Mat3b& bgr, const cv::Mat1b& region);

  // Learns a histogram as Histogram returns it (kBins values summing to 1), as
  // Learn does the region's; an empty histogram leaves the model as it was.
  void Learn(const std::vector<double>& histogram);

  // Learns `histogram` (as Learn does) as a model that has learnt nothing yet
  // would: what was learnt before is forgotten, the storage is kept.
  void Relearn(const std::vector<double>& histogram);

  // The normalised colour histogram of `bgr` where `region` is non-zero (same
  // size), kBins values summing to 1; empty when the region has no pixel.
  static std::vector<double> Histogram(const cv::Mat3b& bgr, const cv::Mat1b& region);
  // The same from the pixels' bins (as Bins gives them).
  static std::vector<double> Histogram(const cv::Mat1w& bins, const cv::Mat1b& region);
  // The histograms of the pixels where `region` is non-zero and of those where
  // it is zero, in one pass: {Histogram(bins, region), Histogram(bins, ~region)}.
  static std::array<std::vector<double>, 2> Histograms(const cv::Mat1w& bins,
                                                       const cv::Mat1b& region);

  // The share of a histogram's mass (as Histogram returns it) in bins whose
  // likelihood is at least `threshold`: how much of a region this model would
  // call floor-coloured. 0 before anything is learnt.
  double Coverage(const std::vector<double>& histogram, float threshold) const;

  // How floor-like each pixel's colour is, in [0, 1]: the smoothed histogram at
  // its bin over the histogram's maximum. All zeros before anything is learnt.
  cv::Mat1f Likelihood(const cv::Mat3b& bgr) const;
  float Likelihood(const cv::Vec3b& bgr) const { return likelihood_[Bin(bgr)]; }

  // The smoothed, normalised histogram at each pixel's bin: a density over the
  // bins that sums to 1 (0 before anything is learnt), to compare two models.
  cv::Mat1f Density(const cv::Mat3b& bgr) const;

  // Likelihood and Density of each bin (kBins values each): the per-pixel
  // functions are these at Bin(pixel), so a frame's bins (Bins) can be looked
  // up in them, or in tables derived from them, once per test.
  const std::vector<float>& likelihoods() const { return likelihood_; }
  const std::vector<float>& densities() const { return density_; }

  // The histogram bin of a BGR colour (a lookup on its 5 high bits per channel).
  static int Bin(const cv::Vec3b& bgr);
  // Bin of each pixel of `bgr`, so that the colour of a frame is converted
  // once for all the tests on it. `bins` is (re)allocated to bgr's size unless
  // it has it already.
  static void Bins(const cv::Mat3b& bgr, cv::Mat1w& bins);

 private:
  void UpdateLikelihood();
  // The passes of smoothing along L* (options.lightness_spread).
  int LightnessPasses() const;

  FloorColourModelOptions options_;
  bool learnt_ = false;
  std::vector<double> histogram_;  // normalised: sums to 1 once learnt
  std::vector<float> density_;     // smoothed histogram
  std::vector<float> likelihood_;  // smoothed histogram / its maximum
  std::vector<double> smoothed_;   // scratch of UpdateLikelihood
  std::vector<double> scratch_;
};

}  // namespace pirouette::vision
