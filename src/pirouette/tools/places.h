#pragma once

#include <cstdint>
#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/eval/place_observer.h"
#include "pirouette/localize/observed_place.h"
#include "pirouette/localize/place_signature.h"
#include "pirouette/localize/place_table.h"
#include "pirouette/sim/world.h"

namespace pirouette::tools {

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
  double range_factor = eval::kPlaceRangeFactor;
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

// A recovered heading this close to the truth is right (docs/measurements.md,
// "Place recognition"): ten of the profile's 1° bins, a third of the turn
// between a pirouette's frames; wider would count a twin place's heading.
inline constexpr double kHeadingToleranceDeg = 10.0;
// A query whose ROP hits something in fewer bins than this (a tenth of the
// bearings) sees too little to tell a place by; the report gives the rates
// over the other queries too.
inline constexpr int kInformativeBins = 36;
// The refinement searches this many table spacings around a matched place:
// more than half a spacing, so that a query between two places reaches the
// true one from either; wider costs search time and reaches look-alike
// neighbours.
inline constexpr double kSearchRadiusSpacings = 0.75;

// The noise seed of query `q`'s pirouette in a run seeded `seed`. The stride
// is larger than the queries a run makes (100 in docs/measurements.md,
// "Place recognition" and 20 in "Kidnapped robot"), so runs with different
// seeds never share a pirouette's noise (any stride above the query count
// would; a prime is the customary choice).
inline constexpr std::uint64_t kQuerySeedStride = 7919;
inline std::uint64_t QuerySeed(std::uint64_t seed, std::size_t q) {
  return seed * kQuerySeedStride + q;
}

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
// each signature, the place is right when the best entry lies within one coarse cell of the
// truly nearest entry's distance from the true position (|e − p| ≤
// min_e' |e' − p| + coarse cell), and the heading is right when, besides,
// the recovered heading is within kHeadingToleranceDeg of the truth (for the
// signatures that give one). Throws core::InputError for a bad world, table,
// query count or spacing (exit 2).
PlacesResult MeasurePlaces(const PlacesRequest& request);

// The JSON report (format pirouette-places-report/1).
nlohmann::json PlacesJson(const PlacesRequest& request, const PlacesResult& result);

}  // namespace pirouette::tools
