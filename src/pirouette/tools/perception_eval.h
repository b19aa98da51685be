#pragma once

#include <string>
#include <vector>

#include "pirouette/eval/perception_eval.h"

namespace pirouette::tools {

// The report of `pirouette perception-eval` (eval::EvaluatePerception) as
// indented JSON, ending in a newline: the method, poses a world and seed;
// per world and over all of them, the median, 95th percentile and largest
// absolute range error of columns that are hits both in truth and as
// measured, the median signed error (> 0: read too far), the rate of wrong
// classes, the confusion counts (truth → measured), and how many true hits
// end the floor at a silhouette.
std::string PerceptionEvalJson(const eval::PerceptionEvalRequest& request,
                               const std::vector<eval::WorldPerception>& worlds);

}  // namespace pirouette::tools
