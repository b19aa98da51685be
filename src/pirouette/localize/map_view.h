#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <string>
#include <vector>

#include "pirouette/core/colour_class.h"
#include "pirouette/localize/colour_map.h"
#include "pirouette/localize/place_table.h"
#include "pirouette/mapping/trinary_map.h"

// What a saved map would show a pirouette: its Radial Obstacle Profile cast
// on the map, and the place table made from those views (Taylor, Geva &
// Boles 2005, §5.3's "table of signatures and positions", made from the map
// instead of from pirouettes).

namespace pirouette::localize {

// What the map says one bearing from a point would show the camera: the first
// occupied cell within the range (kHit, its range), free cells all the way
// (kClear, the range), or a cell that is neither first (kUnknown, the range
// to it: the map cannot say what lies there). An unknown cell in a gap
// between occupied cells (its occupied neighbours form two or more separate
// runs round it) counts as a hit on one of them: it is a hole in an
// obstacle's mapped outline, its inside unseen. (Unknown floor beside one
// obstacle's edge, in its shadow, stays unknown.)
enum class MapRayKind : std::uint8_t { kHit, kClear, kUnknown };

struct MapView {
  std::vector<double> ranges_m;   // kRadialProfileBins, bin b: bearings [b, b + 1)° from +x
  std::vector<MapRayKind> kinds;  // per bin
  // Per bin, the colour layer's class at a hit (kNone elsewhere or where the
  // layer has none); empty without a colour layer.
  std::vector<core::ColourClass> colours;
};

// The map's ROP from `origin_m` (world frame), bin b cast along the bin's
// centre bearing (b + 0.5)° counter-clockwise from the map's +x, in steps of
// kMapRayStepCells. Off the map counts as unknown. With a colour layer (not
// empty, on the map's geometry) each hit takes its (occupied) cell's colour.
inline constexpr double kMapRayStepCells = 0.25;
MapView CastMapView(const mapping::TrinaryMap& map, const Eigen::Vector2d& origin_m,
                    double max_range_m, const ColourMap& colours = {});

// The version of CastMapView's rays, part of every MapTableName: a table made
// by rays that did not yet meet an obstacle through a gap in its outline
// (version 1) is not reused.
inline constexpr int kMapRayVersion = 2;

// A name for the map (its geometry and cells and its colour layer's, an
// FNV-1a hash) and the table's parameters (the robot's radius, the spacing,
// the max range) and kMapRayVersion: what a saved place table's `world` field
// holds, so that a table is reused only for the map, settings and ray casting
// it was made with. A map without a colour layer keeps the name it had before
// maps had colour layers.
std::string MapTableName(const mapping::TrinaryMap& map, const ColourMap& colours,
                         double robot_radius_m, double spacing_m, double max_range_m);

// The place table of a map: at the centres of a square grid of `spacing_m`
// over the map wherever a disc of `robot_radius_m` covers only free cells
// (mapping::DiscKnownFree), the map's ROP (CastMapView) in a frame of heading
// 0; unknown rays are stored as hits at their range (kinds 'b', blind). With
// a colour layer each place's view has the colours of its hits (else none).
PlaceTable BuildMapPlaceTable(const mapping::TrinaryMap& map, const ColourMap& colours,
                              double robot_radius_m, double spacing_m, double max_range_m);

}  // namespace pirouette::localize
