#include "pirouette/tools/locate.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <limits>
#include <numbers>
#include <optional>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/colour_map_file.h"
#include "pirouette/io/map_file.h"
#include "pirouette/io/place_table_file.h"
#include "pirouette/io/world_file.h"
#include "pirouette/localize/map_view.h"
#include "pirouette/mapping/radial_profile.h"
#include "pirouette/mapping/trinary_map.h"
#include "pirouette/run/explorer.h"
#include "pirouette/run/progress_line.h"
#include "pirouette/run/stage_timer.h"
#include "pirouette/sim/simulated_pirouette.h"
#include "pirouette/tools/places.h"

namespace pirouette::tools {
namespace {

using Clock = std::chrono::steady_clock;

// The map's colour layer as LocateRequest::colours_path says; result.colours_path
// names the file read (empty: none).
localize::ColourMap LoadColours(const LocateRequest& request, const mapping::TrinaryMap& map,
                                LocateResult& result) {
  if (!request.use_colours) return {};
  result.colours_path =
      request.colours_path.empty() ? io::ColourMapPathFor(request.map_path) : request.colours_path;
  if (!request.colours_path.empty() || std::filesystem::exists(result.colours_path)) {
    return io::ReadColourMap(result.colours_path, map.geometry);
  }
  result.colours_path.clear();
  return {};
}

// The place table of result.table_path when it was made for this map and
// settings, else one built and written there (result.table_loaded,
// result.table_replaced say which).
localize::PlaceTable LoadOrBuildTable(const LocateRequest& request, const mapping::TrinaryMap& map,
                                      const localize::ColourMap& colours, double radius_m,
                                      LocateResult& result) {
  const std::string name =
      localize::MapTableName(map, colours, radius_m, result.spacing_m, result.max_range_m);
  localize::PlaceTable table;
  if (std::filesystem::exists(result.table_path)) {
    table = io::LoadPlaceTable(result.table_path);
    result.table_loaded = table.world() == name && !table.entries().empty();
    result.table_replaced = !result.table_loaded;
  }
  if (!result.table_loaded) {
    table =
        localize::BuildMapPlaceTable(map, colours, radius_m, result.spacing_m, result.max_range_m);
    if (table.entries().empty()) {
      throw core::InputError(request.map_path, 0, "",
                             "the map has no free place where the robot fits");
    }
    io::SavePlaceTable(table, result.table_path);
  }
  return table;
}

// How far the trial's answer lies from its truth, and whether it is right.
void Judge(const LocateRequest& request, double coarse_cell_m, localize::LocateTrial& trial) {
  trial.position_error_m =
      (trial.answer.world_T_robot.translation() - trial.truth.translation()).norm();
  trial.heading_error_deg = std::abs(core::RadToDeg(
      core::NormalizeAngle(trial.answer.world_T_robot.heading() - trial.truth.heading())));
  const bool close = trial.position_error_m <= coarse_cell_m &&
                     trial.heading_error_deg <= request.options.heading_tolerance_deg;
  trial.right = trial.answer.found && close;
}

}  // namespace

LocateResult RunLocate(const LocateRequest& request) {
  if (!request.pose && request.random < 1) {
    throw core::InputError("", 0, "--pose", "give --pose X,Y,H or --random N (N >= 1)");
  }
  // Rays pass the map's pinholes (FillPinholes), here and in the table.
  mapping::TrinaryMap map = mapping::FillPinholes(io::ReadRosMap(request.map_path), kPinholeCells);
  const sim::World world = io::LoadWorldFile(request.world_path);
  LocateResult result;
  result.coarse_cell_m = eval::CoarseCellSize(world);
  result.spacing_m = eval::DefaultTableSpacing(world);
  result.max_range_m = eval::PlaceMaxRange(world, request.range_factor);
  result.table_path =
      request.table_path.empty()
          ? (std::filesystem::path(request.map_path).parent_path() / "places.yaml").string()
          : request.table_path;
  if (request.pose) sim::PlaceRobot(world, *request.pose, "--pose");  // throws when it does not fit
  const localize::ColourMap colours = LoadColours(request, map, result);

  const auto table_start = Clock::now();
  const localize::PlaceTable table =
      LoadOrBuildTable(request, map, colours, world.robot().radius, result);
  result.table_s = run::Seconds(Clock::now() - table_start);
  result.table_places = static_cast<int>(table.entries().size());

  const std::vector<core::Pose2> truths =
      request.pose ? std::vector<core::Pose2>{*request.pose}
                   : sim::RandomRobotPoses(world, request.random, request.seed, request.world_path);
  eval::PlaceObserver observer(world, request.method, result.max_range_m, request.seed);
  run::ProgressLine line(request.quiet);
  const auto start = Clock::now();
  double locate_s = 0.0;
  for (std::size_t q = 0; q < truths.size(); ++q) {
    localize::LocateTrial trial;
    trial.truth = truths[q];
    trial.seen = observer.Observe(truths[q], QuerySeed(request.seed, q));
    const auto t0 = Clock::now();
    trial.answer = localize::Locate(map, colours, table, trial.seen.view, trial.seen.kinds,
                                    result.spacing_m, result.coarse_cell_m, request.options);
    locate_s += run::Seconds(Clock::now() - t0);
    Judge(request, result.coarse_cell_m, trial);
    result.found_right += trial.right ? 1 : 0;
    result.cannot_tell += trial.answer.found ? 0 : 1;
    result.wrong += trial.answer.found && !trial.right ? 1 : 0;
    result.trials.push_back(std::move(trial));
    line.Show(run::Seconds(Clock::now() - start), [&] {
      return fmt::format("locate {}: {}/{} pirouettes, {} found right, {} cannot tell, {} wrong",
                         world.name(), q + 1, truths.size(), result.found_right, result.cannot_tell,
                         result.wrong);
    });
  }
  result.mean_locate_s = truths.empty() ? 0.0 : locate_s / truths.size();
  result.map = std::move(map);
  return result;
}

nlohmann::json LocateJson(const LocateRequest& request, const LocateResult& result) {
  const auto pose = [](const core::Pose2& p) {
    return nlohmann::json{{"x", p.x()}, {"y", p.y()}, {"heading_deg", core::RadToDeg(p.heading())}};
  };
  nlohmann::json trials = nlohmann::json::array();
  for (const localize::LocateTrial& t : result.trials) {
    nlohmann::json candidates = nlohmann::json::array();
    for (const localize::LocateCandidate& c : t.answer.candidates) {
      nlohmann::json j = pose(c.world_T_robot);
      j["agreement"] = c.score;
      j["compared"] = c.compared;
      candidates.push_back(j);
    }
    nlohmann::json j{{"truth", pose(t.truth)},
                     {"found", t.answer.found},
                     {"best", pose(t.answer.world_T_robot)},
                     {"agreement", t.answer.agreement},
                     {"runner_up", t.answer.runner_up},
                     {"compared", t.answer.compared},
                     {"seen_bins", t.answer.seen_bins},
                     {"position_error_m", t.position_error_m},
                     {"heading_error_deg", t.heading_error_deg},
                     {"right", t.right},
                     {"candidates", candidates}};
    if (!t.answer.found) j["reason"] = t.answer.reason;
    trials.push_back(j);
  }
  return {{"format", "pirouette-locate-report/1"},
          {"map", request.map_path},
          {"world", request.world_path},
          {"seed", request.seed},
          {"table", result.table_path},
          {"table_loaded", result.table_loaded},
          {"colours", result.colours_path.empty() ? nlohmann::json(nullptr)
                                                  : nlohmann::json(result.colours_path)},
          {"table_places", result.table_places},
          {"spacing_m", result.spacing_m},
          {"coarse_cell_m", result.coarse_cell_m},
          {"max_range_m", result.max_range_m},
          {"queries", result.trials.size()},
          {"found_right", result.found_right},
          {"cannot_tell", result.cannot_tell},
          {"wrong", result.wrong},
          {"table_s", result.table_s},
          {"mean_locate_s", result.mean_locate_s},
          {"trials", trials}};
}

}  // namespace pirouette::tools
