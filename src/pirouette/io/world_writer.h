#pragma once

#include <string>
#include <vector>

#include "pirouette/sim/world_spec.h"

namespace pirouette::io {

// The text of a world file (SPEC.md, `pirouette-world/1`) that LoadWorldFile
// reads back to the world sim::BuildWorld(spec) builds, from any folder: the
// camera's fields are written inline (ParseCameraNode reads them), numbers as
// the shortest decimals that read back the same doubles. The spec's comment
// heads the file as comment lines; obstacles follow in order, one a line.
// Throws std::invalid_argument for a number that is not finite. Writing it to
// disk (atomically) is the caller's.
std::string WorldFileText(const sim::WorldSpec& spec);

// A `grid` obstacle as its line gives it (SPEC.md): the map_server map
// (relative to the world file, or absolute), the blocks' height and colour,
// and whether gaps narrower than the robot are sealed (sim::SealUnreachable).
struct GridFileSpec {
  std::string map;
  double height = 0.0;
  core::Rgb colour;
  bool seal = false;
};

// WorldFileText with `grids` first among the obstacles.
std::string WorldFileText(const sim::WorldSpec& spec, const std::vector<GridFileSpec>& grids);

}  // namespace pirouette::io
