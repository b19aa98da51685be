#include <cstdio>
#include <memory>
#include <string>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "pirouette/eval/map_evaluation.h"
#include "pirouette/io/image_io.h"
#include "pirouette/io/map_file.h"
#include "pirouette/io/world_file.h"

namespace pirouette::cli {

Command AddEvalCommand(CLI::App& parent) {
  auto world_path = std::make_shared<std::string>();
  auto map_path = std::make_shared<std::string>();
  auto picture_path = std::make_shared<std::string>();
  CLI::App* cmd = parent.add_subcommand(
      "eval",
      "Judge a map (ROS map_server YAML + image) against a world's ground truth and print, as "
      "JSON on standard output: coverage (the fraction of the floor the robot can reach that the "
      "map marks free), false_free, false_occupied (occupied cells more than 2 cells from any "
      "true obstacle), wall_error_m and the map's cell counts. With --picture, also draw where the "
      "map is wrong.\n  example: pirouette eval --world worlds/soccer_field.yaml --map "
      "out/map.yaml --picture wrong.png");
  AddWorldOption(cmd, *world_path)->required();
  cmd->add_option("--map", *map_path, "map file (map_server YAML, e.g. out/map.yaml)")->required();
  cmd->add_option("--picture", *picture_path,
                  "also write the map judged cell by cell as a PNG: free white, occupied black, "
                  "unknown grey as in map.png; false free cells red, false occupied cells blue, "
                  "reachable floor left unknown pale amber");
  return {cmd, [world_path, map_path, picture_path] {
            const sim::World world = io::LoadWorldFile(*world_path);
            const mapping::TrinaryMap map = io::ReadRosMap(*map_path);
            const eval::JudgedMap judged = eval::JudgeMap(map, world);
            if (!picture_path->empty()) {
              io::WritePng(*picture_path, eval::DrawJudgedMap(map, judged));
              std::fprintf(stderr, "wrote %s\n", picture_path->c_str());
            }
            const std::string json = eval::MapEvaluationJson(judged.evaluation);
            std::fputs(json.c_str(), stdout);
          }};
}

}  // namespace pirouette::cli
