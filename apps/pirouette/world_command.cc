#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "apps/pirouette/parse.h"
#include "pirouette/core/input_error.h"
#include "pirouette/tools/world_from_map.h"
#include "pirouette/tools/world_generate.h"

namespace pirouette::cli {
namespace {

constexpr const char* kGenerateHelp =
    "Write a random world file of a kind, valid and the same for the same kind, seed and size: "
    "every cell of floor the robot's disc fits in is reachable from its start (checked as "
    "`pirouette eval` computes reachability; a draw that fails is drawn again from a derived "
    "seed, at most 50 times). Floor and wall colours (floors close to the walls' colour, walls "
    "as high as the camera), textures, obstacle shapes, sizes and colours, and the light vary "
    "with the seed; the file's comment says what was drawn. Kinds:\n"
    "  rooms      rooms joined by doors just wider than the robot, a few things in each "
    "(1.5-3 m; the Yujin robot, radius 0.04 m)\n"
    "  maze       a random spanning-tree maze, corridors 1.5-3 robot diameters wide (1.5-3 m)\n"
    "  clutter    one room crowded with boxes, cylinders, prisms and short walls (1.5-2.5 m)\n"
    "  apartment  rooms, doors and furniture at the apartment robot's scale (8-20 m; radius "
    "0.15 m, the webcam640 camera)\n"
    "The camera is written inline, so the file loads from any folder.\n"
    "  example: pirouette world generate --kind maze --seed 7 --out maze7.yaml";

// --size's help, with each kind's limits.
std::string SizeHelp() {
  std::string help =
      "X,Y: the floor's size in metres, to the millimetre (default: drawn for the kind); each side";
  for (const sim::WorldKind kind : sim::kWorldKinds) {
    const sim::WorldSizeLimits limits = sim::SizeLimitsOf(kind);
    help += fmt::format("{} {}-{} m for {}", kind == sim::kWorldKinds.front() ? "" : ",",
                        limits.min, limits.max, sim::WorldKindName(kind));
  }
  return help;
}

// `world generate`.
Command AddWorldGenerate(CLI::App& world) {
  auto request = std::make_shared<tools::WorldGenerateRequest>();
  auto kind = std::make_shared<std::string>();
  auto size = std::make_shared<std::string>();
  CLI::App* cmd = world.add_subcommand("generate", kGenerateHelp);
  cmd->add_option("--kind", *kind, "rooms, maze, clutter or apartment")->required();
  cmd->add_option("--seed", request->seed,
                  "seed of the world: the same kind, seed and size give the same file")
      ->required();
  cmd->add_option("--size", *size, SizeHelp());
  cmd->add_option("--out", request->out_path,
                  "the world file to write (pirouette-world/1 YAML, atomically)")
      ->required();
  return {
      cmd, [request, kind, size] {
        const std::optional<sim::WorldKind> parsed = sim::ParseWorldKind(*kind);
        if (!parsed) {
          throw core::InputError(
              "--kind", 0, "",
              fmt::format("unknown kind '{}' (expected rooms, maze, clutter or apartment)", *kind));
        }
        request->kind = *parsed;
        if (!size->empty()) {
          const std::vector<double> xy = ParseNumbers(*size, 2, "--size", "X,Y in metres");
          request->size = Eigen::Vector2d(xy[0], xy[1]);
        }
        const tools::GeneratedWorld world = tools::RunWorldGenerate(*request);
        const Eigen::Vector2d& floor = world.spec.floor.size;
        std::fprintf(stderr, "wrote %s: %s, %g x %g m, %zu obstacles (draw %d)\n",
                     request->out_path.c_str(), world.spec.name.c_str(), floor.x(), floor.y(),
                     world.spec.obstacles.size(), world.draw + 1);
      }};
}

constexpr const char* kFromMapHelp =
    "Write a world file from a ROS map_server map (a digital twin of a real building): the map "
    "is read exactly as map_server reads it (trinary, scale or raw mode, negate, the "
    "thresholds, PGM or PNG), and every cell map_server does not serve as free becomes a solid "
    "block (occupied and unknown alike: nothing may be explored where the map does not know). "
    "The floor is the map's extent, the map's frame moved so that its origin is the world's "
    "(0, 0). Gaps narrower than the robot (where a laser saw through a wall) are sealed, with "
    "every free cell the robot's disc cannot reach from its start; specks stay. The start is "
    "the point of the largest region the disc can drive in that lies farthest from its walls, "
    "unless --start gives one. The world names the map by its path (relative to the world "
    "file), so keep the map where it is.\n"
    "  example: pirouette world from-map --map ../shared/realdata/maps/sim_tb3_world/map.yaml "
    "--out tb3_world.yaml";

// `world from-map`.
Command AddWorldFromMap(CLI::App& world) {
  auto request = std::make_shared<tools::WorldFromMapRequest>();
  auto start = std::make_shared<std::string>();
  auto no_seal = std::make_shared<bool>(false);
  CLI::App* cmd = world.add_subcommand("from-map", kFromMapHelp);
  cmd->add_option("--map", request->map_path, "the map_server map's yaml file")->required();
  cmd->add_option("--out", request->out_path,
                  "the world file to write (pirouette-world/1 YAML, atomically)")
      ->required();
  cmd->add_option("--radius", request->radius_m, "the robot's radius in metres")
      ->capture_default_str();
  cmd->add_option("--camera", request->camera_path,
                  "a camera file, written inline (default: worlds/webcam640.yaml's camera, "
                  "0.30 m up)");
  cmd->add_option("--height", request->height_m,
                  "the blocks' height in metres (above the camera, as a building's walls are)")
      ->capture_default_str();
  cmd->add_option("--start", *start,
                  "X,Y[,HEADING]: the start in the map's frame (metres, degrees; default: "
                  "chosen)");
  cmd->add_flag("--no-seal", *no_seal,
                "keep every free cell, also those the robot cannot reach (the camera then sees "
                "through gaps it cannot pass)");
  return {cmd, [request, start, no_seal] {
            if (!start->empty()) {
              const std::size_t count = std::count(start->begin(), start->end(), ',') == 1 ? 2 : 3;
              std::vector<double> xyh =
                  ParseNumbers(*start, count, "--start", "X,Y or X,Y,HEADING (metres, degrees)");
              if (count == 2) xyh.push_back(0.0);
              request->start = Eigen::Vector3d(xyh[0], xyh[1], xyh[2]);
            }
            request->seal = !*no_seal;
            const tools::WorldFromMapResult r = tools::RunWorldFromMap(*request);
            const core::GridGeometry& g = r.map.geometry;
            std::fprintf(stderr,
                         "wrote %s: %g x %g m from %s (%d x %d cells at %g m): %zu free cells, "
                         "%zu sealed, blocks in %zu boxes; start (%g, %g) in the map's frame, "
                         "(%g, %g) in the world's\n",
                         request->out_path.c_str(), g.width() * g.resolution(),
                         g.height() * g.resolution(), request->map_path.c_str(), g.width(),
                         g.height(), g.resolution(), r.free_cells, r.sealed_cells, r.boxes,
                         r.start_map.x(), r.start_map.y(), r.start_world.x(), r.start_world.y());
          }};
}

}  // namespace

Command AddWorldCommand(CLI::App& parent) {
  CLI::App* cmd = parent.add_subcommand(
      "world",
      "Make world files that nobody drew by hand (docs/worlds.md): `world generate` draws random "
      "ones of a kind, `world from-map` makes a building's digital twin from its ROS map.\n  "
      "example: pirouette world generate --kind rooms --seed 1 --out "
      "rooms1.yaml");
  cmd->require_subcommand(1);
  // One Add function a subcommand of `world`.
  const std::vector<Command> subcommands = {AddWorldGenerate(*cmd), AddWorldFromMap(*cmd)};
  return {cmd, [subcommands] {
            for (const Command& subcommand : subcommands) {
              if (subcommand.app->parsed()) subcommand.run();
            }
          }};
}

}  // namespace pirouette::cli
