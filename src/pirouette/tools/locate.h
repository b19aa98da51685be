#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/eval/floor_masker.h"
#include "pirouette/localize/colour_map.h"
#include "pirouette/localize/locate.h"
#include "pirouette/localize/place_table.h"
#include "pirouette/mapping/trinary_map.h"
#include "pirouette/tools/places.h"

namespace pirouette::tools {

// The largest pinhole RunLocate fills (cells: mapping::FillPinholes) before
// casting the map's rays: a ray stops at a pinhole of unknown floor seen free
// all round (docs/measurements.md, "Kidnapped robot").
inline constexpr int kPinholeCells = 4;

struct LocateRequest {
  std::string map_path;             // map.yaml
  std::string world_path;           // the simulator's world
  std::optional<core::Pose2> pose;  // the truth; or `random` poses
  int random = 0;                   // > 0: this many random poses where the robot fits
  std::string table_path;           // empty: places.yaml beside the map
  // The map's colour layer; empty: ColourMapPathFor(map_path) when that file
  // exists (else none).
  std::string colours_path;
  bool use_colours = true;  // false: ignore any colour layer
  // The pirouette and the map's views reach this many times the map's range
  // (camera::MaxRange at the default cell); see kPlaceRangeFactor.
  double range_factor = eval::kPlaceRangeFactor;
  std::uint64_t seed = 1;
  vision::MaskSource method = vision::MaskSource::kDefault;
  bool quiet = false;
  localize::LocateOptions options;
};

struct LocateResult {
  // The map as the trials were compared with it (pinholes filled); RunLocate sets it.
  std::optional<mapping::TrinaryMap> map;
  std::string table_path;
  bool table_loaded = false;
  std::string colours_path;  // the colour layer read; empty: none
  // table_path held a place table made for another map or settings (or with
  // no places), which this run replaced.
  bool table_replaced = false;
  int table_places = 0;
  double spacing_m = 0.0;
  double coarse_cell_m = 0.0;
  double max_range_m = 0.0;
  std::vector<localize::LocateTrial> trials;
  int found_right = 0;
  int cannot_tell = 0;
  int wrong = 0;
  double table_s = 0.0;
  double mean_locate_s = 0.0;  // per query, the pirouette's simulation excluded
};

// `pirouette locate`: reads the map (io::ReadRosMap), its colour layer (see
// LocateRequest::colours_path; io::ReadColourMap) and the world, loads the
// map's place table from request.table_path when the file exists and was made
// for this map and settings (else builds it with BuildMapPlaceTable at
// DefaultTableSpacing and writes it there, result.table_replaced when a file
// was there), then for the pose (or for request.random random poses:
// RandomRobotPoses with request.seed) makes one simulated pirouette
// (PlaceObserver; the robot knows nothing of the pose) and Locates it.
// Throws core::InputError for a bad map, world, pose (the robot does not fit:
// "--pose") or count (exit 2).
LocateResult RunLocate(const LocateRequest& request);

// The JSON report (format pirouette-locate-report/1).
nlohmann::json LocateJson(const LocateRequest& request, const LocateResult& result);

}  // namespace pirouette::tools
