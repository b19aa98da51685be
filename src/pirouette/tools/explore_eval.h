#pragma once

#include <cstddef>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pirouette/eval/map_evaluation.h"
#include "pirouette/run/explorer.h"
#include "pirouette/sim/world.h"
#include "pirouette/sim/world_generator.h"

namespace pirouette::tools {

// A world `explore-eval --generate` makes instead of reading a file: the one
// `pirouette world generate --kind KIND --seed SEED` writes (named
// `KIND-SEED`). Its seed draws the world; the runs' seeds (--seeds) are the
// simulator's noise, another thing.
struct GeneratedWorldRequest {
  sim::WorldKind kind = sim::WorldKind::kRooms;
  std::uint64_t seed = 1;

  bool operator==(const GeneratedWorldRequest&) const = default;
};

// The most worlds one --generate value may ask for: far more than an
// evaluation runs in a day, few enough that a typo such as `maze:1-100000`
// is refused before anything runs.
inline constexpr std::size_t kMaxGeneratedWorlds = 1000;

// Parses one --generate value, `KIND:SEEDS`: KIND as `world generate --kind`
// takes it (rooms, maze, clutter, apartment), SEEDS a comma-separated list of
// seeds and inclusive ranges `A-B` (`maze:1-10`, `rooms:1,4,7`,
// `clutter:1-3,9`), in the order given. Throws core::InputError naming
// --generate and the value for an unknown kind, a seed that is not a whole
// number of 64 bits, a range that runs backwards, a seed given twice or more
// than kMaxGeneratedWorlds worlds.
std::vector<GeneratedWorldRequest> ParseGenerateSpec(const std::string& text);

// The generated world exactly as LoadWorldFile reads the file `world
// generate` writes for it: the same text (GenerateValidWorld's), read by
// io::ParseWorldText, never written to disk. Throws std::runtime_error when
// no draw of the seed is valid.
sim::World LoadGeneratedWorld(const GeneratedWorldRequest& request);

// What `pirouette explore-eval` was asked: whole explorations of worlds with
// several seeds and planners, for the table of docs/measurements.md,
// "Exploration maps".
struct ExploreEvalRequest {
  std::vector<std::string> world_paths;
  std::vector<GeneratedWorldRequest> generated;  // explored after world_paths
  std::vector<std::uint64_t> seeds = {1, 2, 3, 4, 5};
  std::vector<run::PlannerKind> planners = {run::PlannerKind::kDistanceTransform,
                                            run::PlannerKind::kFrontier};
  run::ExplorationOptions options;  // seed and planner are set per run
};

// One run's figures.
struct ExploreEvalRun {
  std::string world_name;
  run::PlannerKind planner = run::PlannerKind::kDistanceTransform;
  std::uint64_t seed = 0;
  std::string status;
  eval::MapEvaluation eval;
  double cell_m = 0.0;
  double path_length_m = 0.0;
  int stops = 0;  // pirouettes
  int moves = 0;
  double wall_time_s = 0.0;
};

// Runs every world × planner × seed, the files' worlds first, then the
// generated ones (each made when its turn comes); `on_run` (if set) hears of
// each run as it ends. Throws core::InputError for a bad world file,
// std::runtime_error for a seed with no valid world.
std::vector<ExploreEvalRun> EvaluateExploration(
    const ExploreEvalRequest& request,
    const std::function<void(const ExploreEvalRun&)>& on_run = {});

// The Markdown table of the runs: per world and planner, the runs complete
// (and how many ended with each other status), coverage (worst), false_free and false_occupied
// (worst), wall_error_m (worst, and in cells), mean path length and stops, and the distance
// transform planner's path length as a fraction of the frontier baseline's.
std::string ExploreEvalTable(const std::vector<ExploreEvalRun>& runs);

}  // namespace pirouette::tools
