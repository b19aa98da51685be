#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "pirouette/eval/perception_eval.h"
#include "pirouette/tools/perception_eval.h"

namespace pirouette::cli {

Command AddPerceptionEvalCommand(CLI::App& parent) {
  auto request = std::make_shared<eval::PerceptionEvalRequest>();
  auto method = std::make_shared<std::string>("default");
  CLI::App* cmd = parent.add_subcommand(
      "perception-eval",
      "Measure the obstacle profiles of simulated frames against the truth ray-cast from the "
      "world: pirouettes at random poses; prints the median and 95th percentile range error and "
      "the rate of wrong classes as JSON.\n  example: pirouette perception-eval --world "
      "worlds/soccer_field.yaml --world worlds/maze.yaml --method paper");
  AddWorldsOption(cmd, request->world_paths)->required();
  AddMethodOption(cmd, *method, kMaskSources);
  cmd->add_option("--poses", request->poses, "random poses a world, a pirouette at each")
      ->capture_default_str();
  AddSeedOption(cmd, request->seed, "the random poses and the simulator's noise");
  AddCellOption(cmd, request->cell_m);
  AddMaxRangeOption(cmd, request->max_range_m, "the camera's, by the paper's rule for --cell");
  return {cmd, [request, method] {
            request->method = *vision::ParseMaskSource(*method);
            const auto worlds = eval::EvaluatePerception(*request);
            std::fputs(tools::PerceptionEvalJson(*request, worlds).c_str(), stdout);
          }};
}

}  // namespace pirouette::cli
