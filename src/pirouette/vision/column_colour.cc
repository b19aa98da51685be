#include "pirouette/vision/column_colour.h"

#include <array>
#include <cmath>
#include <cstdint>

#include "pirouette/vision/profile_extractor.h"

namespace pirouette::vision {

core::ColourClass ColumnColour(const cv::Mat3b& bgr, const cv::Mat1b& mask, int u) {
  const int bottom = mask.rows - 1;
  int v = -1;
  for (int k = 0; k < vision::kBlindSearchRows && bottom - k >= 0; ++k) {
    if (mask(bottom - k, u) != 0) {
      v = bottom - k;
      break;
    }
  }
  if (v < 0) {
    v = bottom;  // blind: what fills the view is at the bottom
  } else {
    while (v >= 0 && mask(v, u) != 0) --v;
    if (v < 0) return core::ColourClass::kNone;
  }
  std::array<double, 3> sum{};
  int n = 0;
  for (int row = v; row > v - kColourSampleRows && row >= 0; --row) {
    const cv::Vec3b& p = bgr(row, u);
    for (int c = 0; c < 3; ++c) sum[c] += p[c];
    ++n;
  }
  const auto mean = [&](int c) { return static_cast<std::uint8_t>(std::lround(sum[c] / n)); };
  return core::ClassifyColour(core::Rgb{mean(2), mean(1), mean(0)});
}

}  // namespace pirouette::vision
