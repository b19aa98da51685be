#pragma once

#include <vector>

#include "pirouette/sim/room_plan.h"
#include "pirouette/sim/seeded_random.h"

namespace pirouette::sim {

struct MazePlanOptions {
  Mm width = 0;  // the floor, [0, width] × [0, height]
  Mm height = 0;
  Mm thickness = 0;     // of the walls, even
  Mm corridor_min = 0;  // each column's width and each row's height lies in this range
  Mm corridor_max = 0;  // (where the floor's size allows)
};

// A maze: the floor cut into columns and rows of cells, each column and row
// of its own width between corridor_min and corridor_max, the walls between
// cells drawn as a random spanning tree's complement (a recursive
// backtracker: one path between any two cells, every cell reachable).
struct MazePlan {
  std::vector<Mm> columns;       // widths, west to east
  std::vector<Mm> rows;          // heights, south to north
  std::vector<MmSegment> walls;  // centre lines; `thickness` thick
  std::vector<MmRect> cells;     // their floors, row by row from the south-west
};

MazePlan DrawMazePlan(SeededRandom& random, const MazePlanOptions& options);

}  // namespace pirouette::sim
