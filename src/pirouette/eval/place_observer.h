#pragma once

#include <cstdint>
#include <functional>
#include <memory>

#include "pirouette/core/pose2.h"
#include "pirouette/localize/observed_place.h"
#include "pirouette/localize/place_table.h"
#include "pirouette/sim/world.h"
#include "pirouette/vision/mask_source.h"

namespace pirouette::eval {

// Makes pirouettes in a simulated world and turns them into colour ROPs
// (Taylor, Geva & Boles 2005, §4 and §5.1): each frame is segmented (one
// FloorMasker for the whole run, as a segmenter learns the floor online), its
// obstacle profile extracted with the colour class of each column that is not
// clear (vision::ColumnColour: the base of what was hit, or what fills the
// view of a blind column), and the frames merged by localize::ObservePlace,
// with bearings relative to the robot's heading at the pirouette's start. The constructor makes one
// pirouette at the world's robot start first, so that the segmenter learns the floor there. Holds a
// reference to the world.
class PlaceObserver {
 public:
  PlaceObserver(const sim::World& world, vision::MaskSource method, double max_range_m,
                std::uint64_t render_seed);
  ~PlaceObserver();
  PlaceObserver(const PlaceObserver&) = delete;
  PlaceObserver& operator=(const PlaceObserver&) = delete;

  double max_range_m() const;

  // One pirouette from world_T_robot (the world's odometry noise drawn from
  // `seed`). Throws core::InputError when the robot's disc does not fit there.
  localize::ObservedPlace Observe(const core::Pose2& world_T_robot, std::uint64_t seed);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

// The spacing of a table's grid for `world`: the planner's coarse cell
// (explore::PlannerOptions::CoarseFactor at mapping::DefaultCellSize), but at
// least kMinSpacingRadii robot radii, so that tables stay small (hundreds of
// places) and quick to build.
inline constexpr double kMinSpacingRadii = 4.0;
double CoarseCellSize(const sim::World& world);
double DefaultTableSpacing(const sim::World& world);

// Pirouettes (heading 0) at the centres of a square grid of `spacing_m` over
// the floor, wherever the robot's disc fits; `progress(done, total)` after each.
localize::PlaceTable BuildPlaceTable(const sim::World& world, PlaceObserver& observer,
                                     double spacing_m,
                                     const std::function<void(int, int)>& progress = {});

// How far a pirouette is read for recognising its place, in the map's range
// (camera::MaxRange at the default cell, 0.41 m for the paper's robot): as
// the pose tracker's view (localize::TrackerOptions::view_range_factor), out
// to where the walls beyond the near floor tell places apart. Measured on
// the shipped worlds (docs/measurements.md, "Place recognition"): at 1x a pirouette in mid-floor
// sees little but clear floor, and most places look alike.
inline constexpr double kPlaceRangeFactor = 3.0;

// How far pirouettes are read in `world` for place recognition:
// range_factor times camera::MaxRange at the default cell, but no farther
// than camera::FloorSeenInEveryColumn (and never below the map's range):
// beyond that, a column whose floor runs to the top row would call a wall
// out of its view open floor, and the pirouette would disagree with a map
// that has the wall (the paper's camera sees 1.10 m at its top row's centre
// against 3 × 0.41 m). Throws core::InputError naming --range-factor unless
// range_factor >= 1.
double PlaceMaxRange(const sim::World& world, double range_factor);

}  // namespace pirouette::eval
