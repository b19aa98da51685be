#include "pirouette/tools/explore_eval.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <limits>
#include <map>
#include <optional>
#include <string_view>
#include <system_error>

#include "pirouette/core/input_error.h"
#include "pirouette/io/world_file.h"
#include "pirouette/run/simulated_exploration.h"
#include "pirouette/tools/world_generate.h"

namespace pirouette::tools {
namespace {

// A --generate value refused: the option, the value and what is wrong.
[[noreturn]] void ThrowBadGenerate(const std::string& text, const std::string& problem) {
  throw core::InputError("--generate", 0, "", fmt::format("'{}': {}", text, problem));
}

// A seed of SEEDS: decimal digits only, a whole number of 64 bits.
std::uint64_t ParseSeed(const std::string& text, std::string_view seed_text) {
  std::uint64_t seed = 0;
  const char* end = seed_text.data() + seed_text.size();
  const auto [stop, error] = std::from_chars(seed_text.data(), end, seed);
  if (seed_text.empty() || error != std::errc() || stop != end) {
    ThrowBadGenerate(text,
                     fmt::format("'{}' is not a seed (a whole number from 0 to {}); SEEDS is a "
                                 "list of seeds and ranges A-B, comma separated",
                                 seed_text, std::numeric_limits<std::uint64_t>::max()));
  }
  return seed;
}

// Appends the seeds of one item of SEEDS (`N` or `A-B`) to `seeds`, which
// holds at most kMaxGeneratedWorlds.
void AddSeeds(const std::string& text, std::string_view item, std::vector<std::uint64_t>& seeds) {
  const std::size_t dash = item.find('-');
  const std::uint64_t first = ParseSeed(text, item.substr(0, dash));
  const std::uint64_t last =
      dash == std::string_view::npos ? first : ParseSeed(text, item.substr(dash + 1));
  if (last < first) ThrowBadGenerate(text, fmt::format("the range {} runs backwards", item));
  if (last - first >= kMaxGeneratedWorlds - seeds.size()) {
    ThrowBadGenerate(text, fmt::format("more than {} worlds", kMaxGeneratedWorlds));
  }
  for (std::uint64_t seed = first;; ++seed) {
    if (std::find(seeds.begin(), seeds.end(), seed) != seeds.end()) {
      ThrowBadGenerate(text, fmt::format("seed {} is given twice", seed));
    }
    seeds.push_back(seed);
    if (seed == last) break;
  }
}

struct Summary {
  int runs = 0;
  int complete = 0;
  std::map<std::string, int> other_statuses;  // the runs that did not complete, by status
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
    if (run.status == "complete") {
      ++complete;
    } else {
      ++other_statuses[run.status];
    }
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
  // "4/5", or with runs that did not complete "3/5 (step-limit 1, stuck 1)".
  std::string Complete() const {
    std::string text = fmt::format("{}/{}", complete, runs);
    for (auto it = other_statuses.begin(); it != other_statuses.end(); ++it) {
      text +=
          fmt::format("{}{} {}", it == other_statuses.begin() ? " (" : ", ", it->first, it->second);
    }
    return other_statuses.empty() ? text : text + ")";
  }
};

// Explores `world` with every planner and seed of `request`, appending the runs.
void ExploreWorld(const sim::World& world, const ExploreEvalRequest& request,
                  const std::function<void(const ExploreEvalRun&)>& on_run,
                  std::vector<ExploreEvalRun>& runs) {
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
      run.eval = eval::EvaluateMap(result.grid.ToMapOfRecord(), world);
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

}  // namespace

std::vector<GeneratedWorldRequest> ParseGenerateSpec(const std::string& text) {
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos) {
    ThrowBadGenerate(text, "expected KIND:SEEDS, e.g. maze:1-10 or rooms:1,4,7");
  }
  const std::string kind_text = text.substr(0, colon);
  const std::optional<sim::WorldKind> kind = sim::ParseWorldKind(kind_text);
  if (!kind) {
    ThrowBadGenerate(text, fmt::format("unknown kind '{}' (expected rooms, maze, clutter or "
                                       "apartment)",
                                       kind_text));
  }
  std::vector<std::uint64_t> seeds;
  std::string_view rest = std::string_view(text).substr(colon + 1);
  while (true) {
    const std::size_t comma = rest.find(',');
    AddSeeds(text, rest.substr(0, comma), seeds);
    if (comma == std::string_view::npos) break;
    rest.remove_prefix(comma + 1);
  }
  std::vector<GeneratedWorldRequest> worlds;
  worlds.reserve(seeds.size());
  for (const std::uint64_t seed : seeds) worlds.push_back({*kind, seed});
  return worlds;
}

sim::World LoadGeneratedWorld(const GeneratedWorldRequest& request) {
  const GeneratedWorld world = GenerateValidWorld(request.kind, request.seed);
  return io::ParseWorldText(world.text, world.spec.name + " (generated)");
}

std::vector<ExploreEvalRun> EvaluateExploration(
    const ExploreEvalRequest& request, const std::function<void(const ExploreEvalRun&)>& on_run) {
  std::vector<ExploreEvalRun> runs;
  for (const std::string& path : request.world_paths) {
    ExploreWorld(io::LoadWorldFile(path), request, on_run, runs);
  }
  for (const GeneratedWorldRequest& generated : request.generated) {
    ExploreWorld(LoadGeneratedWorld(generated), request, on_run, runs);
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
      if (planner == run::PlannerKind::kDistanceTransform && baseline != summaries.end() &&
          baseline->second.MeanPath() > 0.0) {
        ratio = fmt::format("{:.2f}×", s.MeanPath() / baseline->second.MeanPath());
      }
      out += fmt::format(
          "| {} | {} | {} | {:.3f} | {:.4f} | {:.4f} | {:.4f} ({:.2f} cells) | {:.2f} | {:.1f} "
          "| {:.1f} | {} |\n",
          world, run::PlannerKindName(planner), s.Complete(), s.worst_coverage, s.worst_false_free,
          s.worst_false_occupied, s.worst_wall_error_m, s.worst_wall_error_m / s.cell_m,
          s.MeanPath(), s.stops_sum / s.runs, s.time_sum / s.runs, ratio);
    }
  }
  return out;
}

}  // namespace pirouette::tools
