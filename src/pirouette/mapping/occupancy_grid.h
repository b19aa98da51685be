#pragma once

#include <Eigen/Core>
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::mapping {

// The Bayes update of one cell, in probabilities; the grid turns them into
// log-odds once, when it is built (OctoMap's sensor model). The defaults are
// OctoMap's. A plain struct: Check() before use.
struct OccupancyOptions {
  double hit_probability = 0.7;   // P(occupied | hit) for the cell at a reading's range
  double miss_probability = 0.4;  // P(occupied | miss) for the cells a reading sees through
  // The value of a blind area (ObstacleProfile's kBlind: an obstacle's base
  // is somewhere in it, unseen): a cell no reading ever touched becomes
  // exactly blind_probability; a cell that any reading touched before is left
  // alone (a blind view neither confirms nor refutes what was seen: the base
  // may lie anywhere in the area, and what was seen free there still is).
  // 0.6 lies half-way between unknown (0.5) and what a hit says (0.7), and
  // below kOccupiedThreshold: a blind area alone is known (the explorer does
  // not chase it), not free (the planner does not drive into it), and not
  // occupied (the map does not draw walls that were never seen).
  double blind_probability = 0.6;
  double clamp_min_probability = 0.12;  // log-odds never go below this one's (OctoMap)
  double clamp_max_probability = 0.97;  // nor above this one's
  // Two places: viewpoints at least this far apart (metres). A cell is
  // solid (OccupancyGrid::Solid) once it sits at the clamp above and hits
  // reached it from two places; the map of record (ToMapOfRecord) calls a
  // cell free only once misses reached it from two places. 0 turns both rules
  // off (the paper's plain Bayes grid). What one place sees can be wrong in a
  // way that repeats from there but not from elsewhere: a phantom hit (a
  // vertical edge cutting a column of a tilted camera's picture, a wall a few
  // centimetres off taken for the floor) lands elsewhere from another place,
  // and a wall that passes for the floor when seen close maps a fan of free
  // cells beyond it that no other place sees; a wall's face is hit, and open
  // floor seen free, wherever it is seen from. Two stops of a robot of the
  // paper's size are about this far apart at the least.
  double two_places_m = 0.15;

  // Throws std::invalid_argument naming the field unless every probability is
  // in (0, 1), miss < 0.5 < hit, blind > 0.5, clamp_min < kFreeThreshold and
  // clamp_max > kOccupiedThreshold (else no cell could ever read free or
  // occupied), and two_places_m is finite, >= 0 and under 1 km.
  void Check() const;
};

// Thresholds of the trinary map, matching map.yaml (SPEC.md): a cell is
// occupied when its probability is above kOccupiedThreshold, free below
// kFreeThreshold, unknown otherwise.
inline constexpr double kOccupiedThreshold = 0.65;
inline constexpr double kFreeThreshold = 0.196;

// The map's cell by default (metres): 1 cm for a robot as small as the
// paper's (radius under kSmallRobotRadiusM), where a cell is a tenth of the
// robot's width; 2 cm for a larger one, where 1 cm cells would quadruple the
// grid's cells (and the planner's and the update's work) for detail its
// camera cannot resolve at range (camera::MaxRange grows with the cell).
inline constexpr double kSmallRobotCellM = 0.01;
inline constexpr double kLargeRobotCellM = 0.02;
inline constexpr double kSmallRobotRadiusM = 0.1;
// The cells a map may have: finer than 2 mm no camera here resolves, coarser
// than half a metre no robot here fits through a door on.
inline constexpr double kMinCellM = 0.002;
inline constexpr double kMaxCellM = 0.5;
inline double DefaultCellSize(double robot_radius_m) {
  return robot_radius_m < kSmallRobotRadiusM ? kSmallRobotCellM : kLargeRobotCellM;
}

// log(p / (1 - p)) and its inverse.
double ProbabilityToLogOdds(double probability);
double LogOddsToProbability(double log_odds);

// What one reading says about one cell.
enum class CellUpdate : std::uint8_t {
  kHit,    // L ← min(L + logit(hit), clamp max)
  kMiss,   // L ← max(L + logit(miss), clamp min)
  kBlind,  // L ← min(logit(blind), clamp max) if the cell was never touched, see OccupancyOptions
};

// A map that would grow past the side it is allowed (OccupancyGrid::LimitSide,
// a run's --max-map-m): what a robot whose odometry jumped a kilometre would
// make, refused before it takes the machine's memory.
class MapTooLarge : public std::length_error {
 public:
  explicit MapTooLarge(const std::string& what) : std::length_error(what) {}
};

// An occupancy grid in clamped log-odds (OctoMap): per cell L = log(p/(1-p)),
// 0 = unknown (p = 0.5), and a mark of whether any reading ever touched it
// (never NaN as a marker). Updates come in frames: between two BeginFrame()
// calls each cell changes at most once, so the first update a cell gets in a
// frame is the one that counts; the sensor model applies hits before the rest
// so that a hit wins (Cartographer). The per-frame mark is a frame stamp per
// cell, so starting a frame costs nothing.
class OccupancyGrid {
 public:
  // Throws std::invalid_argument when options fail Check().
  explicit OccupancyGrid(core::GridGeometry geometry, OccupancyOptions options = {});

  const core::GridGeometry& geometry() const { return geometry_; }
  const OccupancyOptions& options() const { return options_; }

  // The probability of occupancy; 0.5 off the grid.
  double Probability(const core::CellIndex& c) const;
  // The log-odds of occupancy; 0 off the grid.
  float LogOdds(const core::CellIndex& c) const {
    return geometry_.Contains(c) ? cells_[geometry_.Flat(c)].log_odds : 0.0F;
  }
  // kOccupied above kOccupiedThreshold, kFree below kFreeThreshold, else
  // kUnknown; kUnknown off the grid and for cells never touched.
  CellState State(const core::CellIndex& c) const {
    return geometry_.Contains(c) ? StateAt(geometry_.Flat(c)) : CellState::kUnknown;
  }
  // The same for the row-major index `flat` < geometry().CellCount(), unchecked.
  CellState StateAt(std::size_t flat) const { return StateOf(cells_[flat]); }
  // Whether any update ever touched the cell (false off the grid).
  bool Known(const core::CellIndex& c) const {
    return geometry_.Contains(c) && cells_[geometry_.Flat(c)].stamp != 0;
  }
  // Whether the cell's only evidence is a blind area (CellUpdate::kBlind): it
  // was touched, and no hit or miss has changed it since (false off the grid).
  bool BlindOnly(const core::CellIndex& c) const {
    if (!geometry_.Contains(c)) return false;
    const Cell& cell = cells_[geometry_.Flat(c)];
    return cell.stamp != 0 && cell.log_odds == blind_cap_;
  }
  // Whether the cell leans occupied (log-odds above 0) on the evidence of at
  // most one look: a blind area only, or no more than one hit (a hit on a
  // cell nothing else touched, or one that misses have already pulled down).
  // What one frame says can be wrong where a second look would not be (a
  // vertical edge cutting a column of a tilted camera's picture, a wall a few
  // centimetres off filling the view), so an explorer may look again before
  // it takes such a cell to close the map. False off the grid.
  bool OnOneLook(const core::CellIndex& c) const {
    if (!geometry_.Contains(c)) return false;
    const Cell& cell = cells_[geometry_.Flat(c)];
    return cell.stamp != 0 && cell.log_odds > 0.0F &&
           (cell.log_odds == blind_cap_ || cell.log_odds <= one_hit_);
  }
  // Whether the cell is a wall seen for sure: at the log-odds clamp above
  // and hit from two viewpoints at least OccupancyOptions::two_places_m
  // apart (BeginFrame(viewpoint)). The sensor model does not see through a
  // solid cell (InsertProfile). False off the grid and with solidity off.
  bool Solid(const core::CellIndex& c) const {
    return geometry_.Contains(c) && SolidAt(geometry_.Flat(c));
  }
  // The same for the row-major index `flat` < geometry().CellCount(), unchecked.
  bool SolidAt(std::size_t flat) const {
    const Cell& cell = cells_[flat];
    return cell.seen_from == kTwoPlaces && cell.log_odds >= clamp_max_;
  }
  // Blocks of kSolidBlockCells × kSolidBlockCells cells, block (bx, by)
  // holding cells [k·bx, k·bx + k) × [k·by, k·by + k): a block that holds a
  // solid cell is flagged (a flagged one may hold none: a cell hit from two
  // places that misses have pulled off the clamp). A ray can skip the blocks
  // not flagged without looking at their cells.
  static constexpr int kSolidBlockCells = 4;
  int solid_blocks_width() const { return solid_blocks_width_; }
  // Whether row-major block `flat_block` may hold a solid cell (unchecked).
  bool SolidBlockAt(std::size_t flat_block) const { return solid_blocks_[flat_block] != 0; }
  // The whole grid by State(), on the same geometry.
  TrinaryMap ToTrinary() const;
  // The map a run writes out and publishes (map.pgm, /map, the live view,
  // its evaluation): ToTrinary(), except that a free cell not yet seen free
  // from two places (OccupancyOptions::two_places_m; FreeFromTwoPlaces) is
  // unknown. The explorer plans on what one place saw (it must move through
  // the floor it just saw); the record claims only floor seen free twice.
  TrinaryMap ToMapOfRecord() const;
  // Whether misses reached the cell from two places, or it was set free
  // (SetFree); true for every cell with the rule off (two_places_m 0).
  bool FreeFromTwoPlaces(const core::CellIndex& c) const {
    return options_.two_places_m <= 0.0 ||
           (geometry_.Contains(c) && cells_[geometry_.Flat(c)].free_from == kTwoPlaces);
  }
  // Whether the cell is free (State) but seen free from one place only, and
  // a miss from `viewpoint` (world metres) would make it free from two places.
  bool WouldCorroborate(const core::CellIndex& c, const Eigen::Vector2d& viewpoint) const;
  // The grid as an explorer reads it: unknown is only what no update ever
  // touched. A touched cell between the thresholds (a hit and a miss that
  // cancel, or a blind area) counts as occupied when its log-odds are above
  // 0, else free: another look would not settle it.
  TrinaryMap ToExploredMap() const;
  // A copy holding only the bounding box of the cells any update touched,
  // plus `margin_cells` all round (the same cells at the same world
  // positions): the map to write out. A grid nothing touched stays whole.
  OccupancyGrid CroppedToKnown(int margin_cells) const;
  // Makes this grid what it was when `part` was cropped from it
  // (CroppedToKnown): the part's cells at their world positions, every other
  // cell untouched, the part's frame count; the geometry stays this grid's,
  // which must hold the part at whole-cell offsets with the same resolution
  // (as a grid only grows: std::invalid_argument otherwise). A run keeps
  // such parts of its map, a fraction of the grid, to make it again from.
  void Restore(const OccupancyGrid& part);
  // How many cells any update ever touched.
  std::size_t KnownCellCount() const {
    return static_cast<std::size_t>(
        std::count_if(cells_.begin(), cells_.end(), [](const Cell& c) { return c.stamp != 0; }));
  }

  // Grows the grid so that it covers the world rectangle [lo, hi] plus a
  // margin of kGrowMarginCells cells on every side, keeping every cell's value
  // and world position (the origin moves by whole cells); a no-op when it
  // already does. A side that falls short grows by what it lacks plus
  // max(1 m, the grid's size along that axis), so that growth is rare and
  // amortised, but never past the side limit (LimitSide). Throws
  // std::invalid_argument unless lo <= hi and both are finite, MapTooLarge
  // (a std::length_error) when a side would pass the limit.
  void GrowToCover(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi);
  static constexpr int kGrowMarginCells = 2;
  static constexpr double kGrowChunkM = 1.0;
  static constexpr int kMaxSideCells = 1 << 15;
  // The most cells a side may grow to: 1..kMaxSideCells (the default); copies keep it.
  void LimitSide(int max_side_cells);
  int max_side_cells() const { return max_side_cells_; }

  // Starts a new frame: from now on each cell takes at most one update until
  // the next call. Its hits count toward solidity (Solid), and its misses
  // toward the map of record's free (FreeFromTwoPlaces), with the viewpoint
  // they were seen from (world metres); those of a frame begun without one
  // (a confirmation, a test) do not.
  void BeginFrame();
  void BeginFrame(const Eigen::Vector2d& viewpoint);
  // The number of frames begun so far.
  std::uint32_t frame() const { return frame_; }

  // Applies `update` to cell `c` unless it is off the grid or already changed
  // in this frame; returns whether it was applied.
  bool Apply(const core::CellIndex& c, CellUpdate update) {
    return geometry_.Contains(c) && ApplyAt(geometry_.Flat(c), update);
  }
  // The same for the row-major index `flat` < geometry().CellCount(),
  // unchecked: the sensor model's inner loop.
  bool ApplyAt(std::size_t flat, CellUpdate update) {
    Cell& cell = cells_[flat];
    if (cell.stamp == frame_) return false;
    const bool touched = cell.stamp != 0;
    cell.stamp = frame_;
    switch (update) {
      case CellUpdate::kHit:
        cell.log_odds = std::min(cell.log_odds + hit_, clamp_max_);
        if (viewpoint_ != kNoPlace && cell.seen_from != kTwoPlaces) {
          if (cell.seen_from == kNoPlace) {
            cell.seen_from = viewpoint_;
          } else if (FarApart(cell.seen_from, viewpoint_)) {
            cell.seen_from = kTwoPlaces;
            FlagBlockOf(flat);
          }
        }
        break;
      case CellUpdate::kMiss:
        cell.log_odds = std::max(cell.log_odds + miss_, clamp_min_);
        if (viewpoint_ != kNoPlace && cell.free_from != kTwoPlaces) {
          if (cell.free_from == kNoPlace) {
            cell.free_from = viewpoint_;
          } else if (FarApart(cell.free_from, viewpoint_)) {
            cell.free_from = kTwoPlaces;
          }
        }
        break;
      case CellUpdate::kBlind:
        // Only a cell no reading ever touched takes it (stamp was 0).
        if (!touched) cell.log_odds = blind_cap_;
        break;
    }
    return true;
  }

  // Sets cell `c` (if on the grid) to the free clamp, known, whatever it held
  // and whether or not it changed in this frame: for floor known to be free
  // for certain, such as under the robot's footprint.
  void SetFree(const core::CellIndex& c);
  // Sets cell `c` (if on the grid) to the occupied clamp, hit from two
  // places (Solid), whatever it held: for an obstacle known for certain, such
  // as one the robot has touched.
  void SetSolid(const core::CellIndex& c);

 private:
  struct Cell {
    float log_odds = 0.0F;
    std::uint32_t stamp = 0;  // the frame of the last update; 0: never touched
    // Where the first hit was seen from (a viewpoint code, see EncodePlace),
    // kNoPlace before any, kTwoPlaces once a hit came from far enough away.
    std::uint32_t seen_from = kNoPlace;
    // The same for misses (kTwoPlaces also for a cell set free).
    std::uint32_t free_from = kNoPlace;
  };
  // A viewpoint rounded to kPlaceQuantumM on each axis, 16 bits each
  // (clamped to ±32,766 quanta: ±1.6 km), never either marker.
  static constexpr std::uint32_t kNoPlace = 0;
  static constexpr std::uint32_t kTwoPlaces = 0xFFFFFFFFU;
  static constexpr double kPlaceQuantumM = 0.05;
  static std::uint32_t EncodePlace(const Eigen::Vector2d& viewpoint);
  void FlagBlockOf(std::size_t flat) {
    const auto width = static_cast<std::size_t>(geometry_.width());
    const auto k = static_cast<std::size_t>(kSolidBlockCells);
    solid_blocks_[(flat / width / k) * static_cast<std::size_t>(solid_blocks_width_) +
                  (flat % width) / k] = 1;
  }
  // Sizes the blocks to the geometry and flags them from the cells.
  void FlagBlocks();
  bool FarApart(std::uint32_t a, std::uint32_t b) const {
    const int dx = static_cast<int>(a >> 16U) - static_cast<int>(b >> 16U);
    const int dy = static_cast<int>(a & 0xFFFFU) - static_cast<int>(b & 0xFFFFU);
    return dx * dx + dy * dy >= baseline_quanta_squared_;
  }

  CellState StateOf(const Cell& cell) const {
    if (cell.stamp == 0) return CellState::kUnknown;
    if (cell.log_odds > occupied_above_) return CellState::kOccupied;
    if (cell.log_odds < free_below_) return CellState::kFree;
    return CellState::kUnknown;
  }

  core::GridGeometry geometry_;
  int max_side_cells_ = kMaxSideCells;
  OccupancyOptions options_;
  // The sensor model in log-odds, built once from the checked options.
  float hit_;
  float miss_;
  float blind_;
  float blind_cap_;  // min(logit(blind), clamp max)
  float one_hit_;    // min(logit(hit), clamp max): one hit on an untouched cell
  float clamp_min_;
  float clamp_max_;
  float occupied_above_;                // logit(kOccupiedThreshold)
  float free_below_;                    // logit(kFreeThreshold)
  int baseline_quanta_squared_;         // two_places_m² in kPlaceQuantumM², at least 1
  std::uint32_t viewpoint_ = kNoPlace;  // the frame's, or kNoPlace
  std::uint32_t frame_ = 1;
  std::vector<Cell> cells_;  // row-major, geometry_.CellCount()
  int solid_blocks_width_ = 0;
  std::vector<std::uint8_t> solid_blocks_;  // row-major, 1: flagged
};

}  // namespace pirouette::mapping
