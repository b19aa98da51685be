#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "apps/pirouette/parse.h"
#include "pirouette/tools/render_view.h"

namespace pirouette::cli {

Command AddRenderCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::RenderViewRequest>();
  auto pose = std::make_shared<std::string>();
  CLI::App* cmd = parent.add_subcommand(
      "render",
      "Write what the robot's camera sees at a pose, with its lens distortion, vignetting and "
      "noise, as a PNG.\n  example: pirouette render --world worlds/soccer_field.yaml "
      "--pose 0.2,0.2,45 --out view.png");
  AddWorldOption(cmd, request->world_path)->required();
  AddPoseOption(cmd, *pose, "where the robot stands")->required();
  AddOutPngOption(cmd, request->out_path, "the camera's view")->required();
  AddSeedOption(cmd, request->seed, "the simulator's camera noise");
  return {cmd, [request, pose] {
            request->world_T_robot = ParsePose(*pose, "--pose");
            tools::RenderView(*request);
            std::fprintf(stderr, "wrote %s\n", request->out_path.c_str());
          }};
}

}  // namespace pirouette::cli
