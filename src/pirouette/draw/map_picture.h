#pragma once

#include <cstdint>
#include <functional>
#include <opencv2/core.hpp>
#include <vector>

#include "pirouette/core/pose2.h"
#include "pirouette/localize/pose_graph.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::draw {

// A map grid drawn as a picture, north up, `scale` whole pixels a cell, and
// where the map's points fall on it: the ground that DrawMapPicture and
// DrawLocatePicture draw on.
struct MapCanvas {
  // Fractional bits of the points Pixel gives OpenCV's drawing functions.
  static constexpr int kShift = 4;

  cv::Mat3b image;
  core::GridGeometry geometry;
  int scale = 1;

  // Cells of `geometry` in the grey levels `grey` gives them, at
  // max(1, target_width_px / width) pixels a cell.
  static MapCanvas Of(const core::GridGeometry& geometry,
                      const std::function<std::uint8_t(const core::CellIndex&)>& grey,
                      int target_width_px);
  // A trinary map in map_server's greys: free white, occupied black, the
  // unknown kUnknownGrey.
  static MapCanvas OfTrinary(const mapping::TrinaryMap& map, int target_width_px);
  // Where a point of the map (metres) falls, in kShift fixed point.
  cv::Point Pixel(const Eigen::Vector2d& p_m) const;
  // `pixels` in kShift fixed point (a radius for cv::circle).
  static int Fixed(double pixels);
};

// The picture of a run a person looks at (SPEC.md's map.png): the map in
// grey levels by occupancy probability (white free, black occupied, the
// unknown mid grey, and free seen from one place only, which the map of
// record calls unknown, mid grey too: OccupancyGrid::ToMapOfRecord), the robot's path in blue, its
// stops (pirouettes) as orange dots, the start in green and the final pose in red with its heading;
// north up. `path` and `stops` are in the map's frame. With a pose graph (its nodes in the map's
// frame), its odometry and scan-match edges are drawn faintly under the path and its loop closures
// clearly over it. `target_width_px` sets the scale: whole pixels a cell, at least one.
cv::Mat3b DrawMapPicture(const mapping::OccupancyGrid& grid, const std::vector<core::Pose2>& path,
                         const std::vector<core::Pose2>& stops, int target_width_px = 800,
                         const localize::PoseGraph* graph = nullptr);

// A trinary map as MapCanvas::OfTrinary draws it, each cell that `mark`
// gives a colour (not nullptr) painted in it, north up.
cv::Mat3b DrawMarkedMap(const mapping::TrinaryMap& map,
                        const std::function<const cv::Vec3b*(const core::CellIndex&)>& mark,
                        int target_width_px);

}  // namespace pirouette::draw
