#pragma once

#include <string>

#include "pirouette/sim/world.h"

namespace pirouette::io {

// Reads a world file (SPEC.md, `pirouette-world/1`). The robot's camera is a
// camera file relative to the world file, or its fields inline. Throws
// core::InputError naming the file, the line and the field for unknown keys,
// missing required keys, wrong types, negative sizes, colours outside 0..255,
// and a start pose that overlaps an obstacle or leaves the floor.
sim::World LoadWorldFile(const std::string& path);

}  // namespace pirouette::io
