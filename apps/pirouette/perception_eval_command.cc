#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
#include "pirouette/core/input_error.h"
#include "pirouette/eval/perception_eval.h"

namespace pirouette::cli {

Command AddPerceptionEvalCommand(CLI::App& parent) {
  auto request = std::make_shared<eval::PerceptionEvalRequest>();
  auto method = std::make_shared<std::string>("default");
  auto max_range = std::make_shared<double>(0.0);
  CLI::App* cmd = parent.add_subcommand(
      "perception-eval",
      "Measure the obstacle profiles of simulated frames against the truth ray-cast from the "
      "world: pirouettes at random poses; prints the median and 95th percentile range error and "
      "the rate of wrong classes as JSON.\n  example: pirouette perception-eval --world "
      "worlds/soccer_field.yaml --world worlds/maze.yaml --method paper");
  cmd->add_option("--world", request->world_paths, "world file(s) (pirouette-world/1 YAML)")
      ->required();
  cmd->add_option("--method", *method, "paper | default | truth (the simulator's true floor mask)")
      ->capture_default_str();
  cmd->add_option("--poses", request->poses, "random poses a world, a pirouette at each")
      ->capture_default_str();
  cmd->add_option("--seed", request->seed, "seeds the poses and the noise")->capture_default_str();
  cmd->add_option("--cell", request->cell_m, "map cell size the max range is derived for, metres")
      ->capture_default_str();
  CLI::Option* max_range_option = cmd->add_option(
      "--max-range", *max_range, "the profiles' maximum range, metres (default: the camera's)");
  return {cmd, [request, method, max_range, max_range_option] {
            const auto parsed = vision::ParseMaskSource(*method);
            if (!parsed) {
              throw core::InputError("", 0, "--method",
                                     "'" + *method + "' is not a method (paper | default | truth)");
            }
            request->method = *parsed;
            if (max_range_option->count() > 0) request->max_range_m = *max_range;
            const auto worlds = eval::EvaluatePerception(*request);
            std::fputs(eval::PerceptionEvalJson(*request, worlds).c_str(), stdout);
          }};
}

}  // namespace pirouette::cli
