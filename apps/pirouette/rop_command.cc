#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
#include "apps/pirouette/parse.h"
#include "pirouette/core/input_error.h"
#include "pirouette/tools/rop.h"

namespace pirouette::cli {

Command AddRopCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::RopRequest>();
  auto pose = std::make_shared<std::string>();
  auto method = std::make_shared<std::string>("default");
  auto max_range = std::make_shared<double>(0.0);
  CLI::App* cmd = parent.add_subcommand(
      "rop",
      "Simulate one pirouette (12 turns of 30 degrees) at a pose and draw its Radial Obstacle "
      "Profile and the profile's DCT low-pass as a polar plot (the paper's Fig. 2).\n  example: "
      "pirouette rop --world worlds/soccer_field.yaml --pose 0.75,0.65,0 --out rop.png");
  cmd->add_option("--world", request->world_path, "world file (pirouette-world/1 YAML)")
      ->required();
  cmd->add_option("--pose", *pose, "X,Y,HEADING: metres, metres, degrees counter-clockwise from +x")
      ->required();
  cmd->add_option("--out", request->out_path, "the PNG to write")->required();
  cmd->add_option("--method", *method, "paper | default | truth (the simulator's true floor mask)")
      ->capture_default_str();
  cmd->add_option("--seed", request->seed, "seeds the sensor and odometry noise")
      ->capture_default_str();
  cmd->add_option("--cell", request->cell_m, "map cell size the max range is derived for, metres")
      ->capture_default_str();
  CLI::Option* max_range_option = cmd->add_option(
      "--max-range", *max_range, "the profiles' maximum range, metres (default: the camera's)");
  return {cmd, [request, pose, method, max_range, max_range_option] {
            const auto parsed = vision::ParseMaskSource(*method);
            if (!parsed) {
              throw core::InputError("", 0, "--method",
                                     "'" + *method + "' is not a method (paper | default | truth)");
            }
            request->method = *parsed;
            request->world_T_robot = ParsePose(*pose, "--pose");
            if (max_range_option->count() > 0) request->max_range_m = *max_range;
            tools::MakeRop(*request);
            std::fprintf(stderr, "wrote %s\n", request->out_path.c_str());
          }};
}

}  // namespace pirouette::cli
