#pragma once

#include <opencv2/core.hpp>

namespace pirouette::draw {

// The floor found in a photo (BGR) drawn over it: the floor's inside tinted
// green, its boundary (floor pixels with a non-floor 4-neighbour) in
// kFloorEdgeColour. `floor_mask` (non-zero floor) is the photo's size.
cv::Mat3b DrawFloorOverlay(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask);

}  // namespace pirouette::draw
