#pragma once

#include <Eigen/Core>
#include <cstddef>

#include "pirouette/core/angle.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/mapping/occupancy_grid.h"

namespace pirouette::mapping {

// Consecutive readings of a profile whose bearings are at most this far apart
// are taken to have seen the floor between them (the columns of one image);
// see InsertProfile.
inline constexpr double kMaxFillGapRad = core::DegToRad(5.0);

// The paper's ideal range sensor (Taylor, Geva & Boles 2005, §3) applied to
// one frame's obstacle profile, taken with the robot at world_T_robot: ranges
// are from the robot's centre of rotation, bearings counter-clockwise from its
// forward axis. Each reading is a ray from the robot's centre to the point at
// its range, and touches every cell the ray passes through (an exact grid
// traversal, Amanatides & Woo 1987); "the cell at the range" is the cell
// holding that point:
//   kHit:   the cells before the range take a miss, the cell at the range a
//           hit, nothing beyond;
//   kClear: every cell out to the range (the maximum range) takes a miss;
//   kBlind: every cell out to the range takes the blind update (the base of
//           whatever fills the view is somewhere in there, unseen), up to
//           the first cell the grid holds occupied once the frame's hits
//           are in: the base stands in front of it, not behind.
// A hit or clear reading whose ray passes through a solid cell
// (OccupancyGrid::Solid: a wall hit from two places) more than three cells
// short of its end stops just before it: no miss on the wall or beyond, and
// no hit at its end. A reading that runs on through a wall seen for sure is
// a wall passing for the floor (a face of the floor's colour, seen too near
// to tell), and would map a fan of free cells beyond it. Whether a cell is
// solid is as the grid stood before the frame.
// The grid grows to cover the frame first, and the call is one frame of the
// grid (OccupancyGrid::BeginFrame, from the robot's position): each cell
// changes at most once. Hits go
// first, then blind areas, then misses, so a hit wins over both, and blind
// wins over a miss (the cautious reading: something may stand there).
// Where two consecutive readings, neither blind, are at most kMaxFillGapRad
// apart but their rays part by more than a cell at the shorter range, extra
// miss rays at bearings between them fill the gap out to that range, so the
// swept area has no unknown holes for an explorer to chase.
// The profile's feet are hit readings as above, with no fill to any other.
// Returns the number of cell updates applied. Throws std::invalid_argument
// when a reading's bearing or range is not finite or a range is negative, and
// std::length_error when the frame would grow the grid past
// OccupancyGrid::kMaxSideCells.
std::size_t InsertProfile(OccupancyGrid& grid, const core::ObstacleProfile& profile,
                          const core::Pose2& world_T_robot);

// The robot stands on the floor under its footprint: sets every cell whose
// centre lies within radius_m of centre (world, metres) to the free clamp
// (OccupancyGrid::SetFree), growing the grid to cover the disc first. Apply it
// after a frame or a pirouette: the rays of a frame all meet in the robot's
// cell, so a blind reading pulls the cells under the robot toward occupied.
// Throws std::invalid_argument unless radius_m >= 0 and everything is finite.
void MarkFootprintFree(OccupancyGrid& grid, const Eigen::Vector2d& centre, double radius_m);

}  // namespace pirouette::mapping
