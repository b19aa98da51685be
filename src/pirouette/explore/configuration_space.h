#pragma once

#include "pirouette/mapping/trinary_map.h"

namespace pirouette::explore {

// The configuration space of a disc robot (Taylor, Geva & Boles 2005, §4):
// the map with every occupied cell grown by the robot's radius, so that the
// robot becomes a point. A cell is kOccupied ("blocked": the robot's centre
// may not be there) when its centre lies within `robot_radius_m` of the
// centre of a cell the map marks occupied (a disc, exact in cells); the other
// cells keep the map's state, so unknown space is not grown. Cells off the map
// count as not occupied. Throws std::invalid_argument unless the radius is
// finite and >= 0. O(cells + boundary cells × disc cells).
mapping::TrinaryMap MakeConfigurationSpace(const mapping::TrinaryMap& map, double robot_radius_m);

}  // namespace pirouette::explore
