#include "pirouette/tools/places.h"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/explore/planner.h"
#include "pirouette/io/image_io.h"
#include "pirouette/io/place_table_file.h"
#include "pirouette/io/world_file.h"
#include "pirouette/mapping/radial_profile.h"
#include "pirouette/run/explorer.h"
#include "pirouette/run/progress_line.h"
#include "pirouette/run/stage_timer.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/sim/simulated_pirouette.h"
#include "pirouette/vision/column_colour.h"
#include "pirouette/vision/profile_extractor.h"

namespace pirouette::tools {
namespace {

using Clock = std::chrono::steady_clock;

// An answer this much farther than one coarse cell beyond the nearest table
// place still counts as the right place: a tie at exactly a coarse cell is
// right, whatever the rounding of the two distances.
constexpr double kPlaceTieM = 1e-9;

void CheckPlacesRequest(const PlacesRequest& request) {
  if (request.queries < 1) throw core::InputError("", 0, "--queries", "must be at least 1");
  if (request.spacing_m && !(*request.spacing_m > 0.0 && std::isfinite(*request.spacing_m))) {
    throw core::InputError("", 0, "--spacing", "must be a number > 0 (metres)");
  }
}

// The table of request.table_path, which must be of this world and range.
localize::PlaceTable LoadTable(const PlacesRequest& request, const sim::World& world,
                               double max_range) {
  localize::PlaceTable table = io::LoadPlaceTable(request.table_path);
  if (table.world() != world.name()) {
    throw core::InputError(
        request.table_path, 0, "world",
        "the table is of world '" + table.world() + "', not '" + world.name() + "'");
  }
  if (table.entries().empty()) {
    throw core::InputError(request.table_path, 0, "places", "the table has no places");
  }
  if (std::abs(table.max_range_m() - max_range) > 1e-6) {
    throw core::InputError(
        request.table_path, 0, "max_range",
        fmt::format("the table was made with a max range of {:.4f} m, this run reads to {:.4f} m "
                    "(the camera's range times --range-factor)",
                    table.max_range_m(), max_range));
  }
  return table;
}

// The distance from `p` to the nearest place of the table.
double NearestPlaceM(const localize::PlaceTable& table, const Eigen::Vector2d& p) {
  double nearest = std::numeric_limits<double>::infinity();
  for (const localize::PlaceEntry& e : table.entries()) {
    nearest = std::min(nearest, (Eigen::Vector2d(e.x_m, e.y_m) - p).norm());
  }
  return nearest;
}

// The index of the table place nearest `p` (the first of equals).
int NearestEntry(const localize::PlaceTable& table, const Eigen::Vector2d& p) {
  int entry = 0;
  double closest = std::numeric_limits<double>::infinity();
  for (std::size_t i = 0; i < table.entries().size(); ++i) {
    const localize::PlaceEntry& c = table.entries()[i];
    const double d = (Eigen::Vector2d(c.x_m, c.y_m) - p).norm();
    if (d < closest) {
      closest = d;
      entry = static_cast<int>(i);
    }
  }
  return entry;
}

// One signature's answer to a query seen at `truth`, `nearest_m` from the
// nearest table place.
PlaceQuery::Answer Answer(const localize::PlaceTable& table, const localize::ObservedPlace& seen,
                          localize::SignatureKind kind, const localize::PoseSearch& search,
                          const core::Pose2& truth, double nearest_m, double coarse_cell_m) {
  const std::vector<localize::PlaceMatch> best = table.Nearest(seen.view, kind, 1, search);
  PlaceQuery::Answer answer;
  answer.entry = best[0].entry;
  if (best[0].position_m) {
    // The table place nearest the refined position is the answer.
    answer.position_error_m = (*best[0].position_m - truth.translation()).norm();
    answer.entry = NearestEntry(table, *best[0].position_m);
  }
  const localize::PlaceEntry& e = table.entries()[static_cast<std::size_t>(answer.entry)];
  answer.off_m = (Eigen::Vector2d(e.x_m, e.y_m) - truth.translation()).norm();
  if (best[0].heading_rad) {
    answer.heading_error_deg =
        std::abs(core::RadToDeg(core::NormalizeAngle(*best[0].heading_rad - truth.heading())));
  }
  answer.place_ok = answer.off_m <= nearest_m + coarse_cell_m + kPlaceTieM;
  answer.heading_ok = answer.place_ok && answer.heading_error_deg &&
                      *answer.heading_error_deg <= kHeadingToleranceDeg;
  return answer;
}

// Counts one answer into its signature's score (and the sum of its heading
// errors over right places).
void Count(const PlaceQuery::Answer& answer, bool informative, SignatureScore& score,
           double& heading_error_sum) {
  if (answer.place_ok) {
    ++score.place_hits;
    if (answer.heading_error_deg) heading_error_sum += *answer.heading_error_deg;
  }
  if (answer.heading_ok) ++score.heading_hits;
  if (informative) {
    score.informative_place_hits += answer.place_ok ? 1 : 0;
    score.informative_heading_hits += answer.heading_ok ? 1 : 0;
  }
}

// The table of request.table_path when that file exists, else one built
// (and saved there when a path is given); `progress(done, total)` while building.
struct QueriedTable {
  localize::PlaceTable table;
  bool loaded = false;
};

QueriedTable LoadOrBuildTable(const PlacesRequest& request, const sim::World& world,
                              eval::PlaceObserver& observer, double spacing_m, double max_range,
                              const std::function<void(int, int)>& progress) {
  if (!request.table_path.empty() && std::filesystem::exists(request.table_path)) {
    return {LoadTable(request, world, max_range), true};
  }
  localize::PlaceTable table = eval::BuildPlaceTable(world, observer, spacing_m, progress);
  if (table.entries().empty()) {
    throw core::InputError(request.world_path, 0, "--spacing",
                           "no place of the grid has room for the robot");
  }
  if (!request.table_path.empty()) io::SavePlaceTable(table, request.table_path);
  return {std::move(table), false};
}

// One query seen at `truth`: every signature's answer, counted into
// result's scores (and the sums of their heading errors).
PlaceQuery Query(const localize::PlaceTable& table, const localize::ObservedPlace& seen,
                 const core::Pose2& truth, const localize::PoseSearch& search, PlacesResult& result,
                 std::vector<double>& heading_error_sum) {
  PlaceQuery record{truth, NearestPlaceM(table, truth.translation()), 0, {}};
  for (const core::ReadingKind kind : seen.kinds) {
    record.seen_bins += kind != core::ReadingKind::kClear ? 1 : 0;
  }
  const bool informative = record.seen_bins >= kInformativeBins;
  result.informative_queries += informative ? 1 : 0;
  for (std::size_t s = 0; s < result.scores.size(); ++s) {
    record.answers.push_back(Answer(table, seen, result.scores[s].kind, search, truth,
                                    record.nearest_m, result.coarse_cell_m));
    Count(record.answers.back(), informative, result.scores[s], heading_error_sum[s]);
  }
  return record;
}

}  // namespace

PlacesResult MeasurePlaces(const PlacesRequest& request) {
  CheckPlacesRequest(request);
  const sim::World world = io::LoadWorldFile(request.world_path);
  PlacesResult result;
  result.world_name = world.name();
  result.coarse_cell_m = eval::CoarseCellSize(world);
  result.spacing_m = request.spacing_m.value_or(eval::DefaultTableSpacing(world));
  const double max_range = eval::PlaceMaxRange(world, request.range_factor);
  eval::PlaceObserver observer(world, request.method, max_range, request.seed);
  run::ProgressLine line(request.quiet);
  const auto start = Clock::now();

  const QueriedTable queried = LoadOrBuildTable(
      request, world, observer, result.spacing_m, max_range, [&](int done, int total) {
        line.Show(run::Seconds(Clock::now() - start), [&] {
          return fmt::format("places {}: table {}/{} pirouettes", world.name(), done, total);
        });
      });
  const localize::PlaceTable& table = queried.table;
  result.table_loaded = queried.loaded;
  result.build_s = run::Seconds(Clock::now() - start);
  result.table_places = static_cast<int>(table.entries().size());
  result.max_range_m = table.max_range_m();

  for (localize::SignatureKind kind : localize::kSignatureKinds) result.scores.push_back({kind});
  const localize::PoseSearch search{request.refine ? kSearchRadiusSpacings * result.spacing_m : 0.0,
                                    0.5 * result.coarse_cell_m};
  std::vector<double> heading_error_sum(result.scores.size(), 0.0);
  const auto query_start = Clock::now();
  const std::vector<core::Pose2> truths =
      sim::RandomRobotPoses(world, request.queries, request.seed, request.world_path);
  for (std::size_t q = 0; q < truths.size(); ++q) {
    const localize::ObservedPlace seen = observer.Observe(truths[q], QuerySeed(request.seed, q));
    result.query_log.push_back(Query(table, seen, truths[q], search, result, heading_error_sum));
    line.Show(run::Seconds(Clock::now() - start), [&] {
      std::string text =
          fmt::format("places {}: query {}/{}", world.name(), q + 1, request.queries);
      for (const SignatureScore& score : result.scores) {
        text += fmt::format("  {} {}", localize::SignatureKindName(score.kind), score.place_hits);
      }
      return text;
    });
  }
  for (std::size_t s = 0; s < result.scores.size(); ++s) {
    SignatureScore& score = result.scores[s];
    if (score.place_hits > 0) {
      score.mean_heading_error_deg = heading_error_sum[s] / score.place_hits;
    }
  }
  result.queries = request.queries;
  result.query_s = run::Seconds(Clock::now() - query_start);
  return result;
}

nlohmann::json PlacesJson(const PlacesRequest& request, const PlacesResult& result) {
  nlohmann::json out;
  out["format"] = "pirouette-places-report/1";
  out["world"] = result.world_name;
  out["world_file"] = request.world_path;
  out["method"] = std::string(vision::MaskSourceName(request.method));
  out["seed"] = request.seed;
  out["refine"] = request.refine;
  out["queries"] = result.queries;
  out["informative_queries"] = result.informative_queries;
  out["informative_bins"] = kInformativeBins;
  out["table"] = {{"places", result.table_places},
                  {"loaded", result.table_loaded},
                  {"file", request.table_path},
                  {"spacing_m", result.spacing_m},
                  {"max_range_m", result.max_range_m}};
  out["coarse_cell_m"] = result.coarse_cell_m;
  out["heading_tolerance_deg"] = kHeadingToleranceDeg;
  nlohmann::json signatures = nlohmann::json::object();
  for (const SignatureScore& score : result.scores) {
    nlohmann::json s;
    const double n = std::max(1, result.queries);
    s["place_rate"] = score.place_hits / n;
    const double informative = std::max(1, result.informative_queries);
    s["informative_place_rate"] = score.informative_place_hits / informative;
    s["place_hits"] = score.place_hits;
    if (localize::SignatureGivesHeading(score.kind)) {
      s["heading_rate"] = score.heading_hits / n;
      s["heading_hits"] = score.heading_hits;
      s["informative_heading_rate"] = score.informative_heading_hits / informative;
      s["mean_heading_error_deg"] = score.mean_heading_error_deg;
    } else {
      s["heading_rate"] = nullptr;
    }
    signatures[std::string(localize::SignatureKindName(score.kind))] = s;
  }
  out["signatures"] = signatures;
  nlohmann::json log = nlohmann::json::array();
  for (const PlaceQuery& q : result.query_log) {
    nlohmann::json item;
    item["pose"] = {q.world_T_robot.x(), q.world_T_robot.y(),
                    core::RadToDeg(q.world_T_robot.heading())};
    item["nearest_m"] = q.nearest_m;
    item["seen_bins"] = q.seen_bins;
    for (std::size_t s = 0; s < q.answers.size() && s < result.scores.size(); ++s) {
      const PlaceQuery::Answer& a = q.answers[s];
      nlohmann::json answer = {{"entry", a.entry}, {"off_m", a.off_m}, {"place_ok", a.place_ok}};
      if (a.position_error_m) answer["position_error_m"] = *a.position_error_m;
      if (a.heading_error_deg) {
        answer["heading_error_deg"] = *a.heading_error_deg;
        answer["heading_ok"] = a.heading_ok;
      }
      item[std::string(localize::SignatureKindName(result.scores[s].kind))] = answer;
    }
    log.push_back(item);
  }
  out["query_log"] = log;
  out["build_s"] = result.build_s;
  out["query_s"] = result.query_s;
  return out;
}

}  // namespace pirouette::tools
