#include "pirouette/explore/distance_transform.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <string>
#include <vector>

#include "pirouette/testing/test_grids.h"

namespace pirouette::explore {
namespace {

using testing::DijkstraReference;
using testing::Distances;
using testing::Picture;
using testing::RandomGrid;
using testing::RandomMaze;
using testing::Spiral;

constexpr std::int32_t kU = kUnreachable;

const DistanceTransformOptions kSweeps{DistanceAlgorithm::kRasterSweeps};
const DistanceTransformOptions kBuckets{DistanceAlgorithm::kBucketQueue};

// Checks both algorithms against Dijkstra's on `grid`.
void ExpectExact(const CoarseGrid& grid, const std::string& what) {
  const std::vector<std::int32_t> reference = DijkstraReference(grid);
  const DistanceField sweeps = ChamferDistanceTransform(grid, kSweeps);
  const DistanceField buckets = ChamferDistanceTransform(grid, kBuckets);
  EXPECT_TRUE(sweeps.converged()) << what;
  EXPECT_EQ(Distances(sweeps), reference) << what;
  EXPECT_EQ(Distances(buckets), reference) << what;
}

TEST(DistanceTransformTest, ChamferWeightsAlongARowAndADiagonal) {
  for (const DistanceTransformOptions& options : {kSweeps, kBuckets}) {
    const DistanceField field = ChamferDistanceTransform(Picture({
                                                             "...#.",
                                                             "..#..",
                                                             "G....",
                                                         }),
                                                         options);
    // Row 0 (the picture's last line) from the goal at its left end.
    EXPECT_EQ(field.At({0, 0}), 0);
    EXPECT_EQ(field.At({1, 0}), 3);
    EXPECT_EQ(field.At({4, 0}), 12);
    EXPECT_EQ(field.At({1, 1}), 4);
    EXPECT_EQ(field.At({2, 2}), 8);   // two diagonal steps
    EXPECT_EQ(field.At({2, 1}), kU);  // blocked
    EXPECT_EQ(field.At({3, 2}), kU);
    EXPECT_EQ(field.At({4, 2}), 3 + 3 + 4 + 4);  // round the wall's end
  }
}

TEST(DistanceTransformTest, NoGoalLeavesEverythingUnreachable) {
  for (const DistanceTransformOptions& options : {kSweeps, kBuckets}) {
    const DistanceField field = ChamferDistanceTransform(Picture({"..#", "..."}), options);
    for (int y = 0; y < 2; ++y) {
      for (int x = 0; x < 3; ++x) EXPECT_EQ(field.At({x, y}), kU);
    }
  }
}

TEST(DistanceTransformTest, DiagonalStepsPassBetweenBlockedCellsTouchingAtACorner) {
  // As in the chamfer mask: two free cells that share a corner are
  // neighbours, whatever the other two cells at that corner are.
  const CoarseGrid grid = Picture({
      "..#",
      ".##",
      "#G.",
  });
  const DistanceField field = ChamferDistanceTransform(grid, kSweeps);
  EXPECT_EQ(field.At({0, 1}), 4);  // diagonally between the two blocked cells
  EXPECT_EQ(Distances(field), DijkstraReference(grid));
}

TEST(DistanceTransformTest, GoalsSurroundedByBlockedCellsReachNothing) {
  const CoarseGrid grid = Picture({
      "#####",
      "#.#G#",
      "#####",
  });
  const DistanceField field = ChamferDistanceTransform(grid, kBuckets);
  EXPECT_EQ(field.At({1, 1}), kU);
  EXPECT_EQ(field.At({3, 1}), 0);
  EXPECT_EQ(Distances(field), DijkstraReference(grid));
}

TEST(DistanceTransformTest, BothAlgorithmsEqualDijkstraOnRandomGrids) {
  const int sizes[][2] = {{1, 1}, {1, 17}, {23, 1}, {2, 2}, {37, 23}, {64, 64}, {101, 77}};
  const double densities[] = {0.0, 0.1, 0.25, 0.4, 0.55, 0.7};
  const int goal_counts[] = {0, 1, 3, 40};
  std::uint32_t seed = 1;
  for (const auto& size : sizes) {
    for (const double density : densities) {
      for (const int goals : goal_counts) {
        for (int repeat = 0; repeat < 3; ++repeat, ++seed) {
          ExpectExact(RandomGrid(size[0], size[1], density, goals, seed),
                      "random " + std::to_string(size[0]) + "x" + std::to_string(size[1]) +
                          " density " + std::to_string(density) + " goals " +
                          std::to_string(goals) + " seed " + std::to_string(seed));
        }
      }
    }
  }
}

TEST(DistanceTransformTest, BothAlgorithmsEqualDijkstraOnRandomMazes) {
  for (std::uint32_t seed = 1; seed <= 12; ++seed) {
    const int rooms = 3 + static_cast<int>(seed % 5) * 4;
    const int scale = 1 + static_cast<int>(seed % 3);
    ExpectExact(RandomMaze(rooms, scale, seed), "maze seed " + std::to_string(seed));
  }
}

TEST(DistanceTransformTest, BothAlgorithmsEqualDijkstraOnSpirals) {
  for (const int side : {5, 9, 21, 41, 63}) {
    for (const int scale : {1, 2, 3}) {
      ExpectExact(Spiral(side, scale),
                  "spiral " + std::to_string(side) + " scale " + std::to_string(scale));
    }
  }
}

TEST(DistanceTransformTest, LongRowsScannedInPiecesAreExact) {
  // Rows far longer than kShortRun: the row scans run in interleaved pieces
  // whose results are carried from one to the next.
  for (std::uint32_t seed = 1; seed <= 20; ++seed) {
    const int goals = static_cast<int>(seed % 4);
    ExpectExact(RandomGrid(997, 3, seed % 3 == 0 ? 0.002 : 0.0, goals, seed),
                "long rows seed " + std::to_string(seed));
  }
}

TEST(DistanceTransformTest, TwoSweepsAreNotEnoughOnASpiral) {
  // The paper's caveat: one forward and one backward sweep leave cells whose
  // shortest way to the goal turns back on itself with distances too large.
  const CoarseGrid grid = Spiral(21, 2);
  const std::vector<std::int32_t> reference = DijkstraReference(grid);
  const DistanceField two = ChamferDistanceTransform(grid, {DistanceAlgorithm::kRasterSweeps, 2});
  EXPECT_FALSE(two.converged());
  const std::vector<std::int32_t> partial = Distances(two);
  int too_large = 0;
  for (std::size_t i = 0; i < reference.size(); ++i) {
    EXPECT_GE(partial[i], reference[i]);  // sweeps only ever lower distances to the truth
    too_large += partial[i] > reference[i] ? 1 : 0;
  }
  EXPECT_GT(too_large, 100);
  const DistanceField converged = ChamferDistanceTransform(grid, kSweeps);
  EXPECT_TRUE(converged.converged());
  EXPECT_GT(converged.sweeps(), 10);  // a spiral of 5 turns needs many
  EXPECT_EQ(Distances(converged), reference);
}

TEST(DistanceTransformTest, OpenRoomConvergesInTwoSweepsAndAThirdToCheck) {
  const DistanceField field = ChamferDistanceTransform(RandomGrid(50, 40, 0.0, 5, 7), kSweeps);
  EXPECT_TRUE(field.converged());
  EXPECT_EQ(field.sweeps(), 3);
}

TEST(DistanceTransformTest, RejectsNegativeSweepLimit) {
  EXPECT_THROW(ChamferDistanceTransform(Picture({"G."}), {DistanceAlgorithm::kRasterSweeps, -1}),
               std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::explore
