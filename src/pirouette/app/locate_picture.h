#pragma once

#include <opencv2/core.hpp>

#include "pirouette/app/global_localization.h"

namespace pirouette::app {

// The picture of a `pirouette locate` run a person looks at: the map as
// Locate compared it (result.map: white free, black occupied, mid grey
// unknown; north up) and, for each trial, the truth as a green ring with a
// tick along its heading and the answer's best candidate as a disc with a
// tick: blue where it was found right, red where it was found wrong, orange
// where it could not tell (none where the map had no candidate), joined to
// the truth by a thin line of its colour where the two lie more than a
// coarse cell apart. With one trial, the pirouette's hits are drawn where
// the best candidate's pose puts them (cyan dots): how its view fits the
// map. `target_width_px` sets the scale: whole pixels a cell, at least one.
// Throws std::invalid_argument when result.map is empty (RunLocate sets it).
cv::Mat3b DrawLocatePicture(const LocateResult& result, int target_width_px = 800);

}  // namespace pirouette::app
