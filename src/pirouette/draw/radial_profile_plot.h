#pragma once

#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pirouette/mapping/radial_profile.h"

namespace pirouette::draw {

// The polar plot (odometry frame: 0° to the right, counter-clockwise): the
// ROP as a thick line coloured by kind (draw::KindColour), its low-pass as a thin black line, the
// truth (if not empty) as a thin line in kTruthColour, rings every 10 cm and the max range dashed.
cv::Mat3b PlotRadialProfile(const mapping::RadialProfile& rop, const std::vector<double>& low_pass,
                            const std::vector<double>& truth, const std::string& title,
                            int size_px = 640);

}  // namespace pirouette::draw
