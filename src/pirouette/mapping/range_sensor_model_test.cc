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
  return {readings, 0.4, {}};
}

// The grid cell of a world point, which must be on the grid.
CellIndex At(const OccupancyGrid& grid, double x, double y) {
  const auto c = grid.geometry().CellAt({x, y});
  EXPECT_TRUE(c.has_value()) << x << ", " << y;
  return c.value_or(CellIndex{});
}

// The cell holding a point given in cell units (as the sensor model floors it).
CellIndex CellOfCellUnits(const GridGeometry& /*g*/, const Eigen::Vector2d& q) {
  return {static_cast<int>(std::floor(q.x())), static_cast<int>(std::floor(q.y()))};
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

TEST(InsertProfile, BlindReadingStopsAtAWallTheMapHolds) {
  // A robot beside a thin wall it mapped from afar: its view is filled, the
  // base of what fills it under the camera. The floor beyond the wall stays
  // unknown, for the robot to see when it gets there.
  OccupancyGrid grid = MetreGrid();
  InsertProfile(grid, Profile({{0.0, 0.05, ReadingKind::kHit}}), kFacingNorth);
  ASSERT_EQ(grid.State(At(grid, 0.005, 0.055)), CellState::kOccupied);
  InsertProfile(grid, Profile({{0.0, 0.12, ReadingKind::kBlind}}), kFacingNorth);
  EXPECT_EQ(grid.State(At(grid, 0.005, 0.055)), CellState::kOccupied);
  for (int i = 6; i <= 12; ++i) EXPECT_FALSE(grid.Known(At(grid, 0.005, 0.005 + i * kCell))) << i;
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

TEST(InsertProfile, AFootIsAHitThatWinsOverTheColumnsMisses) {
  // A column clear to 0.3 m (the floor seen to a side's edge) and the foot of
  // that side at 0.1 m on a bearing of its own: the foot's cell is occupied,
  // the cells before it free, and the column free on past it.
  OccupancyGrid grid = MetreGrid();
  ObstacleProfile profile = Profile({{0.0, 0.3, ReadingKind::kClear}});
  profile.feet = {{0.0, 0.1, ReadingKind::kHit}, {DegToRad(-90.0), 0.2, ReadingKind::kHit}};
  InsertProfile(grid, profile, kFacingNorth);
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.105)), 0.7, 1e-6);
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.095)), 0.4, 1e-6);
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.205)), 0.4, 1e-6);
  // The second foot, to the right (east): a hit with its own free ray.
  EXPECT_NEAR(grid.Probability(At(grid, 0.205, 0.005)), 0.7, 1e-6);
  EXPECT_NEAR(grid.Probability(At(grid, 0.105, 0.005)), 0.4, 1e-6);
  // No fill between a foot and the column: the wedge between them is unknown.
  EXPECT_FALSE(grid.Known(At(grid, 0.105, 0.105)));
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
  // The blind area stops at the hit: what fills the view stands in front of it.
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.085)), 0.4, 1e-6);
  EXPECT_NEAR(grid.Probability(At(grid, 0.005, 0.155)), 0.4, 1e-6);  // beyond the blind area
}

TEST(InsertProfile, ACellCrossedByManyRaysChangesOnce) {
  OccupancyGrid grid = MetreGrid();
  ObstacleProfile profile{{}, 0.4, {}};
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
  ObstacleProfile profile{{}, 0.4, {}};
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
  ObstacleProfile profile{{}, 1.2, {}};
  for (int i = 0; i <= 180; ++i) {  // the last closes the circle
    const double bearing = DegToRad(-2.0 * i);
    profile.readings.push_back({bearing, range(bearing), ReadingKind::kHit});
  }
  InsertProfile(grid, profile, pose);
  const int cells = ExpectSweptDisc(grid, pose.translation(), 0.8 - kCell);
  EXPECT_GT(cells, 19000);
  // Without the fill (readings farther apart than kMaxFillGapRad) there are holes.
  OccupancyGrid sparse(GridGeometry(kCell, {-1.5, -1.5}, 300, 300));
  ObstacleProfile sparse_profile{{}, 1.2, {}};
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

// Where the segment p→q (cell units) enters cell (x, y), as a fraction of
// the segment, when it passes through the cell (its clip against the cell's
// square, Liang–Barsky, has positive length); -1 when it does not.
double Entry(const Eigen::Vector2d& p, const Eigen::Vector2d& q, int x, int y) {
  double t0 = 0.0;
  double t1 = 1.0;
  const Eigen::Vector2d d = q - p;
  for (int axis = 0; axis < 2; ++axis) {
    const double lo = axis == 0 ? x : y;
    if (d[axis] == 0.0) {
      if (p[axis] <= lo || p[axis] >= lo + 1.0) return -1.0;
      continue;
    }
    double a = (lo - p[axis]) / d[axis];
    double b = (lo + 1.0 - p[axis]) / d[axis];
    if (a > b) std::swap(a, b);
    t0 = std::max(t0, a);
    t1 = std::min(t1, b);
  }
  return t1 - t0 > 1e-9 ? t0 : -1.0;
}

// The ideal model computed cell by cell, independently of InsertProfile's
// traversal: a segment passes through a cell when its clip against the cell's
// square (Liang–Barsky) has positive length (Entry). Each hit or clear ray
// that enters a cell solid in `before` more than three cells short of its
// end stops just before it, with no hit at its end. Returns the log-odds
// every cell of `before` (the grid before the frame) should hold after it.
std::vector<double> IdealFrameOn(const OccupancyGrid& before, const ObstacleProfile& profile,
                                 const Pose2& pose) {
  const GridGeometry& g = before.geometry();

  enum Mark { kNone, kMiss, kBlind, kHit };
  const double hit = std::log(0.7 / 0.3);
  std::vector<Mark> marks(g.CellCount(), kNone);
  const Eigen::Vector2d p = (pose.translation() - g.origin()) / g.resolution();
  const CellIndex robot = g.CellOf(pose.translation());
  const auto box = [&](const CellIndex& end, auto&& each) {
    for (int y = std::min(end.y, robot.y) - 1; y <= std::max(end.y, robot.y) + 1; ++y) {
      for (int x = std::min(end.x, robot.x) - 1; x <= std::max(end.x, robot.x) + 1; ++x) {
        if (g.Contains({x, y})) each(x, y);
      }
    }
  };
  // Each non-blind reading's segment in cell units, cut at its first solid
  // cell, and whether it still ends in a hit.
  struct Cut {
    Eigen::Vector2d q;
    bool hit;
    bool cut;
  };
  std::vector<Cut> cuts;
  for (const auto& r : profile.readings) {
    const Eigen::Vector2d end_world = pose * Eigen::Vector2d(r.range_m * std::cos(r.bearing_rad),
                                                             r.range_m * std::sin(r.bearing_rad));
    Eigen::Vector2d q = (end_world - g.origin()) / g.resolution();
    const double length = (q - p).norm();
    double stop = std::numeric_limits<double>::infinity();
    if (r.kind != ReadingKind::kBlind) {
      box(g.CellOf(end_world), [&](int x, int y) {
        const double t = Entry(p, q, x, y);
        if (t >= 0.0 && t * length < length - 3.0 && before.Solid({x, y})) {
          stop = std::min(stop, t * length);
        }
      });
    }
    const bool cut = std::isfinite(stop);
    if (cut) q = p + (q - p) * (std::max(0.0, stop - 1e-6) / length);
    cuts.push_back({q, r.kind == ReadingKind::kHit && !cut, cut});
  }
  for (const ReadingKind pass : {ReadingKind::kHit, ReadingKind::kBlind, ReadingKind::kClear}) {
    for (std::size_t i = 0; i < profile.readings.size(); ++i) {
      const auto& r = profile.readings[i];
      const Cut& c = cuts[i];
      if (r.kind != pass && !(pass == ReadingKind::kClear && r.kind == ReadingKind::kHit)) continue;
      const CellIndex end = CellOfCellUnits(g, c.q);
      if (pass == ReadingKind::kHit) {
        if (c.hit && marks[g.Flat(end)] == kNone) marks[g.Flat(end)] = kHit;
        continue;
      }
      const Mark mark = pass == ReadingKind::kBlind ? kBlind : kMiss;
      // A blind ray stops just before the first cell occupied once the
      // frame's hits are in.
      double blind_stop = std::numeric_limits<double>::infinity();
      if (pass == ReadingKind::kBlind) {
        box(end, [&](int x, int y) {
          const double t = Entry(p, c.q, x, y);
          const double l = before.LogOdds({x, y}) + (marks[g.Flat({x, y})] == kHit ? hit : 0.0);
          const bool occupied = (before.Known({x, y}) || marks[g.Flat({x, y})] == kHit) &&
                                l > std::log(kOccupiedThreshold / (1.0 - kOccupiedThreshold));
          if (t >= 0.0 && occupied) blind_stop = std::min(blind_stop, t);
        });
      }
      box(end, [&](int x, int y) {
        const bool is_end = CellIndex{x, y} == end;
        if (is_end && c.hit) return;
        if (is_end && c.cut && (c.q - p).norm() == 0.0) return;
        const double t = Entry(p, c.q, x, y);
        if (!is_end && t < 0.0) return;
        if (std::isfinite(blind_stop) && !(t >= 0.0 && t < blind_stop)) return;
        if (marks[g.Flat({x, y})] == kNone) marks[g.Flat({x, y})] = mark;
      });
    }
  }
  const double miss = std::log(0.4 / 0.6);
  const double clamp_min = std::log(0.12 / 0.88);
  const double clamp_max = std::log(0.97 / 0.03);
  std::vector<double> log_odds;
  log_odds.reserve(marks.size());
  for (std::size_t i = 0; i < marks.size(); ++i) {
    const CellIndex c = g.Unflat(i);
    const double l = before.LogOdds(c);
    const bool known = before.Known(c);
    switch (marks[i]) {
      case kHit:
        log_odds.push_back(std::min(l + hit, clamp_max));
        break;
      case kMiss:
        log_odds.push_back(std::max(l + miss, clamp_min));
        break;
      case kBlind:
        log_odds.push_back(known ? l : std::log(0.6 / 0.4));
        break;
      case kNone:
        log_odds.push_back(l);
        break;
    }
  }
  return log_odds;
}

// IdealFrameOn a fresh grid of geometry `g`, as probabilities.
std::vector<double> IdealFrame(const GridGeometry& g, const ObstacleProfile& profile,
                               const Pose2& pose) {
  std::vector<double> cells = IdealFrameOn(OccupancyGrid(g), profile, pose);
  for (double& c : cells) c = LogOddsToProbability(c);
  return cells;
}

// A frame like the paper's camera's: `columns` readings over `field_deg`,
// runs of hits at changing ranges, clear runs out to max_range and blind
// patches, drawn by uniform(lo, hi).
template <class Uniform>
ObstacleProfile RandomFrame(Uniform& uniform, int columns, double field_deg, double max_range) {
  ObstacleProfile profile{{}, max_range, {}};
  int column = 0;
  while (column < columns) {
    const int run = 5 + static_cast<int>(uniform(0.0, 60.0));
    const double kind = uniform(0.0, 1.0);
    const double near = uniform(0.05, max_range);
    const double slope = uniform(-0.004, 0.004);
    for (int i = 0; i < run && column < columns; ++i, ++column) {
      const double bearing = DegToRad(field_deg / 2 - field_deg * (column + 0.5) / columns);
      if (kind < 0.55) {
        profile.readings.push_back(
            {bearing, std::clamp(near + slope * i, 0.02, max_range - 0.001), ReadingKind::kHit});
      } else if (kind < 0.85) {
        profile.readings.push_back({bearing, max_range, ReadingKind::kClear});
      } else {
        profile.readings.push_back({bearing, near / 3, ReadingKind::kBlind});
      }
    }
  }
  return profile;
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
    const ObstacleProfile profile = RandomFrame(uniform, columns, field_deg, 0.4);
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

// Makes cell c solid: hit to the clamp from two places far apart.
void MakeSolid(OccupancyGrid& grid, const CellIndex& c) {
  for (int i = 0; i < 6; ++i) {
    grid.BeginFrame(Eigen::Vector2d(i % 2 == 0 ? -10.0 : 10.0, 0.0));
    grid.Apply(c, CellUpdate::kHit);
  }
  ASSERT_TRUE(grid.Solid(c));
}

TEST(InsertProfile, ARayStopsAtASolidWallUnlessItEndsThere) {
  // A solid wall across x = 0.1 m; readings along +x (bearing -90° facing north).
  OccupancyGrid grid = MetreGrid();
  for (double y = -0.3; y <= 0.3; y += kCell) MakeSolid(grid, At(grid, 0.105, y));
  const double east = DegToRad(-90.0);
  // Seen through the wall to 0.3 m (a wall passing for floor): stops before it.
  InsertProfile(grid, Profile({{east, 0.3, ReadingKind::kHit}}), kFacingNorth);
  EXPECT_NEAR(grid.Probability(At(grid, 0.055, 0.005)), 0.4, 1e-6);  // one miss
  EXPECT_NEAR(grid.Probability(At(grid, 0.095, 0.005)), 0.4, 1e-6);
  EXPECT_TRUE(grid.Solid(At(grid, 0.105, 0.005)));   // untouched
  EXPECT_FALSE(grid.Known(At(grid, 0.2, 0.005)));    // nothing beyond
  EXPECT_FALSE(grid.Known(At(grid, 0.305, 0.005)));  // and no hit at the end
  // A reading of the wall itself, ending less than three cells beyond where
  // it enters the wall, runs on to its end: a range a cell or two long is
  // the wall's own.
  InsertProfile(grid, Profile({{east, 0.12, ReadingKind::kHit}}), kFacingNorth);
  EXPECT_FALSE(grid.Solid(At(grid, 0.105, 0.005)));  // took the miss
  EXPECT_EQ(grid.State(At(grid, 0.125, 0.005)), CellState::kOccupied);
  // A clear reading stops the same way.
  OccupancyGrid clear = MetreGrid();
  MakeSolid(clear, At(clear, 0.105, 0.005));
  InsertProfile(clear, Profile({{east, 0.4, ReadingKind::kClear}}), kFacingNorth);
  EXPECT_NEAR(clear.Probability(At(clear, 0.095, 0.005)), 0.4, 1e-6);
  EXPECT_FALSE(clear.Known(At(clear, 0.3, 0.005)));
}

TEST(InsertProfile, MatchesTheIdealModelWithSolidWallsCellForCell) {
  // Random frames as above over random solid wall segments: the walk that
  // skips what neighbouring rays covered must still stop each ray exactly
  // where a ray walked whole would.
  std::mt19937 random(11);
  const auto uniform = [&random](double lo, double hi) {
    return lo + (hi - lo) * static_cast<double>(random()) / 4294967296.0;
  };
  int shielded = 0;  // cells a frame would touch but for the walls
  for (int frame = 0; frame < 24; ++frame) {
    const GridGeometry geometry(kCell, {-0.6, -0.6}, 120, 120);
    OccupancyGrid grid(geometry);
    // Four walls solid; a fifth hit from two places but pulled off the
    // clamp by a miss (its blocks flagged, its cells not solid).
    for (int wall = 0; wall < 5; ++wall) {
      const double angle = uniform(-3.14, 3.14);
      const double range = uniform(0.08, 0.35);
      const Eigen::Vector2d centre(range * std::cos(angle), range * std::sin(angle));
      const Eigen::Vector2d along(-std::sin(angle + uniform(-0.6, 0.6)),
                                  std::cos(angle + uniform(-0.6, 0.6)));
      const double half = uniform(0.03, 0.2);
      for (double s = -half; s <= half; s += 0.5 * kCell) {
        const CellIndex c = geometry.CellOf(centre + s * along.normalized());
        if (grid.Solid(c)) continue;
        MakeSolid(grid, c);
        if (wall < 4) continue;
        grid.BeginFrame();
        grid.Apply(c, CellUpdate::kMiss);
        ASSERT_FALSE(grid.Solid(c));
      }
    }
    const OccupancyGrid before = grid;
    const Pose2 pose(uniform(-0.05, 0.05), uniform(-0.05, 0.05), uniform(-3.0, 3.0));
    const int columns = frame % 6 == 5 ? 1920 : 320;  // a full circle now and then
    const double field_deg = frame % 6 == 5 ? 360.0 : 60.0;
    const ObstacleProfile profile = RandomFrame(uniform, columns, field_deg, 0.45);
    InsertProfile(grid, profile, pose);
    ASSERT_EQ(grid.geometry(), geometry);
    const std::vector<double> ideal = IdealFrameOn(before, profile, pose);
    const std::vector<double> unshielded = IdealFrame(geometry, profile, pose);
    int wrong = 0;
    for (std::size_t i = 0; i < ideal.size(); ++i) {
      const CellIndex c = geometry.Unflat(i);
      if (unshielded[i] != 0.5 && !before.Known(c) && !grid.Known(c)) ++shielded;
      if (std::abs(grid.LogOdds(c) - ideal[i]) > 1e-4 && ++wrong <= 5) {
        ADD_FAILURE() << "frame " << frame << " cell " << c.x << ", " << c.y << ": "
                      << grid.LogOdds(c) << " instead of " << ideal[i];
      }
    }
    EXPECT_EQ(wrong, 0) << "frame " << frame;
  }
  EXPECT_GT(shielded, 1000);  // the walls were in the frames' way
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
