#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

#include "pirouette/camera/camera_model.h"
#include "pirouette/core/obstacle_profile.h"

namespace pirouette::draw {

// The pixel row of each reading's floor point in the frame of `camera` (the
// column's own row where the profile read it), clamped into the frame; -1
// where the point cannot be seen (behind the camera).
std::vector<int> ReadingRows(const core::ObstacleProfile& profile,
                             const camera::CameraModel& camera);

// What the caption of a capture overlay says of its frame.
struct CaptureCaption {
  int index = 0;                    // in the source
  double floor_fraction = 0.0;      // of all the frame's pixels
  double reference_fraction = 0.0;  // of the reference region that is floor
  std::optional<core::ProfileCounts> counts;
};

// The pixel of each of the profile's feet (ObstacleProfile::feet) in the
// frame of `camera`, those that fall in the frame.
std::vector<cv::Point> FootPixels(const core::ObstacleProfile& profile,
                                  const camera::CameraModel& camera);

// The overlay of one frame (BGR): the floor drawn over it (DrawFloorOverlay),
// and with a profile (`profile`, the frame's, and `reading_rows` from
// ReadingRows) a mark per column at its reading's row in its kind's colour
// (KindColour; blind at the bottom) and a ring in the hit colour at each of
// `foot_pixels` (FootPixels), enlarged by a whole factor to at least
// kMinOverlayWidth pixels wide; below it, with a profile, each column's range as a bar (full
// height: the maximum range), then a caption: the frame's index, floor fractions and counts.
inline constexpr int kMinOverlayWidth = 320;
cv::Mat3b DrawCaptureOverlay(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask,
                             const CaptureCaption& caption,
                             const std::optional<core::ObstacleProfile>& profile,
                             const std::vector<int>& reading_rows,
                             const std::vector<cv::Point>& foot_pixels = {});

}  // namespace pirouette::draw
