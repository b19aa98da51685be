#pragma once

#include <Eigen/Core>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <string>

#include "pirouette/sim/world.h"
#include "pirouette/sim/world_generator.h"
#include "pirouette/sim/world_spec.h"

namespace pirouette::tools {

// What `pirouette world generate` was asked.
struct WorldGenerateRequest {
  sim::WorldKind kind = sim::WorldKind::kRooms;
  std::uint64_t seed = 1;
  std::optional<Eigen::Vector2d> size;  // metres; none: drawn for the kind
  std::string out_path;
};

// The draws a seed gets before generation gives up.
inline constexpr int kMaxWorldDraws = 50;

// Whether a world is valid (SPEC.md, "Worlds nobody drew by hand"), by the
// evaluator's own reachability (eval::ReachableCells) on the cells the
// explorer maps it with (mapping::DefaultCellSize of the robot's radius, on
// the world's lattice): the robot's disc fits at its start, and every cell
// where it fits is reachable from there.
struct WorldValidity {
  bool start_fits = false;
  std::size_t reachable_cells = 0;
  std::size_t unreachable_cells = 0;  // cells the disc fits in that R does not hold
  double cell_m = 0.0;

  bool valid() const { return start_fits && unreachable_cells == 0 && reachable_cells > 0; }
};
WorldValidity CheckWorld(const sim::World& world);

struct GeneratedWorld {
  sim::WorldSpec spec;  // named `KIND-SEED`, its comment saying how it was made
  std::string text;     // the world file
  int draw = 0;         // which draw it is, 0-based
  WorldValidity validity;
};

// Draw `draw` (0-based) of the world of `kind` and `seed`, valid or not (its
// validity left unchecked): sim::GenerateWorld from the seed
// sim::SplitMix64(sim::SplitMix64(seed) + draw), named and commented.
GeneratedWorld DrawWorld(sim::WorldKind kind, std::uint64_t seed,
                         const std::optional<Eigen::Vector2d>& size, int draw);

// The world of `kind` and `seed`: the first valid one of its draws 0 to
// kMaxWorldDraws - 1 (DrawWorld), so the same request gives the same file. Throws core::InputError
// (exit 2) naming --size for a size outside the kind's limits, std::runtime_error (exit 1) when no
// draw is valid.
GeneratedWorld GenerateValidWorld(sim::WorldKind kind, std::uint64_t seed,
                                  const std::optional<Eigen::Vector2d>& size = std::nullopt);

// `pirouette world generate`: GenerateValidWorld, written atomically to
// request.out_path. Throws as GenerateValidWorld does, and std::runtime_error
// when the file cannot be written.
GeneratedWorld RunWorldGenerate(const WorldGenerateRequest& request);

}  // namespace pirouette::tools
