#pragma once

#include <optional>
#include <vector>

#include "pirouette/camera/camera_model.h"

namespace pirouette::camera {

// How precisely a camera reads range from the floor's edge (Taylor, Geva &
// Boles 2005, §3): a boundary found one pixel off along an image column moves
// the floor point it maps to. The error grows with range, roughly as
// (h² + d²) / (h · f) for a camera at height h with focal length f seeing the
// floor at distance d, so a flat-floor range sensor is only precise near the
// robot.
//
// Everything here is measured along the image column through the principal
// point (straight ahead), with the camera's distortion: the column where the
// paper quotes its figure.

// The range error at one range.
struct RangeError {
  double range_m = 0.0;    // from the robot's centre of rotation to the floor point
  double row = 0.0;        // the image row (sub-pixel) where the column sees that point
  double nearer_m = 0.0;   // how far the point moves when the edge is read 1 pixel lower
  double farther_m = 0.0;  // how far it moves when the edge is read 1 pixel higher
  // The larger of the two: what one pixel of boundary error may cost.
  double worst_m() const { return farther_m > nearer_m ? farther_m : nearer_m; }
};

// The error at `range_m`; nullopt when the column does not see the floor at
// that range (nearer than its bottom row, or beyond the horizon or its top row,
// counting the pixel above and below).
std::optional<RangeError> RangeErrorAt(const CameraModel& camera, double range_m);

// The range of the floor point seen at `row` of the centre column; nullopt
// above the horizon.
std::optional<double> RangeAtRow(const CameraModel& camera, double row);

// The nearest and farthest ranges RangeErrorAt answers for.
struct RangeInterval {
  double near_m = 0.0;
  double far_m = 0.0;
};
std::optional<RangeInterval> MeasurableRanges(const CameraModel& camera);

// The paper's maximum range: the range up to which one pixel of boundary
// error (worst_m) moves the floor point by less than half a map cell of
// `cell_size_m`. About 0.40 m for the paper's camera and 1 cm cells. When even
// the nearest visible floor is coarser than that, the nearest visible range;
// when the farthest is finer, the farthest. Requires cell_size_m > 0.
double MaxRange(const CameraModel& camera, double cell_size_m = 0.01);

// The range out to which every column of the image sees the floor: the
// nearest, over the columns, of the floor point at the top row's pixel centre
// (a column whose top row lies above the horizon sees the floor out to the
// horizon, and counts as infinitely far). A profile read farther than this
// cannot tell a wall just beyond some column's top row from open floor: the
// column's floor runs to the top row with no edge. Infinity when no column's
// top row sees the floor.
double FloorSeenInEveryColumn(const CameraModel& camera);

// How far to read a profile for matching, `factor` (>= 1) times the map's
// range `map_range_m`: no farther than FloorSeenInEveryColumn, and never
// below map_range_m.
double LongRange(const CameraModel& camera, double map_range_m, double factor);

// RangeErrorAt every `step_m` from the first multiple of step_m that the
// camera measures to `to_m` (or the farthest it measures). Requires step_m > 0.
std::vector<RangeError> RangeErrorTable(const CameraModel& camera, double step_m, double to_m);

}  // namespace pirouette::camera
