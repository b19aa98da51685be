#pragma once

#include <string>

#include "pirouette/io/map_file.h"
#include "pirouette/sim/block_grid.h"
#include "pirouette/sim/world.h"

namespace pirouette::io {

// Reads a world file (SPEC.md, `pirouette-world/1`). The robot's camera is a
// camera file relative to the world file, or its fields inline. Throws
// core::InputError naming the file, the line and the field for unknown keys,
// missing required keys, wrong types, negative sizes, colours outside 0..255,
// and a start pose that overlaps an obstacle or leaves the floor.
sim::World LoadWorldFile(const std::string& path);

// The world in `text`, read exactly as LoadWorldFile reads a file of these
// bytes at `path`: `path` names it in messages and is the folder relative
// camera and map paths start from. For a world made in memory (a generated
// one's WorldFileText) that must be the world its file would be.
sim::World ParseWorldText(const std::string& text, const std::string& path);

// A `grid` obstacle's blocks (SPEC.md): the map's cells, its lower-left
// corner at the world's (0, 0); a block wherever map_server does not serve
// the cell as free (0): occupied, unknown and, in scale and raw modes, the
// values between.
sim::BlockGrid BlocksOfMap(const MapServerMap& map);

}  // namespace pirouette::io
