#include "pirouette/tools/explore_eval.h"

#include <fmt/format.h>

#include <algorithm>
#include <map>

#include "pirouette/io/world_file.h"
#include "pirouette/run/simulated_exploration.h"

namespace pirouette::tools {
namespace {

struct Summary {
  int runs = 0;
  int complete = 0;
  double worst_coverage = 1.0;
  double worst_false_free = 0.0;
  double worst_false_occupied = 0.0;
  double worst_wall_error_m = 0.0;
  double cell_m = 0.0;
  double path_sum = 0.0;
  double stops_sum = 0.0;
  double time_sum = 0.0;

  void Add(const ExploreEvalRun& run) {
    ++runs;
    complete += run.status == "complete" ? 1 : 0;
    worst_coverage = std::min(worst_coverage, run.eval.coverage);
    worst_false_free = std::max(worst_false_free, run.eval.false_free);
    worst_false_occupied = std::max(worst_false_occupied, run.eval.false_occupied);
    worst_wall_error_m = std::max(worst_wall_error_m, run.eval.wall_error_m);
    cell_m = run.cell_m;
    path_sum += run.path_length_m;
    stops_sum += run.stops;
    time_sum += run.wall_time_s;
  }
  double MeanPath() const { return path_sum / runs; }
};

}  // namespace

std::vector<ExploreEvalRun> EvaluateExploration(
    const ExploreEvalRequest& request, const std::function<void(const ExploreEvalRun&)>& on_run) {
  std::vector<ExploreEvalRun> runs;
  for (const std::string& path : request.world_paths) {
    const sim::World world = io::LoadWorldFile(path);
    for (run::PlannerKind planner : request.planners) {
      for (std::uint64_t seed : request.seeds) {
        run::ExplorationOptions options = request.options;
        options.seed = seed;
        options.planner = planner;
        const run::ExplorationResult result = run::Explore(world, options);
        ExploreEvalRun run;
        run.world_name = world.name();
        run.planner = planner;
        run.seed = seed;
        run.status = result.status;
        run.eval = eval::EvaluateMap(result.grid.ToTrinary(), world);
        run.cell_m = result.grid.geometry().resolution();
        run.path_length_m = result.path_length_m;
        run.stops = result.pirouettes;
        run.moves = result.moves;
        run.wall_time_s = result.wall_time_s;
        if (on_run) on_run(run);
        runs.push_back(std::move(run));
      }
    }
  }
  return runs;
}

std::string ExploreEvalTable(const std::vector<ExploreEvalRun>& runs) {
  std::vector<std::string> worlds;
  std::map<std::pair<std::string, run::PlannerKind>, Summary> summaries;
  for (const ExploreEvalRun& run : runs) {
    if (std::find(worlds.begin(), worlds.end(), run.world_name) == worlds.end()) {
      worlds.push_back(run.world_name);
    }
    summaries[{run.world_name, run.planner}].Add(run);
  }
  std::string out =
      "| world | planner | complete | coverage (worst) | false_free (worst) | false_occupied "
      "(worst) | wall_error_m (worst) | path m (mean) | stops (mean) | time s (mean) | path vs "
      "frontier |\n"
      "| --- | --- | --- | --- | --- | --- | --- | --- | --- | --- | --- |\n";
  for (const std::string& world : worlds) {
    for (run::PlannerKind planner :
         {run::PlannerKind::kDistanceTransform, run::PlannerKind::kFrontier}) {
      const auto it = summaries.find({world, planner});
      if (it == summaries.end()) continue;
      const Summary& s = it->second;
      std::string ratio;
      const auto baseline = summaries.find({world, run::PlannerKind::kFrontier});
      if (planner == run::PlannerKind::kDistanceTransform && baseline != summaries.end()) {
        ratio = fmt::format("{:.2f}×", s.MeanPath() / baseline->second.MeanPath());
      }
      out += fmt::format(
          "| {} | {} | {}/{} | {:.3f} | {:.4f} | {:.4f} | {:.4f} ({:.2f} cells) | {:.2f} | {:.1f} "
          "| {:.1f} | {} |\n",
          world, run::PlannerKindName(planner), s.complete, s.runs, s.worst_coverage,
          s.worst_false_free, s.worst_false_occupied, s.worst_wall_error_m,
          s.worst_wall_error_m / s.cell_m, s.MeanPath(), s.stops_sum / s.runs, s.time_sum / s.runs,
          ratio);
    }
  }
  return out;
}

}  // namespace pirouette::tools
