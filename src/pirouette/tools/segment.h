#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>

#include "pirouette/core/obstacle_profile.h"
#include "pirouette/vision/floor_segmenter.h"

namespace pirouette::tools {

struct SegmentImageRequest {
  std::string image_path;
  std::string camera_path;  // empty: no camera (no correction, no profile)
  vision::SegmentationMethod method = vision::SegmentationMethod::kDefault;
  std::string mask_path;     // a PNG, 255 floor, 0 not; empty: not written
  std::string overlay_path;  // a PNG to look at; empty: not written
  // The profile's maximum range; nullopt: the camera's, by the paper's rule
  // (camera::MaxRange with 1 cm cells).
  std::optional<double> max_range_m;
};

struct SegmentImageResult {
  cv::Mat1b floor_mask;
  std::optional<core::ObstacleProfile> profile;  // when a camera was given
};

// `pirouette segment`: the floor mask of one photo, as the first frame a
// segmenter sees, an overlay picture, and with a camera the obstacle profile.
// Throws core::InputError (exit 2) for an unreadable or empty image, a bad
// camera file, or an image whose size is not the camera's; std::runtime_error
// when an output cannot be written (exit 1).
SegmentImageResult SegmentImage(const SegmentImageRequest& request);

// The profile as indented JSON ending in a newline: {"max_range_m": …,
// "readings": [{"bearing_deg": …, "range_m": …, "kind": "hit" | "clear" |
// "blind"}, …]}, one reading per image column, left to right; metres to 4
// decimals, degrees to 3.
std::string ObstacleProfileJson(const core::ObstacleProfile& profile);

}  // namespace pirouette::tools
