#pragma once

#include <vector>

#include "pirouette/core/colour_class.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/localize/place_signature.h"

namespace pirouette::localize {

// What one pirouette saw, in the robot's own frame at its start: its
// Radial Obstacle Profile with a colour class per bin (Taylor, Geva & Boles
// 2005, §4 and §5.1's colour ROP).
struct ObservedPlace {
  PlaceView view;                        // ranges and colour classes, 360 bins
  std::vector<core::ReadingKind> kinds;  // per bin
};

// One frame of a pirouette: its heading relative to the pirouette's first
// frame, its obstacle profile (robot frame) and the colour class of each of
// its columns' readings (vision::ColumnColour; kNone where none).
struct PirouetteFrame {
  double heading_rad = 0.0;
  core::ObstacleProfile profile;
  std::vector<core::ColourClass> column_colours;  // one per reading
};

// The pirouette's colour ROP: the profiles merged (mapping::MergePirouette),
// and each hit or blind bin given the colour class most of its readings voted
// for (each reading that is not clear and has a colour votes in the bin of its
// bearing plus its frame's heading). Clear and colourless bins are kNone.
ObservedPlace ObservePlace(const std::vector<PirouetteFrame>& frames);

}  // namespace pirouette::localize
