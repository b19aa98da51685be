#pragma once

#include <Eigen/Core>

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

// The robot stands where it stands: marks free every occupied cell of `map`
// whose square lies nearer than `robot_radius_m` to the centre of the cell
// holding `robot_world` (what MakeConfigurationSpace grows into that cell),
// so that the configuration space leaves the robot's own cell free. A wall
// mapped a cell thicker than it is (a cell of wall error) beside a robot
// whose disc clears the true wall by millimetres otherwise puts the robot's
// cell inside the grown wall, and no plan starts where it stands; costmaps
// clear the footprint likewise (navigation2's footprint clearing). The map
// itself is not enough: mapping::MarkFootprintFree frees in the occupancy
// grid only the cells whose centres lie under the disc, as a map of record
// should, while a cell whose square merely reaches into the disc still
// blocks the robot's cell here. For a plan only. Nothing when `robot_world`
// is off the map. Throws std::invalid_argument unless the
// radius is finite and >= 0. Returns how many cells it freed.
int ClearFootprint(mapping::TrinaryMap& map, const Eigen::Vector2d& robot_world,
                   double robot_radius_m);

}  // namespace pirouette::explore
