#include "pirouette/mapping/occupancy_grid.h"

#include <cstdio>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>

namespace pirouette::mapping {
namespace {

void CheckOpenUnit(double p, const char* field) {
  if (!(p > 0.0 && p < 1.0)) {
    throw std::invalid_argument(std::string("OccupancyOptions.") + field +
                                " must lie strictly between 0 and 1, got " + std::to_string(p));
  }
}

void Refuse(const char* field, const char* why, double value) {
  throw std::invalid_argument(std::string("OccupancyOptions.") + field + " " + why + ", got " +
                              std::to_string(value));
}

const OccupancyOptions& Checked(const OccupancyOptions& options) {
  options.Check();
  return options;
}

}  // namespace

void OccupancyOptions::Check() const {
  CheckOpenUnit(hit_probability, "hit_probability");
  CheckOpenUnit(miss_probability, "miss_probability");
  CheckOpenUnit(blind_probability, "blind_probability");
  CheckOpenUnit(clamp_min_probability, "clamp_min_probability");
  CheckOpenUnit(clamp_max_probability, "clamp_max_probability");
  if (!(hit_probability > 0.5)) Refuse("hit_probability", "must be above 0.5", hit_probability);
  if (!(miss_probability < 0.5)) Refuse("miss_probability", "must be below 0.5", miss_probability);
  if (!(blind_probability > 0.5)) {
    Refuse("blind_probability", "must be above 0.5", blind_probability);
  }
  if (!(clamp_min_probability < kFreeThreshold)) {
    Refuse("clamp_min_probability", "must be below the free threshold 0.196",
           clamp_min_probability);
  }
  if (!(clamp_max_probability > kOccupiedThreshold)) {
    Refuse("clamp_max_probability", "must be above the occupied threshold 0.65",
           clamp_max_probability);
  }
  if (!(std::isfinite(two_places_m) && two_places_m >= 0.0 && two_places_m < 1e3)) {
    Refuse("two_places_m", "must be finite, >= 0 and under 1 km", two_places_m);
  }
}

double ProbabilityToLogOdds(double probability) {
  return std::log(probability / (1.0 - probability));
}

double LogOddsToProbability(double log_odds) { return 1.0 / (1.0 + std::exp(-log_odds)); }

OccupancyGrid::OccupancyGrid(core::GridGeometry geometry, OccupancyOptions options)
    : geometry_(std::move(geometry)),
      options_(Checked(options)),
      hit_(static_cast<float>(ProbabilityToLogOdds(options_.hit_probability))),
      miss_(static_cast<float>(ProbabilityToLogOdds(options_.miss_probability))),
      blind_(static_cast<float>(ProbabilityToLogOdds(options_.blind_probability))),
      clamp_min_(static_cast<float>(ProbabilityToLogOdds(options_.clamp_min_probability))),
      clamp_max_(static_cast<float>(ProbabilityToLogOdds(options_.clamp_max_probability))),
      occupied_above_(static_cast<float>(ProbabilityToLogOdds(kOccupiedThreshold))),
      free_below_(static_cast<float>(ProbabilityToLogOdds(kFreeThreshold))),
      cells_(geometry_.CellCount()) {
  blind_cap_ = std::min(blind_, clamp_max_);
  one_hit_ = std::min(hit_, clamp_max_);
  const double quanta = options_.two_places_m / kPlaceQuantumM;
  baseline_quanta_squared_ = std::max(1, static_cast<int>(std::ceil(quanta * quanta)));
  FlagBlocks();
}

void OccupancyGrid::FlagBlocks() {
  const int k = kSolidBlockCells;
  solid_blocks_width_ = (geometry_.width() + k - 1) / k;
  const int blocks_height = (geometry_.height() + k - 1) / k;
  solid_blocks_.assign(
      static_cast<std::size_t>(solid_blocks_width_) * static_cast<std::size_t>(blocks_height), 0);
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    if (cells_[i].seen_from == kTwoPlaces) FlagBlockOf(i);
  }
}

std::uint32_t OccupancyGrid::EncodePlace(const Eigen::Vector2d& viewpoint) {
  const auto code = [](double metres) {
    constexpr double kLimit = 32766.0;
    const double q = std::clamp(std::round(metres / kPlaceQuantumM), -kLimit, kLimit);
    return static_cast<std::uint32_t>(static_cast<int>(q) + 32768);
  };
  return (code(viewpoint.x()) << 16U) | code(viewpoint.y());
}

double OccupancyGrid::Probability(const core::CellIndex& c) const {
  return LogOddsToProbability(LogOdds(c));
}

TrinaryMap OccupancyGrid::ToTrinary() const {
  TrinaryMap map{geometry_, std::vector<CellState>(cells_.size())};
  for (std::size_t i = 0; i < cells_.size(); ++i) map.cells[i] = StateOf(cells_[i]);
  return map;
}

bool OccupancyGrid::WouldCorroborate(const core::CellIndex& c,
                                     const Eigen::Vector2d& viewpoint) const {
  if (options_.two_places_m <= 0.0 || !viewpoint.allFinite() || !geometry_.Contains(c)) {
    return false;
  }
  const Cell& cell = cells_[geometry_.Flat(c)];
  return StateOf(cell) == CellState::kFree && cell.free_from != kNoPlace &&
         cell.free_from != kTwoPlaces && FarApart(cell.free_from, EncodePlace(viewpoint));
}

TrinaryMap OccupancyGrid::ToMapOfRecord() const {
  const bool two_places = options_.two_places_m > 0.0;
  TrinaryMap map{geometry_, std::vector<CellState>(cells_.size())};
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const CellState state = StateOf(cells_[i]);
    const bool one_place = two_places && cells_[i].free_from != kTwoPlaces;
    map.cells[i] = state == CellState::kFree && one_place ? CellState::kUnknown : state;
  }
  return map;
}

TrinaryMap OccupancyGrid::ToExploredMap() const {
  TrinaryMap map{geometry_, std::vector<CellState>(cells_.size())};
  for (std::size_t i = 0; i < cells_.size(); ++i) {
    const Cell& cell = cells_[i];
    CellState state = StateOf(cell);
    if (state == CellState::kUnknown && cell.stamp != 0) {
      state = cell.log_odds > 0.0F ? CellState::kOccupied : CellState::kFree;
    }
    map.cells[i] = state;
  }
  return map;
}

void OccupancyGrid::BeginFrame(const Eigen::Vector2d& viewpoint) {
  BeginFrame();
  if (options_.two_places_m > 0.0 && viewpoint.allFinite()) viewpoint_ = EncodePlace(viewpoint);
}

void OccupancyGrid::BeginFrame() {
  viewpoint_ = kNoPlace;
  if (++frame_ == 0) {
    // After 2^32 frames the stamps wrap: keep "touched" (1) and start again.
    for (Cell& cell : cells_) cell.stamp = cell.stamp == 0 ? 0 : 1;
    frame_ = 2;
  }
}

void OccupancyGrid::SetFree(const core::CellIndex& c) {
  if (!geometry_.Contains(c)) return;
  Cell& cell = cells_[geometry_.Flat(c)];
  cell.log_odds = clamp_min_;
  cell.stamp = frame_;
  cell.free_from = kTwoPlaces;
}

void OccupancyGrid::SetSolid(const core::CellIndex& c) {
  if (!geometry_.Contains(c)) return;
  const std::size_t flat = geometry_.Flat(c);
  Cell& cell = cells_[flat];
  cell.log_odds = clamp_max_;
  cell.stamp = frame_;
  cell.seen_from = kTwoPlaces;
  FlagBlockOf(flat);
}

void OccupancyGrid::LimitSide(int max_side_cells) {
  if (max_side_cells < 1 || max_side_cells > kMaxSideCells) {
    throw std::invalid_argument("OccupancyGrid::LimitSide: needs 1..kMaxSideCells cells");
  }
  max_side_cells_ = max_side_cells;
}

void OccupancyGrid::GrowToCover(const Eigen::Vector2d& lo, const Eigen::Vector2d& hi) {
  if (!lo.allFinite() || !hi.allFinite() || !(lo.array() <= hi.array()).all()) {
    throw std::invalid_argument("OccupancyGrid::GrowToCover: needs finite lo <= hi");
  }
  const double resolution = geometry_.resolution();
  const Eigen::Vector2d cells_lo = (lo - geometry_.origin()) / resolution;
  const Eigen::Vector2d cells_hi = (hi - geometry_.origin()) / resolution;
  const double limit = 4.0 * kMaxSideCells;  // keeps the casts below defined
  if ((cells_lo.array().abs() > limit).any() || (cells_hi.array().abs() > limit).any()) {
    throw MapTooLarge("the map would grow thousands of kilometres");
  }
  // The cells the rectangle plus the margin spans, in the current indices.
  const int x0 = static_cast<int>(std::floor(cells_lo.x())) - kGrowMarginCells;
  const int y0 = static_cast<int>(std::floor(cells_lo.y())) - kGrowMarginCells;
  const int x1 = static_cast<int>(std::floor(cells_hi.x())) + kGrowMarginCells;
  const int y1 = static_cast<int>(std::floor(cells_hi.y())) + kGrowMarginCells;
  const int width = geometry_.width();
  const int height = geometry_.height();
  if (x0 >= 0 && y0 >= 0 && x1 < width && y1 < height) return;

  const int chunk = static_cast<int>(std::ceil(kGrowChunkM / resolution));
  const auto grow = [](int lacking, int chunk_cells) {
    return lacking > 0 ? lacking + chunk_cells : 0;
  };
  int left = grow(-x0, std::max(chunk, width));
  int right = grow(x1 - (width - 1), std::max(chunk, width));
  int bottom = grow(-y0, std::max(chunk, height));
  int top = grow(y1 - (height - 1), std::max(chunk, height));
  // Near the limit, grow by what is lacking only.
  if (static_cast<long>(width) + left + right > max_side_cells_) {
    left = grow(-x0, 0);
    right = grow(x1 - (width - 1), 0);
  }
  if (static_cast<long>(height) + bottom + top > max_side_cells_) {
    bottom = grow(-y0, 0);
    top = grow(y1 - (height - 1), 0);
  }
  const long new_width = static_cast<long>(width) + left + right;
  const long new_height = static_cast<long>(height) + bottom + top;
  if (new_width > max_side_cells_ || new_height > max_side_cells_) {
    char what[160];
    std::snprintf(what, sizeof what,
                  "the map would grow to %.0f x %.0f m, past its limit of %.0f m a side",
                  static_cast<double>(new_width) * resolution,
                  static_cast<double>(new_height) * resolution, max_side_cells_ * resolution);
    throw MapTooLarge(what);
  }

  const core::GridGeometry grown(resolution,
                                 geometry_.origin() - Eigen::Vector2d(left, bottom) * resolution,
                                 static_cast<int>(new_width), static_cast<int>(new_height));
  std::vector<Cell> cells(grown.CellCount());
  for (int y = 0; y < height; ++y) {
    const auto from = cells_.begin() + static_cast<std::ptrdiff_t>(geometry_.Flat({0, y}));
    std::copy(from, from + width,
              cells.begin() + static_cast<std::ptrdiff_t>(grown.Flat({left, y + bottom})));
  }
  geometry_ = grown;
  cells_ = std::move(cells);
  FlagBlocks();  // the origin moved by whole cells, not whole blocks
}

OccupancyGrid OccupancyGrid::CroppedToKnown(int margin_cells) const {
  int x0 = geometry_.width();
  int y0 = geometry_.height();
  int x1 = -1;
  int y1 = -1;
  for (int y = 0; y < geometry_.height(); ++y) {
    for (int x = 0; x < geometry_.width(); ++x) {
      if (cells_[geometry_.Flat({x, y})].stamp == 0) continue;
      x0 = std::min(x0, x);
      y0 = std::min(y0, y);
      x1 = std::max(x1, x);
      y1 = std::max(y1, y);
    }
  }
  if (x1 < 0) return *this;
  x0 = std::max(0, x0 - margin_cells);
  y0 = std::max(0, y0 - margin_cells);
  x1 = std::min(geometry_.width() - 1, x1 + margin_cells);
  y1 = std::min(geometry_.height() - 1, y1 + margin_cells);
  const double r = geometry_.resolution();
  OccupancyGrid cropped(core::GridGeometry(r, geometry_.origin() + Eigen::Vector2d(x0 * r, y0 * r),
                                           x1 - x0 + 1, y1 - y0 + 1),
                        options_);
  cropped.frame_ = frame_;
  for (int y = y0; y <= y1; ++y) {
    for (int x = x0; x <= x1; ++x) {
      cropped.cells_[cropped.geometry_.Flat({x - x0, y - y0})] = cells_[geometry_.Flat({x, y})];
    }
  }
  cropped.FlagBlocks();
  return cropped;
}

void OccupancyGrid::Restore(const OccupancyGrid& part) {
  const double r = geometry_.resolution();
  const Eigen::Vector2d offset = (part.geometry_.origin() - geometry_.origin()) / r;
  const int x0 = static_cast<int>(std::lround(offset.x()));
  const int y0 = static_cast<int>(std::lround(offset.y()));
  if (part.geometry_.resolution() != r || std::abs(offset.x() - x0) > 1e-6 ||
      std::abs(offset.y() - y0) > 1e-6 || x0 < 0 || y0 < 0 ||
      x0 + part.geometry_.width() > geometry_.width() ||
      y0 + part.geometry_.height() > geometry_.height()) {
    throw std::invalid_argument(
        "OccupancyGrid::Restore: the part must lie within the grid, at whole cells");
  }
  std::fill(cells_.begin(), cells_.end(), Cell{});
  for (int y = 0; y < part.geometry_.height(); ++y) {
    const auto row = part.cells_.begin() + static_cast<std::ptrdiff_t>(part.geometry_.Flat({0, y}));
    std::copy(row, row + part.geometry_.width(),
              cells_.begin() + static_cast<std::ptrdiff_t>(geometry_.Flat({x0, y0 + y})));
  }
  frame_ = part.frame_;
  FlagBlocks();
}

}  // namespace pirouette::mapping
