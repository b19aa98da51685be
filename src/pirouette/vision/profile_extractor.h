#pragma once

#include <opencv2/core.hpp>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/core/obstacle_profile.h"

namespace pirouette::vision {

// The rows at the bottom of a column that are searched for floor before the
// column is called blind: a segmenter may leave the image's last rows out.
inline constexpr int kBlindSearchRows = 3;

// The obstacle profile of one frame (Taylor, Geva & Boles 2005, §3): the
// floor's edge in each image column read as a range through the inverse
// perspective mapping.
//
// For each column of `floor_mask` (255 floor, 0 not, the IPM's size), from
// the lowest floor pixel among the bottom kBlindSearchRows rows upward, the
// first pixel that is not floor ends the floor. The edge lies between that
// pixel's centre and the one below; it is read half-way, as the mid-point of
// the two pixels' floor points (the floor point below when the pixel above
// sees no floor). In the robot frame, the reading's bearing is atan2(y, x) of
// that point and its range the point's distance from the robot's centre:
//   kHit   when that range is at most max_range_m;
//   kClear when it is farther, or when the floor goes on past max_range_m (or
//          past the horizon, or to the top row) with no edge: range_m =
//          max_range_m, bearing of the first floor point beyond max_range_m;
//   kBlind when the bottom kBlindSearchRows rows hold no floor: range and
//          bearing of the bottom pixel's floor point.
// Pure: the same mask gives the same profile.
core::ObstacleProfile ExtractProfile(const cv::Mat1b& floor_mask,
                                     const camera::InversePerspectiveMap& ipm, double max_range_m);

}  // namespace pirouette::vision
