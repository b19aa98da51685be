#pragma once

#include <cstddef>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <string>
#include <vector>

#include "pirouette/mapping/trinary_map.h"
#include "pirouette/sim/world.h"

namespace pirouette::eval {

// A map judged against its world's ground truth (SPEC.md, "eval").
//
// The truth is the world rasterised on the map's own grid: a cell is truly
// occupied where its centre lies inside a solid or off the floor
// (sim::World::IsOccupied). Distances are Euclidean between cell centres.
// R, the reachable cells, is the 4-connected flood fill, from the cell of the
// robot's start, over the cells whose centre has World::Clearance greater
// than the robot's radius (its disc touches nothing there). When the start
// cell's own centre does not clear, the fill starts from those of its 8
// neighbours that do (eval::ReachableCells, which the world generator's
// validity check shares). R is taken over the whole floor on the map's grid
// (extended past the map's edges with the same cells), so a map that covers
// part of the floor covers part of R.
//
// An empty denominator gives 0: coverage is 0 when R is empty, false_free 0
// when the map has no free cells, false_occupied and wall_error_m 0 when it
// has no occupied cells.
struct MapEvaluation {
  double coverage = 0.0;        // |R ∩ map free| / |R|
  double false_free = 0.0;      // |map free ∩ truly occupied| / |map free|
  double false_occupied = 0.0;  // |map occupied farther than kFalseOccupiedCells| / |map occupied|
  double wall_error_m = 0.0;    // mean over map occupied of the distance to the truly occupied
  std::size_t free = 0;         // the map's cells in each state
  std::size_t occupied = 0;
  std::size_t unknown = 0;
  std::size_t reachable = 0;  // |R|
};

// A map's occupied cell is false when every truly occupied cell is farther
// than this many cells from it.
inline constexpr double kFalseOccupiedCells = 2.0;

// Judges `map` against `world`. Map cells off the floor are truly occupied.
// Throws std::invalid_argument when the map's cells do not match its geometry.
MapEvaluation EvaluateMap(const mapping::TrinaryMap& map, const sim::World& world);

// What the judgement says of one map cell.
enum class CellVerdict : std::uint8_t {
  kFree,           // free in the map and in truth
  kFalseFree,      // free in the map, occupied in truth (counts in false_free)
  kOccupied,       // occupied in the map, within kFalseOccupiedCells of the truth's
  kFalseOccupied,  // occupied in the map, farther (counts in false_occupied)
  kUnknown,        // unknown in the map, and not reachable floor
  kMissedFloor,    // unknown in the map but in R (what coverage misses)
};

// The judgement and, cell by cell (GridGeometry::Flat order), its verdicts.
struct JudgedMap {
  MapEvaluation evaluation;
  std::vector<CellVerdict> verdicts;
};

// EvaluateMap, keeping each cell's verdict.
JudgedMap JudgeMap(const mapping::TrinaryMap& map, const sim::World& world);

// Where a map is wrong, as a picture a person looks at (`eval --picture`),
// north up, whole pixels a cell (about target_width_px wide): free white,
// occupied black, unknown mid grey, as map.png; false free cells red, false
// occupied cells blue, reachable floor the map left unknown pale amber (the
// palette's; draw::DrawMarkedMap draws it). Throws std::invalid_argument
// when the verdicts do not match the map's geometry.
cv::Mat3b DrawJudgedMap(const mapping::TrinaryMap& map, const JudgedMap& judged,
                        int target_width_px = 800);

// The fields of SPEC.md's eval: coverage, false_free, false_occupied,
// wall_error_m, cells {free, occupied, unknown}; and reachable_cells (|R|).
nlohmann::json MapEvaluationToJson(const MapEvaluation& evaluation);

// MapEvaluationToJson's object as text, indented, ending in a newline.
std::string MapEvaluationJson(const MapEvaluation& evaluation);

}  // namespace pirouette::eval
