#pragma once

#include <opencv2/core.hpp>
#include <vector>

#include "pirouette/core/pose2.h"
#include "pirouette/mapping/occupancy_grid.h"

namespace pirouette::app {

// The picture of a run a person looks at (SPEC.md's map.png): the map in
// grey levels by occupancy probability (white free, black occupied, the
// unknown mid grey), the robot's path in blue, its stops (pirouettes) as
// orange dots, the start in green and the final pose in red with its
// heading; north up. `path` and `stops` are in the map's frame.
// `target_width_px` sets the scale: whole pixels a cell, at least one.
cv::Mat3b DrawMapPicture(const mapping::OccupancyGrid& grid, const std::vector<core::Pose2>& path,
                         const std::vector<core::Pose2>& stops, int target_width_px = 800);

}  // namespace pirouette::app
