#include <cstdio>
#include <memory>
#include <string>
#include <vector>

#include <fmt/format.h>

#include "apps/pirouette/command.h"
#include "apps/pirouette/options.h"
#include "apps/pirouette/parse.h"
#include "pirouette/core/input_error.h"
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

}  // namespace

Command AddWorldCommand(CLI::App& parent) {
  CLI::App* cmd = parent.add_subcommand(
      "world",
      "Make world files that nobody drew by hand (docs/worlds.md): `world generate` draws random "
      "ones of a kind.\n  example: pirouette world generate --kind rooms --seed 1 --out "
      "rooms1.yaml");
  cmd->require_subcommand(1);
  // One Add function a subcommand of `world`; `world from-map` joins this list.
  const std::vector<Command> subcommands = {AddWorldGenerate(*cmd)};
  return {cmd, [subcommands] {
            for (const Command& subcommand : subcommands) {
              if (subcommand.app->parsed()) subcommand.run();
            }
          }};
}

}  // namespace pirouette::cli
