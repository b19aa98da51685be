#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "pirouette/localize/locate.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::draw {

// The picture of a `pirouette locate` run a person looks at: the map as
// Locate compared it (white free, black occupied, mid grey unknown; north up)
// and, for each trial, the truth as a ring with a tick along its heading and
// the answer's best candidate as a disc with a tick, in the palette's
// colours (kTruthColour; kRightColour, kWrongColour, kCannotTellColour; none
// where the map had no candidate), joined to the truth by a thin line of its
// colour where the two lie more than `coarse_cell_m` apart. With one trial,
// the pirouette's hits are drawn where the best candidate's pose puts them
// (kHitColour dots): how its view fits the map. `target_width_px` sets the
// scale: whole pixels a cell, at least one.
cv::Mat3b DrawLocatePicture(const mapping::TrinaryMap& map,
                            const std::vector<localize::LocateTrial>& trials, double coarse_cell_m,
                            int target_width_px = 800);

}  // namespace pirouette::draw
