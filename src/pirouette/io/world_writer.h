#pragma once

#include <string>

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

}  // namespace pirouette::io
