#pragma once

#include <string>

#include "pirouette/eval/segmentation_eval.h"

namespace pirouette::tools {

// The report of `pirouette segment-eval` (eval::EvaluateSegmentation or
// eval::EvaluateSimulatedSegmentation) as indented JSON, ending in a
// newline: the method, the photos' range, the mean IoU, the boundary row
// errors where measured (simulated frames), and each image's IoU, precision
// and recall.
std::string SegmentationEvalJson(const eval::SegmentationEvalRequest& request,
                                 const eval::SegmentationEvalResult& result);

}  // namespace pirouette::tools
