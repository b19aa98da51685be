#pragma once

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "pirouette/eval/map_evaluation.h"
#include "pirouette/run/explorer.h"

namespace pirouette::tools {

// What `pirouette explore-eval` was asked: whole explorations of worlds with
// several seeds and planners, for the table of docs/measurements.md,
// "Exploration maps".
struct ExploreEvalRequest {
  std::vector<std::string> world_paths;
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

// Runs every world × planner × seed; `on_run` (if set) hears of each run as
// it ends. Throws core::InputError for a bad world.
std::vector<ExploreEvalRun> EvaluateExploration(
    const ExploreEvalRequest& request,
    const std::function<void(const ExploreEvalRun&)>& on_run = {});

// The Markdown table of the runs: per world and planner, the runs complete,
// coverage (worst), false_free and false_occupied (worst), wall_error_m
// (worst, and in cells), mean path length and stops, and the distance
// transform planner's path length as a fraction of the frontier baseline's.
std::string ExploreEvalTable(const std::vector<ExploreEvalRun>& runs);

}  // namespace pirouette::tools
