#include <cstdio>
#include <memory>
#include <string>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "apps/pirouette/parse.h"
#include "pirouette/core/angle.h"
#include "pirouette/draw/locate_picture.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/tools/locate.h"

namespace pirouette::cli {
namespace {

constexpr const char* kLocateHelp =
    "Global localization (the kidnapped robot): the simulator puts the robot at --pose, unseen; "
    "it makes one pirouette, and its Radial Obstacle Profile is looked up in the map's place "
    "table (Taylor, Geva & Boles 2005, §5.3: a table of places made from the saved map by ray "
    "casting, written beside the map and reused while the map is the same) and each candidate "
    "verified against the map; where the map has a colour layer (map_colours.png, which explore "
    "writes beside map.yaml) the colours of what the pirouette saw must agree with it too, which "
    "tells a symmetric room from its mirror image (§5.1's colour ROP). Prints 'found X Y H "
    "(agreement A)' or 'cannot tell: REASON' (exit 0 for both). With --random N instead of "
    "--pose, N random poses where the robot fits and the rates: found right (within one coarse "
    "cell, heading within 10 degrees), cannot tell, wrong.\n  example: pirouette explore --world "
    "worlds/soccer_field.yaml --out soccer && pirouette locate --map soccer/map.yaml --world "
    "worlds/soccer_field.yaml --pose 0.75,0.65,30 --picture where.png";

// The options given as text, read when the command runs.
struct LocateChoices {
  std::string pose;
  CLI::Option* pose_option = nullptr;
  std::string method = "default";
  std::string out;
  std::string picture;
};

// The map, the world, and where the robot is (one pose, or random ones).
void AddWhereOptions(CLI::App* cmd, tools::LocateRequest& request, LocateChoices& choices) {
  cmd->add_option("--map", request.map_path, "the saved map (map.yaml, as explore writes it)")
      ->required();
  AddWorldOption(cmd, request.world_path, "the simulator renders it")->required();
  choices.pose_option =
      AddPoseOption(cmd, choices.pose, "where the robot truly is (it is not told)");
  CLI::Option* random_option =
      cmd->add_option("--random", request.random, "measure over N random poses instead");
  choices.pose_option->excludes(random_option);
}

// What the pirouette is compared with: the map's place table and colours.
void AddMapKnowledgeOptions(CLI::App* cmd, tools::LocateRequest& request) {
  AddPlaceTableOption(cmd, request.table_path,
                      "default: places.yaml beside the map; loaded if made for this map, else "
                      "built and written");
  CLI::Option* colours_option =
      cmd->add_option("--colours", request.colours_path,
                      "the map's colour layer (default: map_colours.png beside the map, if there)");
  cmd->add_flag_callback(
         "--no-colours", [&request] { request.use_colours = false; },
         "ignore the map's colour layer (ranges only)")
      ->excludes(colours_option);
}

// How the pirouette is simulated and read.
void AddPirouetteOptions(CLI::App* cmd, tools::LocateRequest& request, LocateChoices& choices) {
  AddSeedOption(cmd, request.seed, "the random poses and the simulator's noise");
  AddMethodOption(cmd, choices.method, kMaskSources);
  AddRangeFactorOption(cmd, request.range_factor);
}

void AddOutputOptions(CLI::App* cmd, tools::LocateRequest& request, LocateChoices& choices) {
  AddReportOption(cmd, choices.out);
  cmd->add_option("--picture", choices.picture,
                  "write a PNG of the map with each pose's truth (green ring) and answer (blue: "
                  "right, red: wrong, orange: cannot tell); with --pose, the pirouette's hits too "
                  "(cyan), where the answer puts them");
  AddQuietOption(cmd, request.quiet);
}

// The table on standard error; the answer (one pose) or the rates (random
// poses) on standard output.
void Print(const tools::LocateRequest& request, const tools::LocateResult& result) {
  if (result.table_replaced) {
    std::fprintf(stderr,
                 "note: %s held a place table made for another map or settings; replaced it\n",
                 result.table_path.c_str());
  }
  std::fprintf(stderr, "table %s: %d places (spacing %.3f m)%s; colours: %s\n",
               result.table_path.c_str(), result.table_places, result.spacing_m,
               result.table_loaded ? ", loaded" : ", built",
               result.colours_path.empty() ? "none" : result.colours_path.c_str());
  if (request.pose) {
    const localize::LocateAnswer& a = result.trials.front().answer;
    if (a.found) {
      std::printf("found %.3f %.3f %.1f (agreement %.3f)\n", a.world_T_robot.x(),
                  a.world_T_robot.y(), core::RadToDeg(a.world_T_robot.heading()), a.agreement);
    } else {
      std::printf("cannot tell: %s\n", a.reason.c_str());
    }
    return;
  }
  const auto n = static_cast<double>(result.trials.size());
  std::printf(
      "locate: %zu random poses, coarse cell %.3f m: found right %.1f%% (%d), cannot tell %.1f%% "
      "(%d), wrong %.1f%% (%d); %.2f s a query\n",
      result.trials.size(), result.coarse_cell_m, 100.0 * result.found_right / n,
      result.found_right, 100.0 * result.cannot_tell / n, result.cannot_tell,
      100.0 * result.wrong / n, result.wrong, result.mean_locate_s);
}

void Locate(tools::LocateRequest& request, const LocateChoices& choices) {
  request.method = *vision::ParseMaskSource(choices.method);
  if (choices.pose_option->count() > 0) request.pose = ParsePose(choices.pose, "--pose");
  const tools::LocateResult result = tools::RunLocate(request);
  Print(request, result);
  if (!choices.out.empty()) {
    io::WriteFileAtomically(choices.out, tools::LocateJson(request, result).dump(2) + "\n");
    std::fprintf(stderr, "wrote %s\n", choices.out.c_str());
  }
  if (!choices.picture.empty()) {
    io::WritePng(choices.picture,
                 draw::DrawLocatePicture(*result.map, result.trials, result.coarse_cell_m));
    std::fprintf(stderr, "wrote %s\n", choices.picture.c_str());
  }
}

}  // namespace

Command AddLocateCommand(CLI::App& parent) {
  auto request = std::make_shared<tools::LocateRequest>();
  auto choices = std::make_shared<LocateChoices>();
  CLI::App* cmd = parent.add_subcommand("locate", kLocateHelp);
  AddWhereOptions(cmd, *request, *choices);
  AddMapKnowledgeOptions(cmd, *request);
  AddPirouetteOptions(cmd, *request, *choices);
  AddOutputOptions(cmd, *request, *choices);
  return {cmd, [request, choices] { Locate(*request, *choices); }};
}

}  // namespace pirouette::cli
