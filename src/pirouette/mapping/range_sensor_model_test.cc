#include "pirouette/mapping/range_sensor_model.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <random>
#include <set>
#include <stdexcept>
#include <utility>
#include <vector>

#include "pirouette/core/angle.h"

namespace pirouette::mapping {
namespace {

using core::CellIndex;
using core::DegToRad;
using core::GridGeometry;
using core::ObstacleProfile;
using core::Pose2;
using core::ReadingKind;

constexpr double kCell = 0.01;

// A 1 m square grid of 1 cm cells centred on the world's origin.
OccupancyGrid MetreGrid() { return OccupancyGrid(GridGeometry(kCell, {-0.5, -0.5}, 100, 100)); }

ObstacleProfile Profile(std::initializer_list<core::RangeReading> readings) {
  return {readings, 0.4};
}

// The grid cell of a world point, which must be on the grid.
CellIndex At(const OccupancyGrid& grid, double x, double y) {
  const auto c = grid.geometry().CellAt({x, y});
  EXPECT_TRUE(c.has_value()) << x << ", " << y;
  return c.value_or(CellIndex{});
}

// Robot at a cell centre facing +y; bearing 0 is therefore +y.
const Pose2 kFacingNorth(0.005, 0.005, std::numbers::pi / 2);

TEST(InsertProfile, HitRayFreeBeforeOccupiedAtUnknownBeyond) {
  OccupancyGrid grid = MetreGrid();
  const std::size_t applied =
      InsertProfile(grid, Profile({{0.0, 0.2, ReadingKind::kHit}}), kFacingNorth);
  EXPECT_EQ(applied, 21U);  // 20 misses and the hit
  for (int i = 0; i < 20; ++i) {
    const CellIndex c = At(grid, 0.005, 0.005 + i * kCell);
    EXPECT_NEAR(grid.Probability(c), 0.4, 1e-6) << i;
  }
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.205)), 0.7, 1e-6);
  EXPECT_EQ(grid.State(At(grid, 0.005, 0.205)), CellState::kOccupied);
  for (int i = 21; i < 45; ++i) EXPECT_FALSE(grid.Known(At(grid, 0.005, 0.005 + i * kCell)));
  // Nothing off the ray was touched.
  int known = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) known += grid.Known({x, y}) ? 1 : 0;
  }
  EXPECT_EQ(known, 21);
}

TEST(InsertProfile, BearingsAreCounterClockwiseFromTheHeading) {
  OccupancyGrid grid = MetreGrid();
  const Pose2 facing_east(0.005, 0.005, 0.0);
  InsertProfile(grid, Profile({{DegToRad(90.0), 0.1, ReadingKind::kHit}}), facing_east);
  EXPECT_EQ(grid.State(At(grid, 0.005, 0.105)), CellState::kOccupied);  // left of east: north
  InsertProfile(grid, Profile({{DegToRad(-90.0), 0.1, ReadingKind::kHit}}), kFacingNorth);
  EXPECT_EQ(grid.State(At(grid, 0.105, 0.005)), CellState::kOccupied);  // right of north: east
}

TEST(InsertProfile, RayCellsFollowTheLine) {
  OccupancyGrid grid = MetreGrid();
  const Pose2 pose(-0.123, 0.041, DegToRad(10.0));
  const double bearing = DegToRad(23.0);
  const double range = 0.37;
  InsertProfile(grid, Profile({{bearing, range, ReadingKind::kClear}}), pose);
  const Eigen::Vector2d& a = pose.translation();
  const Eigen::Vector2d b =
      pose * Eigen::Vector2d(range * std::cos(bearing), range * std::sin(bearing));
  const CellIndex ca = grid.geometry().CellOf(a);
  const CellIndex cb = grid.geometry().CellOf(b);
  int known = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      if (!grid.Known({x, y})) continue;
      ++known;
      // The segment passes through each cell of the ray.
      const Eigen::Vector2d p = grid.geometry().CellCentre({x, y});
      const double t = std::clamp((p - a).dot(b - a) / (b - a).squaredNorm(), 0.0, 1.0);
      EXPECT_LE((a + t * (b - a) - p).norm(), kCell * std::sqrt(0.5)) << x << ", " << y;
      EXPECT_NEAR(grid.Probability({x, y}), 0.4, 1e-6);
    }
  }
  // One cell per column and row crossed, both ends included: 4-connected.
  EXPECT_EQ(known, std::abs(cb.x - ca.x) + std::abs(cb.y - ca.y) + 1);
  EXPECT_TRUE(grid.Known(ca));
  EXPECT_TRUE(grid.Known(cb));
}

TEST(InsertProfile, ClearReadingIsFreeOutToTheRange) {
  OccupancyGrid grid = MetreGrid();
  const std::size_t applied =
      InsertProfile(grid, Profile({{0.0, 0.4, ReadingKind::kClear}}), kFacingNorth);
  EXPECT_EQ(applied, 41U);
  for (int i = 0; i <= 40; ++i) {
    EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.005 + i * kCell)), 0.4, 1e-6) << i;
  }
  EXPECT_FALSE(grid.Known(At(grid, 0.005, 0.415)));
}

TEST(InsertProfile, BlindReadingIsHalfWayOutToTheRange) {
  OccupancyGrid grid = MetreGrid();
  InsertProfile(grid, Profile({{0.0, 0.12, ReadingKind::kBlind}}), kFacingNorth);
  for (int i = 0; i <= 12; ++i) {
    const CellIndex c = At(grid, 0.005, 0.005 + i * kCell);
    EXPECT_NEAR(grid.Probability(c), 0.6, 1e-6) << i;
    EXPECT_TRUE(grid.Known(c));
    EXPECT_EQ(grid.State(c), CellState::kUnknown);
  }
  EXPECT_FALSE(grid.Known(At(grid, 0.005, 0.135)));
  // More blind frames keep it there.
  for (int i = 0; i < 10; ++i) {
    InsertProfile(grid, Profile({{0.0, 0.12, ReadingKind::kBlind}}), kFacingNorth);
  }
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.065)), 0.6, 1e-6);
}

TEST(InsertProfile, HitWinsOverMissInTheSameFrame) {
  // A clear reading passes through the cell where another one hits; whichever
  // comes first in the profile, the hit counts and the cell changes once.
  for (const bool hit_first : {true, false}) {
    OccupancyGrid grid = MetreGrid();
    const core::RangeReading hit{0.0, 0.1, ReadingKind::kHit};
    const core::RangeReading clear{0.0, 0.3, ReadingKind::kClear};
    InsertProfile(grid, hit_first ? Profile({hit, clear}) : Profile({clear, hit}), kFacingNorth);
    EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.105)), 0.7, 1e-6);
    EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.095)), 0.4, 1e-6);
    EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.205)), 0.4, 1e-6);
  }
}

TEST(InsertProfile, HitWinsOverBlindAndBlindOverMiss) {
  OccupancyGrid grid = MetreGrid();
  InsertProfile(grid,
                Profile({{0.0, 0.3, ReadingKind::kClear},
                         {0.0, 0.1, ReadingKind::kBlind},
                         {0.0, 0.05, ReadingKind::kHit}}),
                kFacingNorth);
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.055)), 0.7, 1e-6);  // hit
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.025)), 0.6, 1e-6);  // blind over miss
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.085)), 0.6, 1e-6);
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.155)), 0.4, 1e-6);  // beyond the blind area
}

TEST(InsertProfile, ACellCrossedByManyRaysChangesOnce) {
  OccupancyGrid grid = MetreGrid();
  ObstacleProfile profile{{}, 0.4};
  for (int i = 0; i < 100; ++i) {
    profile.readings.push_back({DegToRad(-5.0 + 0.1 * i), 0.3, ReadingKind::kClear});
  }
  const std::size_t applied = InsertProfile(grid, profile, kFacingNorth);
  // The robot's cell lies on all 100 rays and took one miss.
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.005)), 0.4, 1e-6);
  std::size_t known = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      if (!grid.Known({x, y})) continue;
      ++known;
      EXPECT_NEAR(grid.Probability({x, y}), 0.4, 1e-6);
    }
  }
  EXPECT_EQ(applied, known);  // one update per touched cell
  // The next frame is a new one: one more miss each.
  InsertProfile(grid, profile, kFacingNorth);
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.005)), 0.16 / (0.16 + 0.36), 1e-6);
}

// Every cell whose centre lies within `radius` of `centre` is known and more
// likely free than not; returns how many cells that was.
int ExpectSweptDisc(const OccupancyGrid& grid, const Eigen::Vector2d& centre, double radius) {
  const GridGeometry& g = grid.geometry();
  int cells = 0;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if ((g.CellCentre({x, y}) - centre).norm() > radius) continue;
      ++cells;
      EXPECT_TRUE(grid.Known({x, y})) << "hole at " << x << ", " << y;
      EXPECT_LT(grid.Probability({x, y}), 0.5) << x << ", " << y;
    }
  }
  return cells;
}

TEST(InsertProfile, FullCircleLeavesNoHoles) {
  // The paper's column spacing (~0.19°) at 0.4 m, from an off-centre pose.
  OccupancyGrid grid = MetreGrid();
  const Pose2 pose(0.0137, -0.0291, 0.3);
  ObstacleProfile profile{{}, 0.4};
  for (int i = 0; i < 1920; ++i) {
    profile.readings.push_back({DegToRad(180.0 - 0.1875 * i), 0.4, ReadingKind::kClear});
  }
  InsertProfile(grid, profile, pose);
  EXPECT_GT(ExpectSweptDisc(grid, pose.translation(), 0.4 - kCell), 1500);
}

TEST(InsertProfile, SparseReadingsAreFilledBetween) {
  // 2° apart at 1 m, rays part by 3.5 cells: the gaps between them are filled
  // out to the shorter range. Hits at ranges that vary with the bearing.
  OccupancyGrid grid(GridGeometry(kCell, {-1.5, -1.5}, 300, 300));
  const Pose2 pose(0.003, 0.008, 0.0);
  const auto range = [](double bearing) { return 0.9 + 0.1 * std::sin(3.0 * bearing); };
  ObstacleProfile profile{{}, 1.2};
  for (int i = 0; i <= 180; ++i) {  // the last closes the circle
    const double bearing = DegToRad(-2.0 * i);
    profile.readings.push_back({bearing, range(bearing), ReadingKind::kHit});
  }
  InsertProfile(grid, profile, pose);
  const int cells = ExpectSweptDisc(grid, pose.translation(), 0.8 - kCell);
  EXPECT_GT(cells, 19000);
  // Without the fill (readings farther apart than kMaxFillGapRad) there are holes.
  OccupancyGrid sparse(GridGeometry(kCell, {-1.5, -1.5}, 300, 300));
  ObstacleProfile sparse_profile{{}, 1.2};
  for (int i = 0; i < 60; ++i) {
    sparse_profile.readings.push_back({DegToRad(-6.0 * i), 0.9, ReadingKind::kClear});
  }
  InsertProfile(sparse, sparse_profile, pose);
  int holes = 0;
  const GridGeometry& g = sparse.geometry();
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if ((g.CellCentre({x, y}) - pose.translation()).norm() < 0.8 && !sparse.Known({x, y})) {
        ++holes;
      }
    }
  }
  EXPECT_GT(holes, 1000);
}

TEST(InsertProfile, FillStopsShortOfHitsAndSkipsBlindAreas) {
  OccupancyGrid grid = MetreGrid();
  // Two hits 4° apart at 0.4 m (2.8 cells apart): the fill between them is
  // free out to the range, never occupied there; nothing is filled between
  // the second and a blind reading.
  InsertProfile(grid,
                Profile({{DegToRad(2.0), 0.4, ReadingKind::kHit},
                         {DegToRad(-2.0), 0.4, ReadingKind::kHit},
                         {DegToRad(-6.0), 0.4, ReadingKind::kBlind}}),
                kFacingNorth);
  const auto world = [](double bearing_deg, double range) {
    const double b = DegToRad(bearing_deg);
    return kFacingNorth * Eigen::Vector2d(range * std::cos(b), range * std::sin(b));
  };
  int occupied = 0;
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) occupied += grid.State({x, y}) == CellState::kOccupied ? 1 : 0;
  }
  EXPECT_EQ(occupied, 2);
  for (const double range : {0.2, 0.3, 0.38}) {
    const Eigen::Vector2d p = world(0.0, range);
    EXPECT_NEAR(grid.Probability(At(grid, p.x(), p.y())), 0.4, 1e-6) << range;
  }
  const Eigen::Vector2d unfilled = world(-4.0, 0.3);
  EXPECT_FALSE(grid.Known(At(grid, unfilled.x(), unfilled.y())));
}

// The ideal model computed cell by cell, independently of InsertProfile's
// traversal: a segment passes through a cell when its clip against the cell's
// square (Liang–Barsky) has positive length. Returns the probability every
// cell of `g` should hold after one frame on a fresh grid.
std::vector<double> IdealFrame(const GridGeometry& g, const ObstacleProfile& profile,
                               const Pose2& pose) {
  const auto crosses = [](const Eigen::Vector2d& p, const Eigen::Vector2d& q, int x, int y) {
    double t0 = 0.0;
    double t1 = 1.0;
    const Eigen::Vector2d d = q - p;
    for (int axis = 0; axis < 2; ++axis) {
      const double lo = axis == 0 ? x : y;
      if (d[axis] == 0.0) {
        if (p[axis] <= lo || p[axis] >= lo + 1.0) return false;
        continue;
      }
      double a = (lo - p[axis]) / d[axis];
      double b = (lo + 1.0 - p[axis]) / d[axis];
      if (a > b) std::swap(a, b);
      t0 = std::max(t0, a);
      t1 = std::min(t1, b);
    }
    return t1 - t0 > 1e-9;
  };
  enum Mark { kNone, kMiss, kBlind, kHit };
  std::vector<Mark> marks(g.CellCount(), kNone);
  const Eigen::Vector2d p = (pose.translation() - g.origin()) / g.resolution();
  // In the order of precedence: hits, blind areas, misses.
  for (const ReadingKind pass : {ReadingKind::kHit, ReadingKind::kBlind, ReadingKind::kClear}) {
    for (const auto& r : profile.readings) {
      if (r.kind != pass && !(pass == ReadingKind::kClear && r.kind == ReadingKind::kHit)) continue;
      const Eigen::Vector2d end_world = pose * Eigen::Vector2d(r.range_m * std::cos(r.bearing_rad),
                                                               r.range_m * std::sin(r.bearing_rad));
      const Eigen::Vector2d q = (end_world - g.origin()) / g.resolution();
      const CellIndex end = g.CellOf(end_world);
      if (pass == ReadingKind::kHit) {
        if (marks[g.Flat(end)] == kNone) marks[g.Flat(end)] = kHit;
        continue;
      }
      const Mark mark = pass == ReadingKind::kBlind ? kBlind : kMiss;
      for (int y = std::min(end.y, g.CellOf(pose.translation()).y) - 1;
           y <= std::max(end.y, g.CellOf(pose.translation()).y) + 1; ++y) {
        for (int x = std::min(end.x, g.CellOf(pose.translation()).x) - 1;
             x <= std::max(end.x, g.CellOf(pose.translation()).x) + 1; ++x) {
          const bool is_end = CellIndex{x, y} == end;
          if (is_end && r.kind == ReadingKind::kHit) continue;
          if (!is_end && !crosses(p, q, x, y)) continue;
          if (marks[g.Flat({x, y})] == kNone) marks[g.Flat({x, y})] = mark;
        }
      }
    }
  }
  std::vector<double> probabilities;
  probabilities.reserve(marks.size());
  for (const Mark m : marks) {
    probabilities.push_back(m == kHit ? 0.7 : m == kBlind ? 0.6 : m == kMiss ? 0.4 : 0.5);
  }
  return probabilities;
}

TEST(InsertProfile, MatchesTheIdealModelCellForCell) {
  // Frames like the paper's camera's: 320 columns over 60°, runs of hits at
  // changing ranges, clear runs and blind patches, from fixed seeds; and a
  // full circle. InsertProfile walks only the parts of rays its neighbours
  // have not covered; the result must be the same as every ray walked whole.
  std::mt19937 random(7);
  const auto uniform = [&random](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(random()) / 4294967296.0;
  };
  for (int frame = 0; frame < 8; ++frame) {
    const GridGeometry geometry(kCell, {-0.6, -0.6}, 120, 120);
    OccupancyGrid grid(geometry);
    const Pose2 pose(uniform(-0.05, 0.05), uniform(-0.05, 0.05), uniform(-3.0, 3.0));
    const int columns = frame == 7 ? 1920 : 320;
    const double field_deg = frame == 7 ? 360.0 : 60.0;
    ObstacleProfile profile{{}, 0.4};
    int column = 0;
    while (column < columns) {
      const int run = 5 + static_cast<int>(uniform(0.0, 60.0));
      const double kind = uniform(0.0, 1.0);
      const double near = uniform(0.05, 0.4);
      const double slope = uniform(-0.004, 0.004);
      for (int i = 0; i < run && column < columns; ++i, ++column) {
        const double bearing = DegToRad(field_deg / 2 - field_deg * (column + 0.5) / columns);
        if (kind < 0.55) {
          profile.readings.push_back(
              {bearing, std::clamp(near + slope * i, 0.02, 0.399), ReadingKind::kHit});
        } else if (kind < 0.85) {
          profile.readings.push_back({bearing, 0.4, ReadingKind::kClear});
        } else {
          profile.readings.push_back({bearing, near / 3, ReadingKind::kBlind});
        }
      }
    }
    const std::size_t applied = InsertProfile(grid, profile, pose);
    ASSERT_EQ(grid.geometry(), geometry);  // no growth: the frame fits
    const std::vector<double> ideal = IdealFrame(geometry, profile, pose);
    std::size_t touched = 0;
    int wrong = 0;
    for (std::size_t i = 0; i < ideal.size(); ++i) {
      const CellIndex c = geometry.Unflat(i);
      touched += ideal[i] != 0.5 ? 1 : 0;
      if (std::abs(grid.Probability(c) - ideal[i]) > 1e-6 && ++wrong <= 5) {
        ADD_FAILURE() << "frame " << frame << " cell " << c.x << ", " << c.y << ": "
                      << grid.Probability(c) << " instead of " << ideal[i];
      }
    }
    EXPECT_EQ(wrong, 0) << "frame " << frame;
    EXPECT_EQ(applied, touched) << "frame " << frame;
  }
}

TEST(InsertProfile, GrowsTheGridToCoverTheFrame) {
  OccupancyGrid grid(GridGeometry(kCell, {0.0, 0.0}, 10, 10));
  grid.BeginFrame();
  ASSERT_TRUE(grid.Apply({8, 1}, CellUpdate::kHit));  // off the ray below
  const Eigen::Vector2d marked = grid.geometry().CellCentre({8, 1});
  const Pose2 pose(0.05, 0.05, DegToRad(200.0));
  InsertProfile(grid, Profile({{0.0, 0.35, ReadingKind::kHit}}), pose);
  const Eigen::Vector2d end = pose * Eigen::Vector2d(0.35, 0.0);
  EXPECT_EQ(grid.State(grid.geometry().CellOf(end)), CellState::kOccupied);
  EXPECT_NEAR(grid.Probability(grid.geometry().CellOf(marked)), 0.7, 1e-6);
  EXPECT_LT(grid.geometry().origin().x(), end.x());
  EXPECT_LT(grid.geometry().origin().y(), end.y());
}

TEST(InsertProfile, RefusesBadReadings) {
  OccupancyGrid grid = MetreGrid();
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  EXPECT_THROW(InsertProfile(grid, Profile({{nan, 0.1, ReadingKind::kHit}}), kFacingNorth),
               std::invalid_argument);
  EXPECT_THROW(InsertProfile(grid, Profile({{0.0, inf, ReadingKind::kClear}}), kFacingNorth),
               std::invalid_argument);
  EXPECT_THROW(InsertProfile(grid, Profile({{0.0, -0.1, ReadingKind::kHit}}), kFacingNorth),
               std::invalid_argument);
  EXPECT_EQ(InsertProfile(grid, Profile({}), kFacingNorth), 0U);
}

TEST(MarkFootprintFree, FreesTheDiscOnly) {
  OccupancyGrid grid = MetreGrid();
  InsertProfile(grid, Profile({{0.0, 0.1, ReadingKind::kBlind}}), kFacingNorth);
  const Eigen::Vector2d centre(0.005, 0.005);
  MarkFootprintFree(grid, centre, 0.04);
  const GridGeometry& g = grid.geometry();
  for (int y = 0; y < 100; ++y) {
    for (int x = 0; x < 100; ++x) {
      const double d = (g.CellCentre({x, y}) - centre).norm();
      if (d <= 0.04) {
        EXPECT_EQ(grid.State({x, y}), CellState::kFree);
      } else if (d > 0.041 && !(x == 50 && y > 50 && y <= 60)) {
        EXPECT_FALSE(grid.Known({x, y})) << x << ", " << y;
      }
    }
  }
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.085)), 0.6, 1e-6);  // the blind area beyond
  EXPECT_THROW(MarkFootprintFree(grid, centre, -0.01), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::mapping
