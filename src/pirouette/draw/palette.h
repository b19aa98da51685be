#pragma once

#include <opencv2/core.hpp>

#include "pirouette/core/obstacle_profile.h"

// The one palette of every picture pirouette draws (BGR, OpenCV's order): the
// same thing is the same colour in map.png, the locate picture, the capture
// overlays, the ROP plot and explore.mp4.

namespace pirouette::draw {

// Readings of an obstacle profile, wherever they are drawn.
inline const cv::Vec3b kHitColour(200, 0, 200);    // magenta: an obstacle's base
inline const cv::Vec3b kClearColour(230, 160, 0);  // azure: floor all the way
inline const cv::Vec3b kBlindColour(0, 190, 255);  // amber: the base unseen, under the camera

// The floor found in a camera frame: its inside tinted green, its edge red.
inline const cv::Vec3b kFloorEdgeColour(0, 0, 255);
inline constexpr int kFloorTintGreen = 100;  // added to half the pixel's green

// The robot on a map: its path, its stops (pirouettes), where it started and
// where it is (with its heading).
inline const cv::Vec3b kPathColour(200, 90, 20);   // blue
inline const cv::Vec3b kStopColour(0, 140, 255);   // orange
inline const cv::Vec3b kStartColour(40, 170, 40);  // green
inline const cv::Vec3b kRobotColour(30, 30, 220);  // red
// The pose graph over the stops: odometry and scan-match edges faint (pale
// blue-grey and pale green), loop closures clear (deep purple).
inline const cv::Vec3b kOdometryEdgeColour(215, 200, 185);
inline const cv::Vec3b kMatchEdgeColour(175, 215, 175);
inline const cv::Vec3b kLoopClosureColour(140, 20, 120);

// Judged against the truth: the truth is the start's green; an answer found
// right is the path's blue, found wrong the robot's red, "cannot tell" the
// stops' orange.
inline const cv::Vec3b kTruthColour = kStartColour;
inline const cv::Vec3b kRightColour = kPathColour;
inline const cv::Vec3b kWrongColour = kRobotColour;
inline const cv::Vec3b kCannotTellColour = kStopColour;

// A map judged cell by cell against the truth (`eval --picture`): free where
// the truth is not red, occupied far from the truth blue, floor the map left
// unknown pale amber.
inline const cv::Vec3b kFalseFreeColour = kRobotColour;
inline const cv::Vec3b kFalseOccupiedColour(235, 120, 0);
inline const cv::Vec3b kMissedFloorColour(150, 215, 245);

// Map cells in grey levels (map_server's: white free, black occupied), the
// unknown a mid grey.
inline constexpr unsigned char kUnknownGrey = 160;

// Panels, captions and plot furniture.
inline const cv::Vec3b kPanelColour(32, 32, 32);
inline const cv::Vec3b kTextColour(230, 230, 230);
inline const cv::Vec3b kRuleColour(90, 90, 90);
inline const cv::Vec3b kWhite(255, 255, 255);
inline const cv::Vec3b kGridColour(225, 225, 225);
inline const cv::Vec3b kLabelColour(120, 120, 120);
inline const cv::Vec3b kLowPassColour(0, 0, 0);

// The colour of a reading's kind.
inline const cv::Vec3b& KindColour(core::ReadingKind kind) {
  switch (kind) {
    case core::ReadingKind::kHit:
      return kHitColour;
    case core::ReadingKind::kClear:
      return kClearColour;
    case core::ReadingKind::kBlind:
      break;
  }
  return kBlindColour;
}

// A palette colour for OpenCV's drawing functions.
inline cv::Scalar Scalar(const cv::Vec3b& bgr) {
  return {double(bgr[0]), double(bgr[1]), double(bgr[2])};
}

}  // namespace pirouette::draw
