#include "pirouette/explore/distance_transform.h"

#include <algorithm>
#include <array>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <utility>

namespace pirouette::explore {
namespace {

using Distance = std::int32_t;

// The maximal runs of unblocked cells of each row, as padded column ranges
// [begin, end); the raster sweeps visit only these, so that a blocked cell
// (which holds kUnreachable) is never written and costs no branch.
struct Run {
  int begin;
  int end;
};

struct RowRuns {
  std::vector<Run> runs;           // all rows' runs, row after row
  std::vector<std::size_t> first;  // the first run of padded row r is runs[first[r]]
};

// Writes every cell of the padded field (kUnreachable, goals 0) and lists
// the runs.
template <typename Vector>
RowRuns Initialise(const CoarseGrid& grid, Vector& padded, std::size_t stride) {
  const int w = grid.width();
  const int h = grid.height();
  std::fill_n(padded.data(), stride, kUnreachable);
  std::fill_n(padded.data() + (static_cast<std::size_t>(h) + 1) * stride, stride, kUnreachable);
  RowRuns rows;
  rows.first.assign(static_cast<std::size_t>(h) + 3, 0);
  const CoarseCell* labels = grid.cells().data();
  for (int y = 0; y < h; ++y) {
    const std::size_t r = static_cast<std::size_t>(y) + 1;
    rows.first[r] = rows.runs.size();
    const CoarseCell* row = labels + static_cast<std::size_t>(y) * w;
    Distance* out = padded.data() + r * stride;
    out[0] = kUnreachable;
    out[w + 1] = kUnreachable;
    for (int x = 0; x < w; ++x) out[x + 1] = row[x] == CoarseCell::kGoal ? 0 : kUnreachable;
    int x = 0;
    while (x < w) {
      while (x < w && row[x] == CoarseCell::kBlocked) ++x;
      if (x == w) break;
      const int begin = x;
      while (x < w && row[x] != CoarseCell::kBlocked) ++x;
      rows.runs.push_back({begin + 1, x + 1});
    }
  }
  rows.first[static_cast<std::size_t>(h) + 1] = rows.runs.size();
  rows.first[static_cast<std::size_t>(h) + 2] = rows.runs.size();
  return rows;
}

// The columns [lo, hi] of a row; empty when lo > hi.
struct Span {
  int lo = 1;
  int hi = 0;

  bool Empty() const { return lo > hi; }
  void Add(const Span& s) {
    if (s.Empty()) return;
    if (Empty()) {
      *this = s;
    } else {
      lo = std::min(lo, s.lo);
      hi = std::max(hi, s.hi);
    }
  }
};

// Runs shorter than this are scanned in one chain.
constexpr int kShortRun = 64;
// Longer ones in this many interleaved chains.
constexpr int kChains = 4;

// The horizontal half of a row sweep on [begin, end): each cell takes the
// smaller of its distance and its left neighbour's + 3, left to right (or
// right to left when !rightwards), from a blocked cell outside the ends.
// Returns non-zero if a distance fell. The chain of minima is the sweep's
// critical path; long runs are cut into kChains pieces scanned together, and
// each piece's result then carried into the next until it makes no change.
Distance ScanRow(Distance* row, int begin, int end, bool rightwards) {
  Distance changed = 0;
  const int length = end - begin;
  if (length < kShortRun) {
    Distance carry = kUnreachable;
    for (int i = 0; i < length; ++i) {
      Distance& cell = row[rightwards ? begin + i : end - 1 - i];
      const Distance d = std::min(cell, carry + kChamferOrthogonal);
      changed |= d ^ cell;
      cell = d;
      carry = d;
    }
    return changed;
  }
  const int piece = length / kChains;
  const std::ptrdiff_t step = rightwards ? 1 : -1;
  // Piece k starts at first[k] and runs `piece` cells in the scan's direction
  // (the last piece also takes the rest).
  std::array<Distance*, kChains> first{};
  for (std::size_t k = 0; k < kChains; ++k) {
    const std::ptrdiff_t skip = static_cast<std::ptrdiff_t>(k) * piece;
    first[k] = rightwards ? row + begin + skip : row + end - 1 - skip;
  }
  std::array<Distance, kChains> carry{};
  carry.fill(kUnreachable);
  for (std::ptrdiff_t i = 0; i < piece; ++i) {
    for (std::size_t k = 0; k < kChains; ++k) {
      Distance& cell = first[k][i * step];
      const Distance d = std::min(cell, carry[k] + kChamferOrthogonal);
      changed |= d ^ cell;
      cell = d;
      carry[k] = d;
    }
  }
  Distance last = carry[kChains - 1];
  for (int i = kChains * piece; i < length; ++i) {
    Distance& cell = row[rightwards ? begin + i : end - 1 - i];
    const Distance d = std::min(cell, last + kChamferOrthogonal);
    changed |= d ^ cell;
    cell = d;
    last = d;
  }
  for (std::size_t k = 1; k < kChains; ++k) {
    Distance from = first[k][-step];
    const std::ptrdiff_t left = rightwards ? row + end - first[k] : first[k] - (row + begin) + 1;
    for (std::ptrdiff_t i = 0; i < left; ++i) {
      from += kChamferOrthogonal;
      Distance& cell = first[k][i * step];
      if (from >= cell) break;
      cell = from;
      changed = 1;
    }
  }
  return changed;
}

// The vertical half of a row sweep on [begin, end): each cell takes the
// smallest of its distance and its three neighbours' in the row `from` (the
// previous row in the sweep's order) + their weights. Vectorised.
Distance ScanFromRow(Distance* __restrict row, const Distance* __restrict from, int begin,
                     int end) {
  Distance changed = 0;
  for (int x = begin; x < end; ++x) {
    const Distance old = row[x];
    Distance d = std::min(from[x - 1], from[x + 1]) + kChamferDiagonal;
    d = std::min(d, from[x] + kChamferOrthogonal);
    d = std::min(d, old);
    changed |= d ^ old;
    row[x] = d;
  }
  return changed;
}

// Sweeps one row: first each cell from the row before it in the sweep's
// order, then, in each run where a distance fell (every run if `all`), along
// the row both ways. (The second way is not in Borgefors' two-pass mask; it
// needs fewer sweeps.) Only the cells in `seed` are swept from the row before,
// the others' neighbours there being unchanged. Returns the span of the runs
// in which a distance fell.
Span SweepRow(Distance* row, const Distance* from, const Run* run, const Run* run_end,
              const Span& seed, bool forward, bool all) {
  Span changed{std::numeric_limits<int>::max(), -1};
  for (; run != run_end && run->begin <= seed.hi; ++run) {
    if (run->end <= seed.lo) continue;
    Distance c =
        ScanFromRow(row, from, std::max(run->begin, seed.lo), std::min(run->end, seed.hi + 1));
    if (c == 0 && !all) continue;
    c |= ScanRow(row, run->begin, run->end, forward);
    c |= ScanRow(row, run->begin, run->end, !forward);
    if (c != 0) changed.Add({run->begin, run->end - 1});
  }
  return changed;
}

// Raster sweeps, alternately forward (rows in increasing y) and backward,
// until a sweep changes nothing. After its sweep a row is consistent along
// itself and with the row before it; a later change to the row itself keeps
// that (it only lowers distances, along the row both ways), so the row need
// be swept again only next to what changed in the row before it since, and
// along itself only in runs where that lowers a distance. Returns the sweeps
// run and whether the field converged.
template <typename Vector>
std::pair<int, bool> RasterSweeps(Vector& padded, std::size_t stride, const RowRuns& rows, int w,
                                  int h, int max_sweeps) {
  const std::size_t rows_padded = static_cast<std::size_t>(h) + 2;
  // What changed in each row and is not yet read by the forward sweep of the
  // next row (for_next) or the backward sweep of the previous (for_previous).
  std::vector<Span> for_next(rows_padded);
  std::vector<Span> for_previous(rows_padded);
  for (std::size_t r = 0; r < rows_padded; ++r) for_next[r] = for_previous[r] = Span{1, w};
  const Run* runs = rows.runs.data();
  int sweeps = 0;
  while (true) {
    bool any = false;
    const bool forward = sweeps % 2 == 0;
    for (std::size_t i = 1; i <= static_cast<std::size_t>(h); ++i) {
      const std::size_t r = forward ? i : static_cast<std::size_t>(h) + 1 - i;
      const std::size_t before = forward ? r - 1 : r + 1;
      Span& seen = forward ? for_next[before] : for_previous[before];
      if (seen.Empty()) continue;
      // A cell reads its row before's cells x - 1 .. x + 1.
      const Span seed{std::max(seen.lo - 1, 1), std::min(seen.hi + 1, w)};
      seen = Span{};
      const Span changed =
          SweepRow(padded.data() + r * stride, padded.data() + before * stride,
                   runs + rows.first[r], runs + rows.first[r + 1], seed, forward, sweeps == 0);
      if (!changed.Empty()) {
        for_next[r].Add(changed);
        for_previous[r].Add(changed);
        any = true;
      }
    }
    ++sweeps;
    // After the first two sweeps, a sweep that changes nothing leaves
    // nothing pending for the next: converged.
    if (!any && sweeps >= 2) return {sweeps, true};
    if (max_sweeps > 0 && sweeps >= max_sweeps) return {sweeps, false};
  }
}

// Dial's algorithm: a ring of buckets, one per distance modulo the largest
// weight + 1, each holding the cells whose distance was last lowered to it.
template <typename Vector>
void BucketQueue(Vector& padded, std::size_t stride, const CoarseGrid& grid) {
  const int w = grid.width();
  const int h = grid.height();
  std::vector<std::uint8_t> open(padded.size(), 0);  // kFree cells, which may be lowered
  constexpr std::size_t kBuckets = kChamferDiagonal + 1;
  std::array<std::vector<std::uint32_t>, kBuckets> buckets;
  std::size_t queued = 0;
  for (int y = 0; y < h; ++y) {
    for (int x = 0; x < w; ++x) {
      const auto i = static_cast<std::uint32_t>(static_cast<std::size_t>(y + 1) * stride + x + 1);
      const CoarseCell c = grid.cells()[static_cast<std::size_t>(y) * w + x];
      if (c == CoarseCell::kFree) open[i] = 1;
      if (c == CoarseCell::kGoal) {
        padded[i] = 0;
        buckets[0].push_back(i);
        ++queued;
      }
    }
  }
  const auto s = static_cast<std::ptrdiff_t>(stride);
  const std::array<std::pair<std::ptrdiff_t, Distance>, 8> steps = {{
      {-1, kChamferOrthogonal},
      {1, kChamferOrthogonal},
      {-s, kChamferOrthogonal},
      {s, kChamferOrthogonal},
      {-s - 1, kChamferDiagonal},
      {-s + 1, kChamferDiagonal},
      {s - 1, kChamferDiagonal},
      {s + 1, kChamferDiagonal},
  }};
  std::vector<std::uint32_t> current;
  for (Distance d = 0; queued > 0; ++d) {
    std::vector<std::uint32_t>& bucket = buckets[static_cast<std::size_t>(d) % kBuckets];
    // Cells are only added to buckets of larger distances, so this one can be swapped out.
    current.clear();
    std::swap(current, bucket);
    queued -= current.size();
    for (const std::uint32_t i : current) {
      if (padded[i] != d) continue;  // lowered again after it was queued
      for (const auto& [offset, weight] : steps) {
        const auto n = static_cast<std::size_t>(static_cast<std::ptrdiff_t>(i) + offset);
        const Distance nd = d + weight;
        if (open[n] != 0 && nd < padded[n]) {
          padded[n] = nd;
          buckets[static_cast<std::size_t>(nd) % kBuckets].push_back(static_cast<std::uint32_t>(n));
          ++queued;
        }
      }
    }
  }
}

}  // namespace

void DistanceTransformOptions::Check() const {
  if (max_sweeps < 0) {
    throw std::invalid_argument("DistanceTransformOptions: max_sweeps must be >= 0");
  }
}

DistanceField::DistanceField(int width, int height)
    : width_(width),
      height_(height),
      stride_(static_cast<std::size_t>(width) + 2),
      padded_(stride_ * (static_cast<std::size_t>(height) + 2)) {}

DistanceField ChamferDistanceTransform(const CoarseGrid& grid,
                                       const DistanceTransformOptions& options) {
  options.Check();
  if (grid.geometry().CellCount() > kMaxDistanceTransformCells) {
    throw std::invalid_argument("ChamferDistanceTransform: the grid is too large");
  }
  DistanceField field(grid.width(), grid.height());
  if (options.algorithm == DistanceAlgorithm::kBucketQueue) {
    std::fill(field.padded_.begin(), field.padded_.end(), kUnreachable);
    BucketQueue(field.padded_, field.stride_, grid);
    return field;
  }
  const RowRuns rows = Initialise(grid, field.padded_, field.stride_);
  const auto [sweeps, converged] = RasterSweeps(field.padded_, field.stride_, rows, grid.width(),
                                                grid.height(), options.max_sweeps);
  field.sweeps_ = sweeps;
  field.converged_ = converged;
  return field;
}

}  // namespace pirouette::explore
