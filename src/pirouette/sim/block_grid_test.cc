#include "pirouette/sim/block_grid.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "pirouette/sim/seeded_random.h"

// Its own namespace: the unit tests compile together (unity batches).
namespace pirouette::sim::block_grid_test {
namespace {

// A grid from rows of text, the first line the top row: '#' a block.
BlockGrid FromText(const std::vector<std::string>& rows, double resolution = 0.05,
                   Eigen::Vector2d origin = Eigen::Vector2d::Zero()) {
  const int height = static_cast<int>(rows.size());
  const int width = static_cast<int>(rows[0].size());
  BlockGrid grid{core::GridGeometry(resolution, origin, width, height), {}};
  grid.solid.resize(grid.geometry.CellCount(), 0);
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      grid.solid[grid.geometry.Flat({x, y})] = rows[height - 1 - y][x] == '#' ? 1 : 0;
    }
  }
  return grid;
}

bool InsideAny(const std::vector<Solid>& solids, const Eigen::Vector2d& p) {
  for (const Solid& solid : solids) {
    if (solid.SignedDistance(p) < 0.0) return true;
  }
  return false;
}

TEST(BlockGridTest, BoxesCoverExactlyTheBlocks) {
  SeededRandom random(11);
  BlockGrid grid{core::GridGeometry(0.05, {1.0, -2.0}, 37, 23), {}};
  for (std::size_t i = 0; i < grid.geometry.CellCount(); ++i) {
    grid.solid.push_back(random.Uniform(0.0, 1.0) < 0.4 ? 1 : 0);
  }
  // Whole rows of blocks, which merge into one box.
  for (int x = 0; x < 37; ++x) {
    for (int y = 10; y < 14; ++y) grid.solid[grid.geometry.Flat({x, y})] = 1;
  }
  const std::vector<Solid> solids = BlockGridSolids(grid, 0.3, {10, 20, 30});
  EXPECT_LT(solids.size(), grid.SolidCount());
  for (const Solid& solid : solids) {
    EXPECT_EQ(solid.kind, Solid::Kind::kGridBlock);
    EXPECT_EQ(solid.height, 0.3);
    EXPECT_EQ(solid.footprint.size(), 4U);
  }
  for (int y = 0; y < 23; ++y) {
    for (int x = 0; x < 37; ++x) {
      const Eigen::Vector2d centre = grid.geometry.CellCentre({x, y});
      EXPECT_EQ(InsideAny(solids, centre), grid.IsSolid({x, y})) << x << ", " << y;
    }
  }
}

TEST(BlockGridTest, ARoomsWallIsFourBoxes) {
  const BlockGrid grid = FromText({"######",  //
                                   "#....#",  //
                                   "#....#",  //
                                   "######"});
  EXPECT_EQ(BlockGridSolids(grid, 0.5, {}).size(), 4U);
}

TEST(BlockGridTest, RefusesABadGridOrHeight) {
  BlockGrid grid = FromText({"#."});
  EXPECT_THROW(BlockGridSolids(grid, 0.0, {}), std::invalid_argument);
  grid.solid.pop_back();
  EXPECT_THROW(BlockGridSolids(grid, 1.0, {}), std::invalid_argument);
}

TEST(BlockGridTest, ClearanceIsTheDistanceToTheNearestBlockOrTheEdge) {
  const BlockGrid grid = FromText({".......",  //
                                   "...#...",  //
                                   "......."});
  const std::vector<double> clearance = CellClearance(grid);
  const auto at = [&](int x, int y) { return clearance[grid.geometry.Flat({x, y})]; };
  EXPECT_EQ(at(3, 1), 0.0);
  EXPECT_NEAR(at(4, 1), 0.025, 1e-6);  // beside the block: half a cell
  EXPECT_NEAR(at(0, 1), 0.025, 1e-6);  // beside the grid's edge
  EXPECT_NEAR(at(6, 1), 0.025, 1e-6);  // beside the other edge
  EXPECT_NEAR(at(5, 1), 0.075, 1e-6);  // 1.5 cells from the block's and the edge's faces
}

TEST(BlockGridTest, TheStartIsInTheLargestRegionFarthestFromItsWalls) {
  // A small room (left) and a larger one (right), apart.
  std::vector<std::string> rows;
  rows.emplace_back(40, '#');
  for (int i = 0; i < 12; ++i)
    rows.push_back("#" + std::string(8, '.') + "#" + std::string(29, '.') + "#");
  rows.emplace_back(40, '#');
  const BlockGrid grid = FromText(rows, 0.05);
  const std::optional<Eigen::Vector2d> start = ChooseGridStart(grid, 0.12);
  ASSERT_TRUE(start.has_value());
  EXPECT_GT(start->x(), 10 * 0.05);      // in the right-hand room
  EXPECT_NEAR(start->y(), 0.35, 0.051);  // midway between its walls
  // A disc that fits nowhere.
  EXPECT_FALSE(ChooseGridStart(grid, 1.0).has_value());
}

TEST(BlockGridTest, SealingClosesAGapNarrowerThanTheRobotAndKeepsAWiderOne) {
  // Two rooms joined by a wall with a 2-cell gap (10 cm) at the top and a
  // 7-cell gap (35 cm) at the bottom; a speck in the left room.
  std::vector<std::string> rows;
  rows.emplace_back(41, '#');
  for (int i = 0; i < 20; ++i) {
    std::string row = "#" + std::string(19, '.') + "#" + std::string(19, '.') + "#";
    rows.push_back(row);
  }
  rows.emplace_back(41, '#');
  // rows[1] is the top row inside; gaps in column 20.
  rows[3][20] = '.';
  rows[4][20] = '.';
  for (int i = 12; i < 19; ++i) rows[i][20] = '.';
  rows[10][8] = '#';  // the speck
  const BlockGrid grid = FromText(rows, 0.05);
  const double radius = 0.1;
  const BlockGrid sealed = SealUnreachable(grid, radius, {0.5, 0.5});
  const int height = static_cast<int>(rows.size());
  const auto cell = [&](int column, int text_row) {
    return core::CellIndex{column, height - 1 - text_row};
  };
  EXPECT_TRUE(sealed.IsSolid(cell(20, 3)));  // the narrow gap: closed
  EXPECT_TRUE(sealed.IsSolid(cell(20, 4)));
  EXPECT_FALSE(sealed.IsSolid(cell(20, 15)));  // the wide one: open
  EXPECT_TRUE(sealed.IsSolid(cell(8, 10)));    // the speck: kept
  EXPECT_FALSE(sealed.IsSolid(cell(30, 10)));  // the far room: reachable
  EXPECT_TRUE(sealed.IsSolid(cell(1, 1)));     // a corner the disc cannot sweep
  EXPECT_FALSE(sealed.IsSolid(cell(10, 1)));   // beside a straight wall: swept
}

TEST(BlockGridTest, SealingWithoutAFittingStartChangesNothing) {
  const BlockGrid grid = FromText({"#####",  //
                                   "#...#",  //
                                   "#####"});
  EXPECT_EQ(SealUnreachable(grid, 0.1, {0.1, 0.07}).solid, grid.solid);
}

}  // namespace
}  // namespace pirouette::sim::block_grid_test
