#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "pirouette/tools/explore_eval.h"

namespace pirouette::cli {

Command AddExploreEvalCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::ExploreEvalRequest>();
  auto planners =
      std::make_shared<std::vector<std::string>>(std::vector<std::string>{"dt", "frontier"});
  CLI::App* cmd = parent.add_subcommand(
      "explore-eval",
      "Explore worlds with several seeds and both planners and print a Markdown table "
      "(docs/measurements.md, \"Exploration maps\": completion, coverage, false free/occupied, "
      "wall error, path length and stops; "
      "the distance transform's path against the frontier baseline's). Progress on standard "
      "error, the table on standard output.\n  example: pirouette explore-eval --world "
      "worlds/soccer_field.yaml --world worlds/maze.yaml --seeds 1,2,3,4,5");
  AddWorldsOption(cmd, request->world_paths)->required();
  cmd->add_option("--seeds", request->seeds, "seeds, comma separated")
      ->delimiter(',')
      ->capture_default_str();
  AddPlannersOption(cmd, *planners);
  AddMaxStepsOption(cmd, request->options.max_steps);
  return {
      cmd, [request, planners] {
        request->planners.clear();
        for (const std::string& p : *planners) {
          request->planners.push_back(*run::ParsePlannerKind(p));
        }
        const auto runs = tools::EvaluateExploration(*request, [](const tools::ExploreEvalRun& r) {
          std::fprintf(stderr,
                       "explore-eval: %s %s seed %llu: %s, coverage %.3f, path %.2f m, "
                       "%d stops, %.1f s\n",
                       r.world_name.c_str(), std::string(run::PlannerKindName(r.planner)).c_str(),
                       static_cast<unsigned long long>(r.seed), r.status.c_str(), r.eval.coverage,
                       r.path_length_m, r.stops, r.wall_time_s);
        });
        std::fputs(tools::ExploreEvalTable(runs).c_str(), stdout);
      }};
}

}  // namespace pirouette::cli
