#pragma once

#include <Eigen/Core>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/app/floor_masker.h"
#include "pirouette/app/place_recognition.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/localize/colour_map.h"
#include "pirouette/localize/place_table.h"
#include "pirouette/mapping/trinary_map.h"

// Global localization (the kidnapped robot) from one pirouette on a saved map:
// Taylor, Geva & Boles 2005, §5.3, sketch it from the Radial Obstacle Profile
// (a table of places looked up by the ROP); here the table is made from the
// map itself, and every candidate is verified against the map.

namespace pirouette::app {

// What the map says one bearing from a point would show the camera: the first
// occupied cell within max_range_m (kHit, its range), free cells all the way
// (kClear, range max_range_m), or a cell that is neither first (kUnknown, the
// range to it: the map cannot say what lies there). An unknown cell in a gap
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
// a quarter cell. Off the map counts as unknown. With a colour layer (not
// empty, on the map's geometry) each hit takes its (occupied) cell's colour.
MapView CastMapView(const mapping::TrinaryMap& map, const Eigen::Vector2d& origin_m,
                    double max_range_m, const localize::ColourMap& colours = {});

// The map with its pinholes filled: every 4-connected group of at most
// `max_cells` unknown cells with no occupied cell among their 8 neighbours
// (floor seen free all round whose own evidence never crossed the map's
// thresholds) becomes free, so that a ray of CastMapView passes it instead of
// stopping there. Larger unknown areas, and unknown cells beside an obstacle,
// are kept.
mapping::TrinaryMap FillPinholes(const mapping::TrinaryMap& map, int max_cells);

// The largest pinhole RunLocate fills (cells).
inline constexpr int kPinholeCells = 4;

// Whether a disc of `radius_m` at `p_m` covers only free cells of the map.
bool DiscFreeOnMap(const mapping::TrinaryMap& map, const Eigen::Vector2d& p_m, double radius_m);

// A name for the map (its geometry and cells and its colour layer's, an FNV-1a hash) and the
// table's parameters (the robot's radius, the spacing, the max range) and the version of
// CastMapView's rays: what a saved place table's `world` field holds, so that a table is reused
// only for the map, settings and ray casting it was made with.
std::string MapTableName(const mapping::TrinaryMap& map, const localize::ColourMap& colours,
                         double robot_radius_m, double spacing_m, double max_range_m);

// The place table of a map (Taylor, Geva & Boles 2005, §5.3's "table of
// signatures and positions", made from the map instead of from pirouettes):
// at the centres of a square grid of `spacing_m` over the map wherever a
// disc of `robot_radius_m` covers only free cells, the map's ROP
// (CastMapView) in a frame of heading 0; unknown rays are stored as hits at
// their range (kinds 'b', blind). With a colour layer each place's view has
// the colours of its hits (else none).
localize::PlaceTable BuildMapPlaceTable(const mapping::TrinaryMap& map,
                                        const localize::ColourMap& colours, double robot_radius_m,
                                        double spacing_m, double max_range_m);

// How well a pirouette's ROP (robot frame) fits the map from a pose.
struct MapAgreement {
  double score = 0.0;  // mean agreement of the compared bins, [0, 1]
  int compared = 0;    // bins compared (the query's and the map's both known)
};

// How Locate scores a pose (its MapAgreement): the query's bin b looks along
// world bearing heading + b°; it is compared with the map's ray there: hit against hit by
// exp(−d²/2σ²), σ = max(kAgreementSigmaFloorM, kAgreementSigmaFraction × range, one map cell);
// clear against clear agrees (1); hit against clear or clear against a hit nearer than the max
// range less 2σ disagrees (0); a blind bin (an obstacle somewhere nearer than its range) agrees
// with a map hit not farther than its range + 2σ, and disagrees with a clear ray. Rays the map
// calls unknown are left out. Where the query and the map both give a colour class for a bin (a
// hit or blind bin of a query with colours against a map hit with a colour layer) and the classes
// differ, the bin's agreement is multiplied by kColourMismatchFactor: a symmetric room's mirror
// image sees the same ranges but not the same colours (Taylor, Geva & Boles 2005, §5.1's colour
// ROP). The score is a weighted mean: a bin clear in both weighs kClearWeight
// (an open floor is clear almost everywhere, which tells places apart poorly), every other bin 1.
inline constexpr double kAgreementSigmaFloorM = 0.02;
inline constexpr double kAgreementSigmaFraction = 0.05;
inline constexpr double kClearWeight = 0.25;
inline constexpr double kColourMismatchFactor = 0.5;

// The thresholds of an answer.
struct LocateOptions {
  int candidates = 30;                  // table places refined (the best coarse scores)
  double min_agreement = 0.85;          // the best's score must reach this
  double min_margin = 0.08;             // above the best candidate more than one coarse cell away
  int min_compared = 240;               // bins (of 360) the best must have compared
  int min_seen = 36;                    // bins of the query that hit something (not clear)
  double heading_tolerance_deg = 10.0;  // for judging against the truth
};

struct LocateCandidate {
  core::Pose2 world_T_robot;
  double score = 0.0;
  int compared = 0;
};

// One localization.
struct LocateAnswer {
  bool found = false;
  std::string reason;         // why not, when !found
  core::Pose2 world_T_robot;  // the best candidate (the answer when found)
  double agreement = 0.0;     // its score
  int compared = 0;
  double runner_up = 0.0;                   // the best score more than one coarse cell away
  int seen_bins = 0;                        // query bins that hit something
  std::vector<LocateCandidate> candidates;  // refined, best first
};

// Finds a pirouette's pose on a map: scores every place of `table` (the
// map's, as BuildMapPlaceTable makes it at `spacing_m`) at every one-degree
// heading against the query (the agreement above, with the place's stored
// view), refines the best options.candidates places by a local search of
// position (down to a map cell) and heading (down to a quarter degree)
// against CastMapView (with `colours`, the map's colour layer, which may be
// empty), and answers the best when its score, compared bins and
// margin over every candidate more than `coarse_cell_m` away pass `options`;
// else not found, with the reason.
LocateAnswer Locate(const mapping::TrinaryMap& map, const localize::ColourMap& colours,
                    const localize::PlaceTable& table, const localize::PlaceView& query,
                    const std::vector<core::ReadingKind>& kinds, double spacing_m,
                    double coarse_cell_m, const LocateOptions& options = {});

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
  double range_factor = kPlaceRangeFactor;
  std::uint64_t seed = 1;
  MaskSource method = MaskSource::kDefault;
  bool quiet = false;
  LocateOptions options;
};

// One query's outcome against the truth.
struct LocateTrial {
  core::Pose2 truth;
  ObservedPlace seen;  // the pirouette's view (robot frame)
  LocateAnswer answer;
  double position_error_m = 0.0;  // of the answer's best candidate
  double heading_error_deg = 0.0;
  bool right = false;  // found, within one coarse cell and the heading tolerance
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
  std::vector<LocateTrial> trials;
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

}  // namespace pirouette::app
