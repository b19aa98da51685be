#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "apps/pirouette/parse.h"
#include "pirouette/tools/rop.h"

namespace pirouette::cli {

Command AddRopCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::RopRequest>();
  auto pose = std::make_shared<std::string>();
  auto method = std::make_shared<std::string>("default");
  CLI::App* cmd = parent.add_subcommand(
      "rop",
      "Simulate one pirouette (12 turns of 30 degrees) at a pose and draw its Radial Obstacle "
      "Profile and the profile's DCT low-pass as a polar plot (the paper's Fig. 2).\n  example: "
      "pirouette rop --world worlds/soccer_field.yaml --pose 0.75,0.65,0 --out rop.png");
  AddWorldOption(cmd, request->world_path)->required();
  AddPoseOption(cmd, *pose, "where the robot pirouettes")->required();
  AddOutPngOption(cmd, request->out_path, "the polar plot")->required();
  AddMethodOption(cmd, *method, kMaskSources);
  AddSeedOption(cmd, request->seed, "the simulator's noise (camera and odometry)");
  AddCellOption(cmd, request->cell_m);
  AddMaxRangeOption(cmd, request->max_range_m, "the camera's, by the paper's rule for --cell");
  return {cmd, [request, pose, method] {
            request->method = *vision::ParseMaskSource(*method);
            request->world_T_robot = ParsePose(*pose, "--pose");
            tools::MakeRop(*request);
            std::fprintf(stderr, "wrote %s\n", request->out_path.c_str());
          }};
}

}  // namespace pirouette::cli
