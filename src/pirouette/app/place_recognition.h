#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/app/floor_masker.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/localize/observed_place.h"
#include "pirouette/localize/place_signature.h"
#include "pirouette/localize/place_table.h"
#include "pirouette/sim/world.h"

namespace pirouette::app {

// Makes pirouettes in a simulated world and turns them into colour ROPs
// (Taylor, Geva & Boles 2005, §4 and §5.1): each frame is segmented (one
// FloorMasker for the whole run, as a segmenter learns the floor online), its
// obstacle profile extracted, the profiles merged (mapping::MergePirouette)
// with bearings relative to the robot's heading at the pirouette's start, and
// each hit or blind bin given the colour class (vision::ColumnColour: the base
// of what was hit, or what fills the view of a blind column) most of its
// readings voted for. Clear and colourless bins
// are kNone. The constructor makes one pirouette at the world's robot start
// first, so that the segmenter learns the floor there. Holds a reference to
// the world.
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
// the shipped worlds (README): at 1x a pirouette in mid-floor sees little but
// clear floor, and most places look alike.
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

struct PlacesRequest {
  std::string world_path;
  int queries = 100;
  std::uint64_t seed = 1;
  std::string table_path;           // empty: none; an existing file is loaded, else written
  std::optional<double> spacing_m;  // default DefaultTableSpacing
  vision::MaskSource method = vision::MaskSource::kDefault;
  bool quiet = false;  // no progress line on standard error
  // Refine the position and heading of the heading-giving signatures' matches
  // (localize::PoseSearch over kSearchRadiusSpacings table spacings, down to
  // half a coarse cell); the answer is then the table place nearest the
  // refined position.
  bool refine = true;
  // The pirouettes read the floor out to this many times the map's range
  // (camera::MaxRange at the default cell); see kPlaceRangeFactor.
  double range_factor = kPlaceRangeFactor;
};

// How one signature did over the queries.
struct SignatureScore {
  localize::SignatureKind kind = localize::SignatureKind::kDct;
  int place_hits = 0;    // the right place (see MeasurePlaces)
  int heading_hits = 0;  // the right place and heading within kHeadingTolerance
  // The same over the informative queries (seen_bins >= kInformativeBins).
  int informative_place_hits = 0;
  int informative_heading_hits = 0;
  double mean_heading_error_deg = 0.0;  // over right places, where the signature gives headings
};

inline constexpr double kHeadingToleranceDeg = 10.0;
// A query whose ROP hits something in fewer bins than this (a tenth of the
// bearings) sees too little to tell a place by; the report gives the rates
// over the other queries too.
inline constexpr int kInformativeBins = 36;
inline constexpr double kSearchRadiusSpacings = 0.75;

// One query: where the robot truly was and what each signature answered.
struct PlaceQuery {
  core::Pose2 world_T_robot;
  double nearest_m = 0.0;  // the distance to the nearest table place
  int seen_bins = 0;       // bins of the query's ROP that hit something (hit or blind)
  struct Answer {
    int entry = 0;
    double off_m = 0.0;  // the answer's distance from the true position
    std::optional<double> heading_error_deg;
    std::optional<double> position_error_m;  // of the refined position, where refined
    bool place_ok = false;
    bool heading_ok = false;
  };
  std::vector<Answer> answers;  // one per localize::kSignatureKinds
};

struct PlacesResult {
  std::string world_name;
  int table_places = 0;
  bool table_loaded = false;  // from request.table_path rather than built
  double spacing_m = 0.0;
  double coarse_cell_m = 0.0;
  double max_range_m = 0.0;
  int queries = 0;
  int informative_queries = 0;
  std::vector<SignatureScore> scores;  // one per localize::kSignatureKinds
  std::vector<PlaceQuery> query_log;
  double build_s = 0.0;
  double query_s = 0.0;
};

// `pirouette places`: builds the place table of the world (or loads
// request.table_path when that file exists, and saves the table there when it
// does not), then queries it from request.queries random poses where the
// robot fits, with random headings (RandomRobotPoses with request.seed). For
// each signature, the
// place is right when the best entry lies within one coarse cell of the
// truly nearest entry's distance from the true position (|e − p| ≤
// min_e' |e' − p| + coarse cell), and the heading is right when, besides,
// the recovered heading is within kHeadingToleranceDeg of the truth (for the
// signatures that give one). Throws core::InputError for a bad world, table,
// query count or spacing (exit 2).
PlacesResult MeasurePlaces(const PlacesRequest& request);

// The JSON report (format pirouette-places-report/1).
nlohmann::json PlacesJson(const PlacesRequest& request, const PlacesResult& result);

}  // namespace pirouette::app
