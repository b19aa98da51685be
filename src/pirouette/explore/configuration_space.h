#pragma once

#include "pirouette/mapping/trinary_map.h"

namespace pirouette::explore {

// The configuration space of a disc robot (Taylor, Geva & Boles 2005, §4):
// the map with every occupied cell grown by the robot's radius, so that the
// robot becomes a point. An occupied cell stands for an obstacle anywhere in
// its square, so a cell is kOccupied ("blocked": the robot's centre may not
// be there) when its centre lies nearer than `robot_radius_m` to the square
// of a cell the map marks occupied (exact in cells). Along the axes that is
// the disc of cell centres within the radius; off them it is up to half a
// cell's diagonal wider, which keeps a plan turning round the end of a wall
// off its corner (grown from the cell's centre, a diagonal leg round it
// passed 3.5 mm inside the radius of the corner and stopped at contact, over
// and over, in a generated maze). The other cells keep the map's state, so
// unknown space is not grown. Cells off the map count as not occupied.
// Throws std::invalid_argument unless the radius is finite and >= 0.
// O(cells + boundary cells × disc cells).
mapping::TrinaryMap MakeConfigurationSpace(const mapping::TrinaryMap& map, double robot_radius_m);

}  // namespace pirouette::explore
