#pragma once

#include <opencv2/core.hpp>

#include "pirouette/core/colour_class.h"

namespace pirouette::vision {

// Pixels above the floor's edge whose mean colour names a column's colour.
inline constexpr int kColourSampleRows = 4;

// The colour class (core::ClassifyColour) of image column u's obstacle
// base, for the colour ROP of Taylor, Geva & Boles 2005 §5.1: the mean of
// the kColourSampleRows pixels just above the floor's edge (the first
// non-floor pixel up from the floor at the bottom); where the bottom
// vision::kBlindSearchRows rows hold no floor (a blind reading: something
// fills the view), the mean of the bottom rows. kNone where the floor
// reaches the top row. `bgr` is the raw frame, `mask` its floor (non-zero).
core::ColourClass ColumnColour(const cv::Mat3b& bgr, const cv::Mat1b& mask, int u);

}  // namespace pirouette::vision
