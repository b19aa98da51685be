#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/vision/floor_segmenter.h"

namespace pirouette::eval {

// Floor segmentation measured on photos with hand-made floor masks, laid out
// as the visar data set (../shared/realdata/visar/README.md): source_N.bmp and
// gt_source_N.bmp, the truth white where the floor is (thresholded at 128).
// Each photo is segmented by a fresh segmenter, as the first frame of a run.
struct SegmentationEvalRequest {
  std::string images_dir;
  vision::SegmentationMethod method = vision::SegmentationMethod::kDefault;
  int first = 0;  // the photos first..last, inclusive
  int last = 99;
};

struct ImageScore {
  int index = 0;
  double iou = 0.0;        // |floor ∩ truth| / |floor ∪ truth|; 1 when both are empty
  double precision = 0.0;  // |floor ∩ truth| / |floor|
  double recall = 0.0;     // |floor ∩ truth| / |truth|
};

struct SegmentationEvalResult {
  std::vector<ImageScore> images;
  double mean_iou = 0.0;
  // Simulated frames only: over all columns of all frames, |the row where the
  // mask's floor ends - the row where the truth's does|, walking up each column
  // from the bottom row (the row of the first pixel that is not floor; -1 when
  // all are): its median and 95th percentile, in pixels.
  std::optional<double> boundary_error_median_px;
  std::optional<double> boundary_error_p95_px;
  // The median of the signed difference (mask's row - truth's row): positive
  // when the mask's floor ends nearer the robot (lower in the image).
  std::optional<double> boundary_bias_median_px;
};

// Throws core::InputError naming the file when a photo or mask is missing or unreadable.
SegmentationEvalResult EvaluateSegmentation(const SegmentationEvalRequest& request);

// The scores of a floor mask against a truth mask of the same size (both non-zero = floor).
ImageScore ScoreMask(const cv::Mat1b& truth, const cv::Mat1b& floor_mask);

// Floor segmentation measured on simulated frames against the ray caster's
// true floor mask: the robot makes a pirouette (12 turns of 30°) at its start
// pose and at `stops` more poses drawn from `seed` where its disc fits, and one
// segmenter sees all the frames in order (learning the floor online), with the
// world's camera. Each frame's index in `images` is its number in that order.
struct SimulatedEvalRequest {
  std::string world_path;
  vision::SegmentationMethod method = vision::SegmentationMethod::kDefault;
  int stops = 3;
  std::uint64_t seed = 1;
  // When set, each frame's overlay (frame_N.png) and true mask (truth_N.png) are written there.
  std::string frames_dir;
};

// Throws core::InputError for a bad world file.
SegmentationEvalResult EvaluateSimulatedSegmentation(const SimulatedEvalRequest& request);

}  // namespace pirouette::eval
