#pragma once

#include <vector>

#include "pirouette/core/obstacle_profile.h"

namespace pirouette::mapping {

// The bins of a Radial Obstacle Profile: one a degree.
inline constexpr int kRadialProfileBins = 360;
// The DCT coefficients the paper keeps of a profile (its Fig. 2's thin line).
inline constexpr int kRadialProfileCoefficients = 20;

// One frame's obstacle profile and the robot's odometry heading (radians,
// counter-clockwise) when it was taken.
struct HeadedProfile {
  double heading_rad = 0.0;
  core::ObstacleProfile profile;
};

// What one bin of bearings says.
struct RadialBin {
  double range_m = 0.0;  // the max range where nothing was read
  core::ReadingKind kind = core::ReadingKind::kClear;
  int readings = 0;  // how many readings fell in the bin; 0: not seen
};

// The Radial Obstacle Profile (ROP) of one pirouette (Taylor, Geva & Boles
// 2005, §4 and Fig. 2): the ranges all around the robot, as a function of
// bearing in the odometry frame. Bin b holds the bearings [b, b + 1)
// degrees, counter-clockwise from the odometry frame's +x; a robot that
// turns on the spot keeps its centre, so every reading shares one origin.
struct RadialProfile {
  std::vector<RadialBin> bins;  // kRadialProfileBins of them
  double max_range_m = 0.0;     // the largest of the views' maximum ranges

  // The ranges of the bins, in bin order.
  std::vector<double> Ranges() const;
};

// Merges the profiles of one pirouette's frames. Where views overlap, each
// bin takes the kind most of its readings have (a tie goes to kHit, then
// kBlind: the cautious reading), and the nearest range among the readings of
// that kind (kClear: the max range). Bins no reading falls in are kClear at
// the max range with readings = 0.
RadialProfile MergePirouette(const std::vector<HeadedProfile>& views);

// The orthonormal DCT-II of x (the "DCT" of signal processing, with scaling
// so that InverseDct(Dct(x)) == x and energy is kept), computed directly.
std::vector<double> Dct(const std::vector<double>& x);
// The inverse of Dct (the orthonormal DCT-III).
std::vector<double> InverseDct(const std::vector<double>& coefficients);

// x smoothed by keeping only its first `keep` DCT coefficients (keep >= 1).
std::vector<double> DctLowPass(const std::vector<double>& x, int keep = kRadialProfileCoefficients);

}  // namespace pirouette::mapping
