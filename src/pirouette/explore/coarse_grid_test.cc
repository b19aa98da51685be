#include "pirouette/explore/coarse_grid.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <deque>
#include <string>
#include <vector>

#include "pirouette/explore/configuration_space.h"
#include "pirouette/testing/test_grids.h"
#include "pirouette/testing/world_raster.h"

namespace pirouette::explore {
namespace {

using mapping::CellState;

using testing::MapPicture;

TEST(CoarseGridTest, BlockedBeatsUnknownBeatsFree) {
  const mapping::TrinaryMap map = MapPicture({
      "..??.",
      "..#?.",
      ".....",
      "....?",
  });
  const CoarseGrid grid = CoarseGrid::FromConfigurationSpace(map, 2);
  ASSERT_EQ(grid.width(), 3);
  ASSERT_EQ(grid.height(), 2);
  EXPECT_EQ(grid.At({0, 0}), CoarseCell::kFree);
  EXPECT_EQ(grid.At({1, 0}), CoarseCell::kFree);
  EXPECT_EQ(grid.At({2, 0}), CoarseCell::kGoal);  // hangs over the right edge; one unknown
  EXPECT_EQ(grid.At({0, 1}), CoarseCell::kFree);
  EXPECT_EQ(grid.At({1, 1}), CoarseCell::kBlocked);  // one occupied beats the unknown
  EXPECT_EQ(grid.At({2, 1}), CoarseCell::kFree);
}

TEST(CoarseGridTest, GeometryIsKTimesCoarserWithTheMapOrigin) {
  const mapping::TrinaryMap map =
      MapPicture(std::vector<std::string>(7, "........."), 0.01, Eigen::Vector2d(-0.12, 0.33));
  const CoarseGrid grid = CoarseGrid::FromConfigurationSpace(map, 3);
  EXPECT_DOUBLE_EQ(grid.geometry().resolution(), 0.03);
  // -12 cells and 33 cells are multiples of 3: the map's origin is on the lattice.
  EXPECT_NEAR(grid.geometry().origin().x(), -0.12, 1e-12);
  EXPECT_NEAR(grid.geometry().origin().y(), 0.33, 1e-12);
  EXPECT_EQ(grid.width(), 3);
  EXPECT_EQ(grid.height(), 3);
}

TEST(CoarseGridTest, CellsStayOnTheWorldLatticeWhenTheMapGrows) {
  // The same floor, once on a map from (0, 0) and once on one grown by 2
  // cells to the left and 1 below: the coarse cells cover the same floor.
  const mapping::TrinaryMap small = MapPicture(
      {
          "......",
          "...#..",
          "......",
          "?.....",
      },
      0.01);
  const mapping::TrinaryMap grown = MapPicture(
      {
          "????????",
          "????????",
          "??......",
          "??...#..",
          "??......",
          "???.....",
          "????????",
      },
      0.01, Eigen::Vector2d(-0.02, -0.01));
  const CoarseGrid a = CoarseGrid::FromConfigurationSpace(small, 3);
  const CoarseGrid b = CoarseGrid::FromConfigurationSpace(grown, 3);
  EXPECT_NEAR(b.geometry().origin().x(), -0.03, 1e-12);
  EXPECT_NEAR(b.geometry().origin().y(), -0.03, 1e-12);
  const Eigen::Vector2d obstacle(0.035, 0.025);
  EXPECT_EQ(a.geometry().CellCentre(a.geometry().CellOf(obstacle)),
            b.geometry().CellCentre(b.geometry().CellOf(obstacle)));
  EXPECT_EQ(a.At(a.geometry().CellOf(obstacle)), CoarseCell::kBlocked);
  EXPECT_EQ(b.At(b.geometry().CellOf(obstacle)), CoarseCell::kBlocked);
}

TEST(CoarseGridTest, OffLatticeOriginStartsAtTheMapOrigin) {
  const mapping::TrinaryMap map =
      MapPicture(std::vector<std::string>(4, "....."), 0.01, Eigen::Vector2d(0.0042, 0.0));
  const CoarseGrid grid = CoarseGrid::FromConfigurationSpace(map, 2);
  EXPECT_EQ(grid.geometry().origin(), Eigen::Vector2d(0.0042, 0.0));
  EXPECT_EQ(grid.width(), 3);
}

TEST(CoarseGridTest, FactorOneKeepsTheMap) {
  const mapping::TrinaryMap map = MapPicture({"#.?", "?.#"});
  const CoarseGrid grid = CoarseGrid::FromConfigurationSpace(map, 1);
  EXPECT_EQ(grid.geometry(), map.geometry);
  const std::vector<CoarseCell> expected = {CoarseCell::kGoal,    CoarseCell::kFree,
                                            CoarseCell::kBlocked, CoarseCell::kBlocked,
                                            CoarseCell::kFree,    CoarseCell::kGoal};
  EXPECT_EQ(grid.cells(), expected);
}

TEST(CoarseGridTest, RejectsBadInput) {
  const mapping::TrinaryMap map = MapPicture({"..", ".."});
  EXPECT_THROW(CoarseGrid::FromConfigurationSpace(map, 0), std::invalid_argument);
  EXPECT_THROW(CoarseGrid(core::GridGeometry(1.0, {0, 0}, 2, 2), {CoarseCell::kFree}),
               std::invalid_argument);
  EXPECT_THROW(DefaultCoarseFactor(0.0, 0.01), std::invalid_argument);
  EXPECT_THROW(DefaultCoarseFactor(0.04, -1.0), std::invalid_argument);
}

TEST(CoarseGridTest, DefaultFactorIsHalfTheRadius) {
  EXPECT_EQ(DefaultCoarseFactor(0.04, 0.01), 2);
  EXPECT_EQ(DefaultCoarseFactor(0.15, 0.02), 3);
  EXPECT_EQ(DefaultCoarseFactor(0.15, 0.0375), 2);
  EXPECT_EQ(DefaultCoarseFactor(0.04, 0.02), 1);
  EXPECT_EQ(DefaultCoarseFactor(0.04, 0.001), 20);
}

// Map cells reached from `start` over cells free in configuration space,
// 8-connected.
std::vector<bool> FineReach(const mapping::TrinaryMap& cspace, const Eigen::Vector2d& start) {
  const core::GridGeometry& g = cspace.geometry;
  std::vector<bool> seen(g.CellCount(), false);
  std::deque<core::CellIndex> queue;
  const core::CellIndex s = g.CellOf(start);
  if (cspace.At(s) == CellState::kFree) {
    seen[g.Flat(s)] = true;
    queue.push_back(s);
  }
  while (!queue.empty()) {
    const core::CellIndex c = queue.front();
    queue.pop_front();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const core::CellIndex n{c.x + dx, c.y + dy};
        if (!g.Contains(n) || seen[g.Flat(n)] || cspace.At(n) != CellState::kFree) continue;
        seen[g.Flat(n)] = true;
        queue.push_back(n);
      }
    }
  }
  return seen;
}

// Coarse cells reached over kFree cells from the start's cell (or its free
// neighbours, as SteepestDescent starts), 8-connected.
std::vector<bool> CoarseReach(const CoarseGrid& grid, const Eigen::Vector2d& start) {
  const core::GridGeometry& g = grid.geometry();
  std::vector<bool> seen(g.CellCount(), false);
  std::deque<core::CellIndex> queue;
  const core::CellIndex s = g.CellOf(start);
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const core::CellIndex n{s.x + dx, s.y + dy};
      if ((grid.At(s) == CoarseCell::kFree) != (n == s)) continue;
      if (g.Contains(n) && grid.At(n) == CoarseCell::kFree && !seen[g.Flat(n)]) {
        seen[g.Flat(n)] = true;
        queue.push_back(n);
      }
    }
  }
  while (!queue.empty()) {
    const core::CellIndex c = queue.front();
    queue.pop_front();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const core::CellIndex n{c.x + dx, c.y + dy};
        if (!g.Contains(n) || seen[g.Flat(n)] || grid.At(n) != CoarseCell::kFree) continue;
        seen[g.Flat(n)] = true;
        queue.push_back(n);
      }
    }
  }
  return seen;
}

// The largest distance (in map cells, 8-connected steps) from a map cell the
// robot's centre can reach to the nearest map cell of a coarse cell the
// planner can reach; a doorway closed on the coarse grid cuts off a room and
// makes it large.
int LargestCutOff(const testing::RasterWorld& world, int factor) {
  const mapping::TrinaryMap cspace = MakeConfigurationSpace(world.map, world.robot_radius_m);
  const CoarseGrid grid = CoarseGrid::FromConfigurationSpace(cspace, factor);
  const std::vector<bool> fine = FineReach(cspace, world.start);
  const std::vector<bool> coarse = CoarseReach(grid, world.start);
  const core::GridGeometry& g = cspace.geometry;
  std::vector<int> distance(g.CellCount(), -1);
  std::deque<core::CellIndex> queue;
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const core::CellIndex c = grid.geometry().CellOf(g.CellCentre({x, y}));
      if (coarse[grid.geometry().Flat(c)]) {
        distance[g.Flat({x, y})] = 0;
        queue.push_back({x, y});
      }
    }
  }
  while (!queue.empty()) {
    const core::CellIndex c = queue.front();
    queue.pop_front();
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const core::CellIndex n{c.x + dx, c.y + dy};
        if (!g.Contains(n) || distance[g.Flat(n)] >= 0) continue;
        distance[g.Flat(n)] = distance[g.Flat(c)] + 1;
        queue.push_back(n);
      }
    }
  }
  int largest = 0;
  int reached = 0;
  for (std::size_t i = 0; i < fine.size(); ++i) {
    if (!fine[i]) continue;
    ++reached;
    largest = std::max(largest, distance[i]);
  }
  EXPECT_GT(reached, 100);
  return largest;
}

struct WorldCase {
  std::string file;
  double resolution_m;
};

class ShippedWorldTest : public ::testing::TestWithParam<WorldCase> {};

// With the default coarse factor, every doorway, corridor and gap between
// furniture of the shipped worlds stays open, at 2k alignments of the world
// on the coarse lattice: all the floor the robot can reach lies within
// two coarse cells (the corners and nooks a coarse cell does not fit in) of
// the coarse cells the planner can reach.
TEST_P(ShippedWorldTest, DefaultCoarseFactorPassesEveryDoorway) {
  const WorldCase& c = GetParam();
  const double radius = testing::RasteriseWorld(c.file, 0.05, 1).robot_radius_m;
  const int k = DefaultCoarseFactor(radius, c.resolution_m);
  // Every shift in x, each with two in y (k² of them would be slow).
  for (int sx = 0; sx < k; ++sx) {
    for (const int sy : {sx, (sx + k / 2) % k}) {
      const testing::RasterWorld world = testing::RasteriseWorld(
          c.file, c.resolution_m, 3 * k, c.resolution_m * Eigen::Vector2d(sx, sy));
      EXPECT_LE(LargestCutOff(world, k), 2 * k)
          << c.file << " at " << c.resolution_m << " m, k = " << k << ", shifted " << sx << ", "
          << sy;
    }
  }
}

// The check has teeth: a coarse cell of twice the robot's radius closes the
// apartment's doors and the cluttered room's gaps.
TEST(CoarseGridTest, TooCoarseAGridClosesDoorways) {
  const testing::RasterWorld apartment = testing::RasteriseWorld("apartment.yaml", 0.05, 3);
  EXPECT_GT(LargestCutOff(apartment, 6), 12);
  const testing::RasterWorld clutter = testing::RasteriseWorld("cluttered_room.yaml", 0.01, 3);
  EXPECT_GT(LargestCutOff(clutter, 8), 16);
}

// The loop's map cells (1 cm for the 4 cm robot, 2 cm for the apartment's)
// and a quarter of the radius.
INSTANTIATE_TEST_SUITE_P(
    Worlds, ShippedWorldTest,
    ::testing::Values(WorldCase{"soccer_field.yaml", 0.01}, WorldCase{"two_rooms.yaml", 0.01},
                      WorldCase{"maze.yaml", 0.01}, WorldCase{"cluttered_room.yaml", 0.01},
                      WorldCase{"apartment.yaml", 0.02}, WorldCase{"apartment.yaml", 0.0375},
                      WorldCase{"cluttered_room.yaml", 0.005}),
    [](const auto& info) {
      std::string name = info.param.file.substr(0, info.param.file.find('.'));
      return name + "_" + std::to_string(info.index);
    });

}  // namespace
}  // namespace pirouette::explore
