#include <cstdio>
#include <memory>

#include "apps/pirouette/command.h"
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
  cmd->add_option("--world", request->world_path, "world file (pirouette-world/1 YAML)")
      ->required();
  cmd->add_option("--pose", *pose, "X,Y,HEADING: metres, metres, degrees counter-clockwise from +x")
      ->required();
  cmd->add_option("--out", request->out_path, "the PNG to write")->required();
  cmd->add_option("--seed", request->seed, "seeds the sensor noise")->capture_default_str();
  return {cmd, [request, pose] {
            request->world_T_robot = ParsePose(*pose, "--pose");
            tools::RenderView(*request);
            std::fprintf(stderr, "wrote %s\n", request->out_path.c_str());
          }};
}

}  // namespace pirouette::cli
