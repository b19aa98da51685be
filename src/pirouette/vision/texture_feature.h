#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "pirouette/vision/vignetting_corrector.h"

namespace pirouette::vision {

// The default segmenter's texture feature: the mean gradient magnitude of the
// low-passed grey image, m = mean(|Sobel_x| + |Sobel_y|) / 8 (grey levels a
// pixel), over a window, binned on a log scale: bin = min(15, ⌊3 log2(1 + m)⌋).
//
// The gradient is always taken at the frame's full resolution: a floor's fine
// texture shrinks with distance, so at a reduced resolution the far floor
// would look smooth where the near floor (the reference region) does not. For
// a working grid reduced by `scale` (cells of scale × scale pixels), the
// window of a cell is the cell and `window` − 1 pixels around it (window / 2
// before it, the rest after), borders reflected (BORDER_REFLECT_101); at scale
// 1 it is the window centred on the pixel, as cv::blur takes it.
//
// The grey image is the frame's luminance (Rec. 601 weights), corrected for
// vignetting by the luminance-weighted mean of the channels' factors when a
// corrector is given, then low-passed by the binomial kernel of `blur_order`.
class TextureFeature {
 public:
  static constexpr int kBins = 16;

  // `corrector`, if any, at full resolution (scale 1) for the frames given.
  TextureFeature(int scale, int window, int blur_order,
                 const std::optional<VignettingCorrector>& corrector);

  int scale() const { return scale_; }

  // The bin of each cell of `bgr_raw` (width / scale × height / scale cells);
  // valid until the next call. The frame must have the corrector's size.
  const cv::Mat1b& Bins(const cv::Mat3b& bgr_raw);

 private:
  int scale_;
  int before_;  // the window's pixels before a cell, and after it
  int after_;
  int blur_order_;
  std::vector<std::uint16_t> grey_gain_q_;  // per pixel, 14-bit fixed point; empty: none
  cv::Size gain_size_;
  std::array<std::uint8_t, 2048> bin_of_mean_{};  // a bin near m = i / 64, never above
  std::uint32_t mean_scale_ = 0;  // S · mean_scale_ >> 16 ≈ 64 m, S the window's sum
  std::array<std::uint32_t, kBins + 1> least_sum_{};  // the least S of each bin
  cv::Mat1b grey_;
  cv::Mat blurred_;
  cv::Mat1w magnitude_;                 // |Sobel_x| + |Sobel_y| at full resolution
  std::vector<std::int16_t> smooth_;    // a row's vertical [1 2 1] sums
  std::vector<std::int16_t> diff_;      // ...and [-1 0 1] differences
  std::vector<std::uint16_t> columns_;  // a cell row's column sums, padded
  std::vector<std::uint32_t> running_;
  cv::Mat1b bins_;
};

}  // namespace pirouette::vision
