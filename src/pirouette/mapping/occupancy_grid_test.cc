#include "pirouette/mapping/occupancy_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace pirouette::mapping {
namespace {

using core::CellIndex;
using core::GridGeometry;

OccupancyGrid SmallGrid() { return OccupancyGrid(GridGeometry(0.01, {-0.05, -0.05}, 10, 10)); }

// Applies `update` to `c` in `frames` frames of their own.
void Repeat(OccupancyGrid& grid, const CellIndex& c, CellUpdate update, int frames) {
  for (int i = 0; i < frames; ++i) {
    grid.BeginFrame();
    ASSERT_TRUE(grid.Apply(c, update));
  }
}

// The message of the std::invalid_argument that `options` throws.
std::string Refusal(const OccupancyOptions& options) {
  try {
    options.Check();
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "";
}

TEST(OccupancyOptions, DefaultsPass) { EXPECT_NO_THROW(OccupancyOptions{}.Check()); }

TEST(OccupancyOptions, RefusalsNameTheField) {
  const double nan = std::numeric_limits<double>::quiet_NaN();
  OccupancyOptions o;
  o.hit_probability = 0.5;
  EXPECT_NE(Refusal(o).find("hit_probability"), std::string::npos);
  o = {};
  o.hit_probability = 1.0;
  EXPECT_NE(Refusal(o).find("hit_probability"), std::string::npos);
  o = {};
  o.miss_probability = 0.6;
  EXPECT_NE(Refusal(o).find("miss_probability"), std::string::npos);
  o = {};
  o.miss_probability = 0.0;
  EXPECT_NE(Refusal(o).find("miss_probability"), std::string::npos);
  o = {};
  o.blind_probability = 0.5;
  EXPECT_NE(Refusal(o).find("blind_probability"), std::string::npos);
  o = {};
  o.blind_probability = nan;
  EXPECT_NE(Refusal(o).find("blind_probability"), std::string::npos);
  o = {};
  o.clamp_min_probability = 0.2;  // above the free threshold: nothing could read free
  EXPECT_NE(Refusal(o).find("clamp_min_probability"), std::string::npos);
  o = {};
  o.clamp_max_probability = 0.6;  // below the occupied threshold
  EXPECT_NE(Refusal(o).find("clamp_max_probability"), std::string::npos);
  o = {};
  o.clamp_max_probability = 1.0;
  EXPECT_NE(Refusal(o).find("clamp_max_probability"), std::string::npos);
  o = {};
  o.two_places_m = -0.1;
  EXPECT_NE(Refusal(o).find("two_places_m"), std::string::npos);
  o.two_places_m = nan;
  EXPECT_NE(Refusal(o).find("two_places_m"), std::string::npos);
  o.clamp_max_probability = 1.0;
  EXPECT_THROW(OccupancyGrid(GridGeometry(0.01, {0, 0}, 2, 2), o), std::invalid_argument);
}

TEST(OccupancyGrid, StartsUnknown) {
  const OccupancyGrid grid = SmallGrid();
  for (const CellIndex c : {CellIndex{0, 0}, CellIndex{9, 9}, CellIndex{-1, 3}, CellIndex{10, 0}}) {
    EXPECT_EQ(grid.Probability(c), 0.5);
    EXPECT_EQ(grid.LogOdds(c), 0.0F);
    EXPECT_EQ(grid.State(c), CellState::kUnknown);
    EXPECT_FALSE(grid.Known(c));
  }
}

TEST(OccupancyGrid, OneUpdateIsBayesRuleFromUnknown) {
  OccupancyGrid grid = SmallGrid();
  grid.BeginFrame();
  EXPECT_TRUE(grid.Apply({1, 1}, CellUpdate::kHit));
  EXPECT_TRUE(grid.Apply({2, 1}, CellUpdate::kMiss));
  EXPECT_TRUE(grid.Apply({3, 1}, CellUpdate::kBlind));
  EXPECT_FALSE(grid.Apply({-1, 1}, CellUpdate::kHit));
  EXPECT_NEAR(grid.Probability({1, 1}), 0.7, 1e-6);
  EXPECT_NEAR(grid.Probability({2, 1}), 0.4, 1e-6);
  EXPECT_NEAR(grid.Probability({3, 1}), 0.6, 1e-6);
  EXPECT_TRUE(grid.Known({1, 1}));
  EXPECT_TRUE(grid.Known({3, 1}));
  // Two hits: odds multiply, (0.7/0.3)^2.
  Repeat(grid, {1, 1}, CellUpdate::kHit, 1);
  EXPECT_NEAR(grid.Probability({1, 1}), 49.0 / 58.0, 1e-6);
}

TEST(OccupancyGrid, EachCellChangesAtMostOncePerFrame) {
  OccupancyGrid grid = SmallGrid();
  grid.BeginFrame();
  EXPECT_TRUE(grid.Apply({4, 4}, CellUpdate::kHit));
  EXPECT_FALSE(grid.Apply({4, 4}, CellUpdate::kHit));
  EXPECT_FALSE(grid.Apply({4, 4}, CellUpdate::kMiss));  // the first update wins
  EXPECT_NEAR(grid.Probability({4, 4}), 0.7, 1e-6);
  grid.BeginFrame();
  EXPECT_TRUE(grid.Apply({4, 4}, CellUpdate::kMiss));
  EXPECT_NEAR(grid.Probability({4, 4}), 0.28 / (0.28 + 0.18), 1e-6);
}

TEST(OccupancyGrid, ClampsAtBothEnds) {
  OccupancyGrid grid = SmallGrid();
  Repeat(grid, {0, 0}, CellUpdate::kHit, 50);
  Repeat(grid, {1, 0}, CellUpdate::kMiss, 50);
  EXPECT_NEAR(grid.Probability({0, 0}), 0.97, 1e-6);
  EXPECT_NEAR(grid.Probability({1, 0}), 0.12, 1e-6);
  // Clamped cells turn back as fast as a fresh one would after the clamp.
  Repeat(grid, {0, 0}, CellUpdate::kMiss, 1);
  EXPECT_NEAR(grid.LogOdds({0, 0}), std::log(0.97 / 0.03) + std::log(0.4 / 0.6), 1e-5);
  Repeat(grid, {1, 0}, CellUpdate::kHit, 1);
  EXPECT_NEAR(grid.LogOdds({1, 0}), std::log(0.12 / 0.88) + std::log(0.7 / 0.3), 1e-5);
}

TEST(OccupancyGrid, BlindMarksOnlyUntouchedCells) {
  OccupancyGrid grid = SmallGrid();
  Repeat(grid, {0, 0}, CellUpdate::kBlind, 20);  // unknown: straight to 0.6 and stays
  EXPECT_NEAR(grid.Probability({0, 0}), 0.6, 1e-6);
  Repeat(grid, {1, 0}, CellUpdate::kMiss, 50);  // free, at the clamp
  const float free = grid.LogOdds({1, 0});
  Repeat(grid, {1, 0}, CellUpdate::kBlind, 20);  // a blind view leaves it
  EXPECT_EQ(grid.LogOdds({1, 0}), free);
  EXPECT_EQ(grid.State({1, 0}), CellState::kFree);
  Repeat(grid, {2, 0}, CellUpdate::kHit, 3);  // occupied: a blind view leaves it
  const float occupied = grid.LogOdds({2, 0});
  Repeat(grid, {2, 0}, CellUpdate::kBlind, 5);
  EXPECT_EQ(grid.LogOdds({2, 0}), occupied);
  // A blind area is known, but neither free nor occupied; a later miss frees it.
  EXPECT_TRUE(grid.Known({0, 0}));
  EXPECT_EQ(grid.State({0, 0}), CellState::kUnknown);
  Repeat(grid, {0, 0}, CellUpdate::kMiss, 1);
  EXPECT_NEAR(grid.Probability({0, 0}), 0.5, 1e-6);
}

TEST(OccupancyGrid, TrinaryByTheThresholds) {
  OccupancyGrid grid = SmallGrid();
  // Misses from 0.5: 0.4, 0.31, 0.23 are unknown, the fourth (0.165) is free.
  for (int n = 1; n <= 4; ++n) Repeat(grid, {n, 0}, CellUpdate::kMiss, n);
  Repeat(grid, {5, 0}, CellUpdate::kHit, 1);  // 0.7 > 0.65
  Repeat(grid, {6, 0}, CellUpdate::kBlind, 1);
  const TrinaryMap map = grid.ToTrinary();
  EXPECT_EQ(map.geometry, grid.geometry());
  ASSERT_EQ(map.cells.size(), grid.geometry().CellCount());
  EXPECT_EQ(map.At({0, 0}), CellState::kUnknown);
  EXPECT_EQ(map.At({1, 0}), CellState::kUnknown);
  EXPECT_EQ(map.At({2, 0}), CellState::kUnknown);
  EXPECT_EQ(map.At({3, 0}), CellState::kUnknown);
  EXPECT_EQ(map.At({4, 0}), CellState::kFree);
  EXPECT_EQ(map.At({5, 0}), CellState::kOccupied);
  EXPECT_EQ(map.At({6, 0}), CellState::kUnknown);
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 10; ++x) {
      const CellState s = map.At({x, y});
      EXPECT_EQ(s, grid.State({x, y}));
      const double p = grid.Probability({x, y});
      if (s == CellState::kFree) {
        EXPECT_LT(p, kFreeThreshold);
      } else if (s == CellState::kOccupied) {
        EXPECT_GT(p, kOccupiedThreshold);
      }
    }
  }
  // A custom model with a weaker hit: 0.62 is below the occupied threshold.
  OccupancyOptions weak;
  weak.hit_probability = 0.62;
  OccupancyGrid weak_grid(GridGeometry(0.01, {0, 0}, 2, 1), weak);
  Repeat(weak_grid, {0, 0}, CellUpdate::kHit, 1);
  EXPECT_EQ(weak_grid.State({0, 0}), CellState::kUnknown);
  Repeat(weak_grid, {0, 0}, CellUpdate::kHit, 1);
  EXPECT_EQ(weak_grid.State({0, 0}), CellState::kOccupied);
}

TEST(OccupancyGrid, SetFreeIsTheFreeClampEvenInAFrameAlreadyUsed) {
  OccupancyGrid grid = SmallGrid();
  grid.BeginFrame();
  ASSERT_TRUE(grid.Apply({3, 3}, CellUpdate::kHit));
  grid.SetFree({3, 3});
  grid.SetFree({30, 3});  // off the grid: nothing
  EXPECT_NEAR(grid.Probability({3, 3}), 0.12, 1e-6);
  EXPECT_EQ(grid.State({3, 3}), CellState::kFree);
  EXPECT_FALSE(grid.Apply({3, 3}, CellUpdate::kHit));  // still this frame's one change
}

TEST(OccupancyGrid, SetSolidIsTheOccupiedClampFromTwoPlaces) {
  OccupancyGrid grid = SmallGrid();
  grid.BeginFrame();
  ASSERT_TRUE(grid.Apply({3, 3}, CellUpdate::kMiss));
  grid.SetSolid({3, 3});
  grid.SetSolid({30, 3});  // off the grid: nothing
  EXPECT_NEAR(grid.Probability({3, 3}), 0.97, 1e-6);
  EXPECT_EQ(grid.State({3, 3}), CellState::kOccupied);
  EXPECT_TRUE(grid.Solid({3, 3}));
  EXPECT_FALSE(grid.Solid({4, 3}));
}

TEST(OccupancyGrid, GrowthKeepsValuesAndWorldPositions) {
  OccupancyGrid grid(GridGeometry(0.01, {0.3, -0.2}, 20, 10));
  const GridGeometry before = grid.geometry();
  // A pattern of values, remembered by world position.
  std::vector<std::pair<Eigen::Vector2d, float>> values;
  for (int y = 0; y < 10; ++y) {
    for (int x = 0; x < 20; ++x) {
      Repeat(grid, {x, y}, (x + y) % 3 == 0 ? CellUpdate::kHit : CellUpdate::kMiss, x % 4 + 1);
      values.emplace_back(before.CellCentre({x, y}), grid.LogOdds({x, y}));
    }
  }
  // Already covered (with the margin): nothing changes.
  grid.GrowToCover({0.33, -0.17}, {0.47, -0.13});
  EXPECT_EQ(grid.geometry(), before);

  grid.GrowToCover({-1.234, 0.0}, {0.4, 2.5});  // left and up
  const GridGeometry& after = grid.geometry();
  EXPECT_EQ(after.resolution(), before.resolution());
  const Eigen::Vector2d shift = (before.origin() - after.origin()) / before.resolution();
  EXPECT_NEAR(shift.x(), std::round(shift.x()), 1e-9);  // whole cells
  EXPECT_NEAR(shift.y(), std::round(shift.y()), 1e-9);
  EXPECT_GT(shift.x(), 0.0);
  EXPECT_EQ(shift.y(), 0.0);
  for (const auto& [p, value] : values) {
    const CellIndex c = after.CellOf(p);
    EXPECT_EQ(grid.LogOdds(c), value);
    EXPECT_TRUE(grid.Known(c));
    EXPECT_LT((after.CellCentre(c) - p).norm(), 1e-9);
  }
  // The rectangle and the margin are covered; growth is in generous chunks.
  const double margin = OccupancyGrid::kGrowMarginCells * after.resolution();
  EXPECT_TRUE(after.CellAt({-1.234 - margin + 1e-6, -0.2}).has_value());
  EXPECT_TRUE(after.CellAt({0.4, 2.5 + margin - 1e-6}).has_value());
  EXPECT_GE(after.width() - before.width(), 100 + 153);
  // Newly covered cells are unknown; growing again within it is a no-op.
  EXPECT_FALSE(grid.Known(after.CellOf({-1.0, 2.0})));
  const GridGeometry grown = after;
  grid.GrowToCover({-1.2, -0.1}, {0.4, 2.4});
  EXPECT_EQ(grid.geometry(), grown);
}

TEST(OccupancyGrid, GrowthRefusesBadRectangles) {
  OccupancyGrid grid = SmallGrid();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(grid.GrowToCover({1.0, 0.0}, {0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(grid.GrowToCover({nan, 0.0}, {0.0, 0.0}), std::invalid_argument);
  EXPECT_THROW(grid.GrowToCover({0.0, 0.0}, {1e9, 0.0}), std::length_error);
  EXPECT_THROW(grid.GrowToCover({0.0, 0.0}, {400.0, 0.0}), std::length_error);
  EXPECT_EQ(grid.geometry().width(), 10);
}

// A limited grid grows in chunks while they fit, then by what is lacking
// only, and refuses (MapTooLarge, nothing changed) a cover past its limit.
TEST(OccupancyGrid, GrowthStopsAtTheSideLimit) {
  OccupancyGrid grid = SmallGrid();
  grid.LimitSide(150);
  grid.GrowToCover({0.0, 0.0}, {1.3, 0.05});
  EXPECT_LE(grid.geometry().width(), 150);
  EXPECT_GE(grid.geometry().width(), 133);
  const GridGeometry before = grid.geometry();
  EXPECT_THROW(grid.GrowToCover({0.0, 0.0}, {1.6, 0.05}), MapTooLarge);
  EXPECT_EQ(grid.geometry(), before);
  const OccupancyGrid copy = grid;
  EXPECT_EQ(copy.max_side_cells(), 150);
  EXPECT_THROW(grid.LimitSide(0), std::invalid_argument);
}

TEST(OccupancyGrid, ExploredMapDecidesEveryTouchedCell) {
  OccupancyGrid grid = SmallGrid();
  Repeat(grid, {0, 0}, CellUpdate::kBlind, 1);  // 0.6: unknown, leaning occupied
  Repeat(grid, {1, 0}, CellUpdate::kHit, 1);
  Repeat(grid, {1, 0}, CellUpdate::kMiss, 1);  // 0.7 then 0.4 -> 0.61: leaning occupied
  Repeat(grid, {2, 0}, CellUpdate::kMiss, 1);  // 0.4: unknown, leaning free
  Repeat(grid, {3, 0}, CellUpdate::kHit, 1);   // occupied
  const TrinaryMap trinary = grid.ToTrinary();
  const TrinaryMap explored = grid.ToExploredMap();
  EXPECT_EQ(trinary.At({0, 0}), CellState::kUnknown);
  EXPECT_EQ(explored.At({0, 0}), CellState::kOccupied);
  EXPECT_EQ(explored.At({1, 0}), CellState::kOccupied);
  EXPECT_EQ(trinary.At({2, 0}), CellState::kUnknown);
  EXPECT_EQ(explored.At({2, 0}), CellState::kFree);
  EXPECT_EQ(explored.At({3, 0}), CellState::kOccupied);
  EXPECT_EQ(explored.At({4, 0}), CellState::kUnknown);  // never touched
}

TEST(OccupancyGrid, OnOneLookIsWhatLeansOccupiedOnOneFrame) {
  OccupancyGrid grid = SmallGrid();
  Repeat(grid, {0, 0}, CellUpdate::kBlind, 3);  // a blind area only
  Repeat(grid, {1, 0}, CellUpdate::kHit, 1);    // one hit
  Repeat(grid, {2, 0}, CellUpdate::kMiss, 1);
  Repeat(grid, {2, 0}, CellUpdate::kHit, 1);  // a hit against a miss: still leaning occupied
  Repeat(grid, {3, 0}, CellUpdate::kHit, 2);  // two looks agree
  Repeat(grid, {4, 0}, CellUpdate::kBlind, 1);
  Repeat(grid, {4, 0}, CellUpdate::kHit, 1);  // a blind area then a hit: two looks
  Repeat(grid, {5, 0}, CellUpdate::kHit, 1);
  Repeat(grid, {5, 0}, CellUpdate::kMiss, 3);  // leans free
  EXPECT_TRUE(grid.OnOneLook({0, 0}));
  EXPECT_TRUE(grid.OnOneLook({1, 0}));
  EXPECT_TRUE(grid.OnOneLook({2, 0}));
  EXPECT_FALSE(grid.OnOneLook({3, 0}));
  EXPECT_FALSE(grid.OnOneLook({4, 0}));
  EXPECT_FALSE(grid.OnOneLook({5, 0}));
  EXPECT_FALSE(grid.OnOneLook({6, 0}));   // never touched
  EXPECT_FALSE(grid.OnOneLook({-1, 0}));  // off the grid
}

TEST(OccupancyGrid, CroppedToKnownKeepsCellsAndWorldPositions) {
  OccupancyGrid grid(core::GridGeometry(0.1, {-1.0, -2.0}, 30, 20));
  ASSERT_TRUE(grid.Apply({10, 5}, CellUpdate::kHit));
  ASSERT_TRUE(grid.Apply({14, 8}, CellUpdate::kMiss));
  const OccupancyGrid cropped = grid.CroppedToKnown(2);
  EXPECT_EQ(cropped.geometry().width(), 4 + 1 + 4);
  EXPECT_EQ(cropped.geometry().height(), 3 + 1 + 4);
  for (const core::CellIndex c : {core::CellIndex{10, 5}, core::CellIndex{14, 8}}) {
    const Eigen::Vector2d p = grid.geometry().CellCentre(c);
    const core::CellIndex d = cropped.geometry().CellOf(p);
    EXPECT_EQ(cropped.LogOdds(d), grid.LogOdds(c));
    EXPECT_TRUE(cropped.Known(d));
  }
  EXPECT_EQ(cropped.KnownCellCount(), 2u);
  // Nothing known: the grid stays whole.
  const OccupancyGrid empty(core::GridGeometry(0.1, {0.0, 0.0}, 5, 5));
  EXPECT_EQ(empty.CroppedToKnown(1).geometry(), empty.geometry());
}

TEST(OccupancyGrid, RestoreMakesTheGridWhatItWasWhenThePartWasCut) {
  OccupancyGrid grid(core::GridGeometry(0.1, {-1.0, -2.0}, 30, 20));
  grid.BeginFrame();
  ASSERT_TRUE(grid.Apply({10, 5}, CellUpdate::kHit));
  const OccupancyGrid part = grid.CroppedToKnown(0);
  const OccupancyGrid before = grid;
  // Later frames, and growth that moves the origin by whole cells.
  grid.BeginFrame();
  ASSERT_TRUE(grid.Apply({10, 5}, CellUpdate::kHit));
  ASSERT_TRUE(grid.Apply({20, 15}, CellUpdate::kMiss));
  grid.GrowToCover({-3.0, -4.0}, {3.0, 1.0});
  ASSERT_NE(grid.geometry().origin(), before.geometry().origin());
  grid.Restore(part);
  EXPECT_EQ(grid.frame(), before.frame());
  EXPECT_EQ(grid.KnownCellCount(), 1u);
  for (int y = 0; y < before.geometry().height(); ++y) {
    for (int x = 0; x < before.geometry().width(); ++x) {
      const core::CellIndex c =
          grid.geometry().CellOf(before.geometry().CellCentre(core::CellIndex{x, y}));
      EXPECT_EQ(grid.LogOdds(c), before.LogOdds({x, y})) << x << "," << y;
      EXPECT_EQ(grid.Known(c), before.Known({x, y})) << x << "," << y;
    }
  }
  // A part that does not fit, or of another resolution, is refused.
  const OccupancyGrid small(core::GridGeometry(0.1, {0.0, 0.0}, 3, 3));
  OccupancyGrid elsewhere(core::GridGeometry(0.1, {5.0, 5.0}, 3, 3));
  EXPECT_THROW(elsewhere.Restore(part), std::invalid_argument);
  OccupancyGrid finer(core::GridGeometry(0.05, {-1.0, -2.0}, 60, 40));
  EXPECT_THROW(finer.Restore(part), std::invalid_argument);
  EXPECT_NO_THROW(OccupancyGrid(core::GridGeometry(0.1, {-1.0, -1.0}, 20, 20)).Restore(small));
}

// Applies `update` to `c` in `frames` frames of their own, seen from `viewpoint`.
void UpdateFrom(OccupancyGrid& grid, const CellIndex& c, const Eigen::Vector2d& viewpoint,
                int frames, CellUpdate update) {
  for (int i = 0; i < frames; ++i) {
    grid.BeginFrame(viewpoint);
    ASSERT_TRUE(grid.Apply(c, update));
  }
}

void HitFrom(OccupancyGrid& grid, const CellIndex& c, const Eigen::Vector2d& viewpoint,
             int frames) {
  UpdateFrom(grid, c, viewpoint, frames, CellUpdate::kHit);
}

void MissFrom(OccupancyGrid& grid, const CellIndex& c, const Eigen::Vector2d& viewpoint,
              int frames) {
  UpdateFrom(grid, c, viewpoint, frames, CellUpdate::kMiss);
}

TEST(OccupancyGrid, TheMapOfRecordCallsFreeOnlyWhatTwoPlacesSawFree) {
  const CellIndex c{4, 4};
  const auto record = [&c](const OccupancyGrid& g) {
    return g.ToMapOfRecord().cells[g.geometry().Flat(c)];
  };
  // Seen free from one place, however often: free to the explorer, unknown on record.
  OccupancyGrid grid = SmallGrid();
  MissFrom(grid, c, {0.0, 0.0}, 10);
  EXPECT_EQ(grid.State(c), CellState::kFree);
  EXPECT_FALSE(grid.FreeFromTwoPlaces(c));
  EXPECT_EQ(record(grid), CellState::kUnknown);
  EXPECT_EQ(grid.ToMapOfRecord().cells[grid.geometry().Flat({0, 0})], CellState::kUnknown);
  // A second place nearer than the baseline (0.15 m), or a frame without one: still not.
  MissFrom(grid, c, {0.1, 0.0}, 1);
  grid.BeginFrame();
  ASSERT_TRUE(grid.Apply(c, CellUpdate::kMiss));
  EXPECT_EQ(record(grid), CellState::kUnknown);
  // From far enough: free on record, and it stays so while the cell is free.
  MissFrom(grid, c, {0.0, 0.2}, 1);
  EXPECT_TRUE(grid.FreeFromTwoPlaces(c));
  EXPECT_EQ(record(grid), CellState::kFree);
  HitFrom(grid, c, {0.0, 0.0}, 4);
  EXPECT_EQ(record(grid), CellState::kOccupied);
  // Hits from two places do not make a cell free from two places.
  OccupancyGrid hit = SmallGrid();
  HitFrom(hit, c, {0.0, 0.0}, 1);
  HitFrom(hit, c, {1.0, 0.0}, 1);
  MissFrom(hit, c, {0.0, 0.0}, 10);
  EXPECT_EQ(hit.State(c), CellState::kFree);
  EXPECT_EQ(record(hit), CellState::kUnknown);
  // A look from far enough from the first place would corroborate; from near it, not.
  OccupancyGrid once = SmallGrid();
  MissFrom(once, c, {0.0, 0.0}, 10);
  EXPECT_TRUE(once.WouldCorroborate(c, {0.2, 0.0}));
  EXPECT_FALSE(once.WouldCorroborate(c, {0.1, 0.0}));
  EXPECT_FALSE(once.WouldCorroborate({0, 0}, {0.2, 0.0}));  // never seen
  EXPECT_FALSE(grid.WouldCorroborate(c, {1.0, 1.0}));       // occupied now
  MissFrom(once, c, {0.2, 0.0}, 1);
  EXPECT_FALSE(once.WouldCorroborate(c, {1.0, 0.0}));  // already free from two places
  // Where the robot stood is free for certain.
  OccupancyGrid stood = SmallGrid();
  stood.SetFree(c);
  EXPECT_EQ(record(stood), CellState::kFree);
  // Kept through a crop and a restore.
  const OccupancyGrid part = grid.CroppedToKnown(0);
  EXPECT_EQ(part.ToMapOfRecord()
                .cells[part.geometry().Flat(part.geometry().CellOf(grid.geometry().CellCentre(c)))],
            CellState::kOccupied);
  OccupancyGrid restored = SmallGrid();
  MissFrom(restored, c, {0.0, 0.0}, 4);
  MissFrom(restored, c, {1.0, 0.0}, 1);
  const OccupancyGrid freed = restored.CroppedToKnown(0);
  OccupancyGrid again = SmallGrid();
  again.Restore(freed);
  EXPECT_EQ(record(again), CellState::kFree);
  // The rule off: the map of record is the trinary map.
  OccupancyOptions off;
  off.two_places_m = 0.0;
  OccupancyGrid plain(GridGeometry(0.01, {-0.05, -0.05}, 10, 10), off);
  MissFrom(plain, c, {0.0, 0.0}, 10);
  EXPECT_TRUE(plain.FreeFromTwoPlaces(c));
  EXPECT_EQ(plain.ToMapOfRecord().cells, plain.ToTrinary().cells);
}

TEST(OccupancyGrid, SolidIsAtTheClampAndHitFromTwoPlaces) {
  const CellIndex c{4, 4};
  // From one place, however often: not solid (a phantom repeats from one place).
  OccupancyGrid one = SmallGrid();
  HitFrom(one, c, {0.0, 0.0}, 20);
  EXPECT_NEAR(one.Probability(c), 0.97, 1e-6);
  EXPECT_FALSE(one.Solid(c));
  // From a second place nearer than the baseline (0.15 m): still not.
  HitFrom(one, c, {0.1, 0.0}, 1);
  EXPECT_FALSE(one.Solid(c));
  // From one far enough: solid, as long as it stays at the clamp.
  HitFrom(one, c, {0.0, 0.2}, 1);
  EXPECT_TRUE(one.Solid(c));
  Repeat(one, c, CellUpdate::kMiss, 1);
  EXPECT_FALSE(one.Solid(c));
  HitFrom(one, c, {0.0, 0.0}, 1);  // back at the clamp, from anywhere
  EXPECT_TRUE(one.Solid(c));
  // Two places but below the clamp: not yet.
  OccupancyGrid two = SmallGrid();
  HitFrom(two, c, {0.0, 0.0}, 1);
  HitFrom(two, c, {1.0, 0.0}, 1);
  EXPECT_FALSE(two.Solid(c));
  HitFrom(two, c, {1.0, 0.0}, 3);
  EXPECT_TRUE(two.Solid(c));
  // Hits of frames begun without a viewpoint never count.
  OccupancyGrid none = SmallGrid();
  Repeat(none, c, CellUpdate::kHit, 10);
  HitFrom(none, c, {1.0, 0.0}, 1);
  EXPECT_FALSE(none.Solid(c));
  // Solidity off.
  OccupancyOptions off;
  off.two_places_m = 0.0;
  OccupancyGrid never(GridGeometry(0.01, {-0.05, -0.05}, 10, 10), off);
  HitFrom(never, c, {0.0, 0.0}, 5);
  HitFrom(never, c, {1.0, 0.0}, 5);
  EXPECT_FALSE(never.Solid(c));
  EXPECT_FALSE(never.Solid({40, 40}));  // off the grid
  // Kept through growth, a crop and a restore, its block flagged in each.
  const auto flagged = [](const OccupancyGrid& g, const CellIndex& cell) {
    const int k = OccupancyGrid::kSolidBlockCells;
    const int block = (cell.y / k) * g.solid_blocks_width() + cell.x / k;
    return g.SolidBlockAt(static_cast<std::size_t>(block));
  };
  EXPECT_TRUE(flagged(two, c));
  EXPECT_FALSE(flagged(two, {9, 9}));
  two.GrowToCover({-2.03, -2.01}, {2.0, 2.0});
  const Eigen::Vector2d centre = SmallGrid().geometry().CellCentre(c);
  const CellIndex grown = two.geometry().CellOf(centre);
  EXPECT_TRUE(two.Solid(grown));
  EXPECT_TRUE(flagged(two, grown));
  const OccupancyGrid part = two.CroppedToKnown(0);
  EXPECT_TRUE(part.Solid(part.geometry().CellOf(centre)));
  EXPECT_TRUE(flagged(part, part.geometry().CellOf(centre)));
  two.GrowToCover({-3.0, -3.0}, {3.0, 3.0});
  two.Restore(part);
  EXPECT_TRUE(flagged(two, two.geometry().CellOf(centre)));
}

}  // namespace
}  // namespace pirouette::mapping
