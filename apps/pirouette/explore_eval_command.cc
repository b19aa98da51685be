#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "pirouette/core/input_error.h"
#include "pirouette/tools/explore_eval.h"

namespace pirouette::cli {
namespace {

constexpr const char* kExploreEvalHelp =
    "Explore worlds with several seeds and both planners and print a Markdown table "
    "(docs/measurements.md, \"Exploration maps\"): per world and planner the runs complete (and "
    "the others' status), coverage, false free/occupied and wall error (the worst run's), path "
    "length, stops and wall time (the mean run's), and the distance transform's path against "
    "the frontier baseline's. The worlds are files (--world), generated ones (--generate: the "
    "world `pirouette world generate` writes, made in memory and named as its file names it, "
    "e.g. maze-7), or both. Progress on standard error, the table on standard output.\n"
    "  example: pirouette explore-eval --world worlds/soccer_field.yaml --world "
    "worlds/maze.yaml --seeds 1,2,3,4,5\n"
    "  example: pirouette explore-eval --generate maze:1-10 --generate rooms:1,4,7 --seeds 1";

constexpr const char* kGenerateHelp =
    "explore the generated worlds of KIND (rooms, maze, clutter or apartment, as `world "
    "generate --kind` takes) and these world seeds (as `world generate --seed`), comma "
    "separated, A-B a range: maze:1-10, rooms:1,4,7. The world seeds draw the worlds; --seeds "
    "seeds each run's simulator noise. Repeat the option for more kinds";

}  // namespace

Command AddExploreEvalCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::ExploreEvalRequest>();
  auto planners =
      std::make_shared<std::vector<std::string>>(std::vector<std::string>{"dt", "frontier"});
  auto generate = std::make_shared<std::vector<std::string>>();
  CLI::App* cmd = parent.add_subcommand("explore-eval", kExploreEvalHelp);
  AddWorldsOption(cmd, request->world_paths);
  cmd->add_option("--generate", *generate, kGenerateHelp)->type_name("KIND:SEEDS");
  cmd->add_option("--seeds", request->seeds,
                  "the runs' seeds, comma separated: each world is explored once a seed and "
                  "planner, the seed drawing the simulator's noise (camera and odometry), not the "
                  "world (that is --generate's)")
      ->delimiter(',')
      ->capture_default_str();
  AddPlannersOption(cmd, *planners);
  AddMaxStepsOption(cmd, request->options.max_steps);
  return {
      cmd, [request, planners, generate] {
        request->generated.clear();
        for (const std::string& spec : *generate) {
          for (const tools::GeneratedWorldRequest& world : tools::ParseGenerateSpec(spec)) {
            request->generated.push_back(world);
          }
        }
        if (request->world_paths.empty() && request->generated.empty()) {
          throw core::InputError("", 0, "",
                                 "explore-eval needs worlds: --world FILE or --generate "
                                 "KIND:SEEDS (each may repeat)");
        }
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
