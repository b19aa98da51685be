#include "pirouette/explore/path.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <stdexcept>

#include "pirouette/testing/test_grids.h"

namespace pirouette::explore {
namespace {

using testing::Picture;
using testing::RandomGrid;
using testing::RandomMaze;
using testing::Spiral;

// Checks a descent: 8-connected steps, each down by its chamfer weight, all
// on free cells, ending next to a goal; the chamfer length is the start's
// distance.
void ExpectDescends(const CoarseGrid& grid, const DistanceField& field, const Path& path,
                    const core::CellIndex& start) {
  ASSERT_EQ(grid.At(path.goal), CoarseCell::kGoal);
  ASSERT_EQ(field.At(path.goal), 0);
  std::vector<core::CellIndex> cells = path.cells;
  cells.push_back(path.goal);
  if (field.At(start) < kUnreachable) {
    ASSERT_EQ(cells.front(), start);
  }
  for (std::size_t i = 0; i + 1 < cells.size(); ++i) {
    const core::CellIndex& a = cells[i];
    const core::CellIndex& b = cells[i + 1];
    ASSERT_EQ(grid.At(a), CoarseCell::kFree);
    const int dx = std::abs(a.x - b.x);
    const int dy = std::abs(a.y - b.y);
    ASSERT_TRUE(dx <= 1 && dy <= 1 && dx + dy > 0);
    const std::int32_t weight = dx + dy == 2 ? kChamferDiagonal : kChamferOrthogonal;
    ASSERT_EQ(field.At(a), field.At(b) + weight);  // strictly down, along a shortest path
  }
}

TEST(PathTest, DescendsFromEveryReachableCellOfRandomGridsAndMazes) {
  std::vector<CoarseGrid> grids;
  for (std::uint32_t seed = 1; seed <= 6; ++seed) {
    grids.push_back(RandomGrid(40, 30, 0.1 * static_cast<double>(seed % 5), 1 + seed, seed));
    grids.push_back(RandomMaze(6, 2, seed));
  }
  grids.push_back(Spiral(15, 2));
  for (const CoarseGrid& grid : grids) {
    const DistanceField field = ChamferDistanceTransform(grid);
    for (int y = 0; y < grid.height(); ++y) {
      for (int x = 0; x < grid.width(); ++x) {
        const std::optional<Path> path = SteepestDescent(grid, field, {x, y});
        const bool reachable = field.At({x, y}) < kUnreachable;
        if (reachable) {
          ASSERT_TRUE(path.has_value());
          ExpectDescends(grid, field, *path, {x, y});
        } else if (path) {
          // A blocked start: the descent starts from a reachable neighbour.
          ASSERT_EQ(grid.At({x, y}), CoarseCell::kBlocked);
          ExpectDescends(grid, field, *path, {x, y});
        }
      }
    }
  }
}

TEST(PathTest, StraightCorridorGivesAStraightPath) {
  const CoarseGrid grid = Picture({
      "#########",
      "G.......#",
      "#########",
  });
  const DistanceField field = ChamferDistanceTransform(grid);
  const std::optional<Path> path = SteepestDescent(grid, field, {7, 1});
  ASSERT_TRUE(path);
  ASSERT_EQ(path->cells.size(), 7U);
  for (std::size_t i = 0; i < 7; ++i) {
    EXPECT_EQ(path->cells[i], (core::CellIndex{7 - static_cast<int>(i), 1}));
  }
  EXPECT_EQ(path->goal, (core::CellIndex{0, 1}));
}

TEST(PathTest, OpenRoomGoesDiagonallyThenStraight) {
  const CoarseGrid grid = Picture({
      ".......",
      ".......",
      ".......",
      "G......",
  });
  const DistanceField field = ChamferDistanceTransform(grid);
  const std::optional<Path> path = SteepestDescent(grid, field, {6, 3});
  ASSERT_TRUE(path);
  // Three diagonal steps down-left (each lowers the distance most), then
  // straight left along the bottom row.
  const std::vector<core::CellIndex> expected = {{6, 3}, {5, 2}, {4, 1}, {3, 0}, {2, 0}, {1, 0}};
  EXPECT_EQ(path->cells, expected);
}

TEST(PathTest, StartOnAGoalGivesAnEmptyPath) {
  const CoarseGrid grid = Picture({"G.."});
  const DistanceField field = ChamferDistanceTransform(grid);
  const std::optional<Path> path = SteepestDescent(grid, field, {0, 0});
  ASSERT_TRUE(path);
  EXPECT_TRUE(path->cells.empty());
  EXPECT_EQ(path->goal, (core::CellIndex{0, 0}));
}

TEST(PathTest, BlockedStartStartsFromItsBestFreeNeighbour) {
  const CoarseGrid grid = Picture({
      "G....",
      "..##.",
      "..#..",
  });
  const DistanceField field = ChamferDistanceTransform(grid);
  // (2, 1) is blocked; of its neighbours (1, 2) is nearest the goal.
  const std::optional<Path> path = SteepestDescent(grid, field, {2, 1});
  ASSERT_TRUE(path);
  ASSERT_FALSE(path->cells.empty());
  EXPECT_EQ(path->cells.front(), (core::CellIndex{1, 2}));
  EXPECT_EQ(path->goal, (core::CellIndex{0, 2}));
}

TEST(PathTest, NoReachableGoalGivesNothing) {
  const CoarseGrid grid = Picture({
      "...#G",
      "...##",
      ".....",
  });
  const DistanceField field = ChamferDistanceTransform(grid);
  EXPECT_FALSE(SteepestDescent(grid, field, {0, 0}));
  EXPECT_FALSE(SteepestDescent(grid, field, {2, 1}));
  // A blocked cell next to the goal reaches it (and has nowhere to drive).
  const std::optional<Path> path = SteepestDescent(grid, field, {3, 1});
  ASSERT_TRUE(path);
  EXPECT_TRUE(path->cells.empty());
  EXPECT_EQ(path->goal, (core::CellIndex{4, 2}));
}

TEST(PathTest, StartOffTheGridThrows) {
  const CoarseGrid grid = Picture({"G.."});
  const DistanceField field = ChamferDistanceTransform(grid);
  EXPECT_THROW(SteepestDescent(grid, field, {3, 0}), std::out_of_range);
  EXPECT_THROW(SteepestDescent(grid, field, {0, -1}), std::out_of_range);
}

}  // namespace
}  // namespace pirouette::explore
