#include <cstdio>
#include <memory>
#include <string>

#include "apps/pirouette/command.h"
#include "apps/pirouette/parse.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/draw/locate_picture.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/tools/locate.h"

namespace pirouette::cli {

Command AddLocateCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::LocateRequest>();
  auto pose = std::make_shared<std::string>();
  auto method = std::make_shared<std::string>("default");
  auto out = std::make_shared<std::string>();
  CLI::App* cmd = parent.add_subcommand(
      "locate",
      "Global localization (the kidnapped robot): the simulator puts the robot at --pose, unseen; "
      "it makes one pirouette, and its Radial Obstacle Profile is looked up in the map's place "
      "table (Taylor, Geva & Boles 2005, §5.3: a table of places made from the saved map by ray "
      "casting, written beside the map and reused while the map is the same) and each candidate "
      "verified against the map; where the map has a colour layer (map_colours.png, which explore "
      "writes beside map.yaml) the colours of what the pirouette saw must agree with it too, "
      "which tells a symmetric room from its mirror image (§5.1's colour ROP). Prints 'found X Y H "
      "(agreement A)' or 'cannot tell: REASON' "
      "(exit 0 for both). With --random N instead of --pose, N random poses where the robot fits "
      "and the rates: found right (within one coarse cell, heading within 10 degrees), cannot "
      "tell, wrong.\n  example: pirouette explore --world worlds/soccer_field.yaml --out soccer "
      "&& pirouette locate --map soccer/map.yaml --world worlds/soccer_field.yaml --pose "
      "0.75,0.65,30 --picture where.png");
  cmd->add_option("--map", request->map_path, "the saved map (map.yaml, as explore writes it)")
      ->required();
  cmd->add_option("--world", request->world_path,
                  "world file (pirouette-world/1 YAML) the simulator renders")
      ->required();
  CLI::Option* pose_option = cmd->add_option(
      "--pose", *pose, "X,Y,HEADING where the robot truly is: metres, metres, degrees");
  CLI::Option* random_option =
      cmd->add_option("--random", request->random, "measure over N random poses instead");
  pose_option->excludes(random_option);
  cmd->add_option("--table", request->table_path,
                  "the map's place table (pirouette-places/1 YAML; default: places.yaml beside "
                  "the map): loaded if made for this map, else built and written");
  CLI::Option* colours_option =
      cmd->add_option("--colours", request->colours_path,
                      "the map's colour layer (default: map_colours.png beside the map, if there)");
  cmd->add_flag_callback(
         "--no-colours", [request] { request->use_colours = false; },
         "ignore the map's colour layer (ranges only)")
      ->excludes(colours_option);
  cmd->add_option("--seed", request->seed, "seeds the noise and the random poses")
      ->capture_default_str();
  cmd->add_option("--method", *method, "floor segmentation: paper | default | truth")
      ->capture_default_str();
  cmd->add_option("--range-factor", request->range_factor,
                  "read the pirouette and the map out to this many times the map's range, but no "
                  "farther than every image column sees the floor")
      ->capture_default_str();
  cmd->add_option("--out", *out, "write the JSON report here (atomically)");
  auto picture = std::make_shared<std::string>();
  cmd->add_option("--picture", *picture,
                  "write a PNG of the map with each pose's truth (green ring) and answer (blue: "
                  "right, red: wrong, orange: cannot tell); with --pose, the pirouette's hits too "
                  "(cyan), where the answer puts them");
  cmd->add_flag("--quiet", request->quiet, "no progress line");
  return {cmd, [request, pose, pose_option, method, out, picture] {
            const auto parsed = vision::ParseMaskSource(*method);
            if (!parsed) {
              throw core::InputError("", 0, "--method",
                                     "'" + *method + "' is not a method (paper | default | truth)");
            }
            request->method = *parsed;
            if (pose_option->count() > 0) request->pose = ParsePose(*pose, "--pose");
            const tools::LocateResult result = tools::RunLocate(*request);
            if (result.table_replaced) {
              std::fprintf(stderr,
                           "note: %s held a place table made for another map or settings; "
                           "replaced it\n",
                           result.table_path.c_str());
            }
            std::fprintf(stderr, "table %s: %d places (spacing %.3f m)%s; colours: %s\n",
                         result.table_path.c_str(), result.table_places, result.spacing_m,
                         result.table_loaded ? ", loaded" : ", built",
                         result.colours_path.empty() ? "none" : result.colours_path.c_str());
            if (request->pose) {
              const localize::LocateAnswer& a = result.trials.front().answer;
              if (a.found) {
                std::printf("found %.3f %.3f %.1f (agreement %.3f)\n", a.world_T_robot.x(),
                            a.world_T_robot.y(), core::RadToDeg(a.world_T_robot.heading()),
                            a.agreement);
              } else {
                std::printf("cannot tell: %s\n", a.reason.c_str());
              }
            } else {
              const auto n = static_cast<double>(result.trials.size());
              std::printf(
                  "locate: %zu random poses, coarse cell %.3f m: found right %.1f%% (%d), cannot "
                  "tell %.1f%% (%d), wrong %.1f%% (%d); %.2f s a query\n",
                  result.trials.size(), result.coarse_cell_m, 100.0 * result.found_right / n,
                  result.found_right, 100.0 * result.cannot_tell / n, result.cannot_tell,
                  100.0 * result.wrong / n, result.wrong, result.mean_locate_s);
            }
            if (!out->empty()) {
              io::WriteFileAtomically(*out, tools::LocateJson(*request, result).dump(2) + "\n");
              std::fprintf(stderr, "wrote %s\n", out->c_str());
            }
            if (!picture->empty()) {
              io::WritePng(*picture, draw::DrawLocatePicture(*result.map, result.trials,
                                                             result.coarse_cell_m));
              std::fprintf(stderr, "wrote %s\n", picture->c_str());
            }
          }};
}

}  // namespace pirouette::cli
