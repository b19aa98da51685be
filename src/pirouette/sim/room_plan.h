#pragma once

#include <cstdint>
#include <vector>

#include "pirouette/sim/seeded_random.h"

namespace pirouette::sim {

// Layouts are drawn on whole millimetres: exact, so the same everywhere.
using Mm = std::int64_t;

// [x0, x1] × [y0, y1], millimetres.
struct MmRect {
  Mm x0 = 0;
  Mm y0 = 0;
  Mm x1 = 0;
  Mm y1 = 0;
};

// A wall's centre line from (x0, y0) to (x1, y1), millimetres, axis-aligned.
struct MmSegment {
  Mm x0 = 0;
  Mm y0 = 0;
  Mm x1 = 0;
  Mm y1 = 0;
};

struct RoomPlanOptions {
  Mm width = 0;  // the floor, [0, width] × [0, height]
  Mm height = 0;
  Mm thickness = 0;  // of the inner walls, even
  Mm min_room = 0;   // the shortest side a room may have
  int rooms = 1;     // how many rooms to split the floor into, at most
  // Doors: most `door_min`..`door_max` wide, `wide_door_chance` of them up to `wide_door_max`.
  Mm door_min = 0;
  Mm door_max = 0;
  Mm wide_door_max = 0;
  double wide_door_chance = 0.0;
  Mm door_margin = 0;  // a door keeps this far from its wall's ends
  Mm jamb = 0;         // a wall drawn later ends at least this far from a door
  Mm approach = 0;     // the floor kept clear each side of a door
};

// A floor split into rooms by walls with one door each (binary space
// partition: a room is split by a wall across it, and the halves split in
// turn), so that every room is joined to every other. A wall ends on the
// centre line of the wall it meets (or on the floor's edge) and never in a
// door.
struct RoomPlan {
  std::vector<MmRect> rooms;     // their floors, between the walls' faces
  std::vector<MmSegment> walls;  // centre lines; `thickness` thick
  std::vector<MmRect> doorways;  // each door's opening and `approach` of floor each side
  std::vector<Mm> door_widths;
};

RoomPlan DrawRoomPlan(SeededRandom& random, const RoomPlanOptions& options);

}  // namespace pirouette::sim
