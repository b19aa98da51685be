#include "pirouette/core/grid_geometry.h"

#include <gtest/gtest.h>

#include <vector>

namespace pirouette::core {
namespace {

TEST(GridGeometry, RefusesNonPositiveSizes) {
  EXPECT_THROW(GridGeometry(0.0, {0, 0}, 10, 10), std::invalid_argument);
  EXPECT_THROW(GridGeometry(0.01, {0, 0}, 0, 10), std::invalid_argument);
  EXPECT_THROW(GridGeometry(0.01, {0, 0}, 10, -1), std::invalid_argument);
}

TEST(GridGeometry, CoveringRoundsUp) {
  const GridGeometry g = GridGeometry::Covering(0.01, {0.0, 0.0}, {1.50, 1.305});
  EXPECT_EQ(g.width(), 150);
  EXPECT_EQ(g.height(), 131);
}

TEST(GridGeometry, WorldToCellAndBack) {
  const GridGeometry g(0.5, {-1.0, 2.0}, 4, 3);
  EXPECT_EQ(g.CellOf({-1.0, 2.0}), (CellIndex{0, 0}));
  EXPECT_EQ(g.CellOf({-0.01, 2.49}), (CellIndex{1, 0}));
  EXPECT_EQ(g.CellOf({0.99, 3.51}), (CellIndex{3, 3}));
  EXPECT_FALSE(g.CellAt({0.99, 3.51}).has_value());
  EXPECT_FALSE(g.CellAt({-1.01, 2.0}).has_value());
  ASSERT_TRUE(g.CellAt({0.99, 3.49}).has_value());
  const Eigen::Vector2d c = g.CellCentre({1, 2});
  EXPECT_DOUBLE_EQ(c.x(), -0.25);
  EXPECT_DOUBLE_EQ(c.y(), 3.25);
  EXPECT_EQ(g.CellOf(c), (CellIndex{1, 2}));
}

TEST(GridGeometry, FlatIsRowMajor) {
  const GridGeometry g(1.0, {0, 0}, 7, 5);
  EXPECT_EQ(g.Flat({3, 2}), 17u);
  EXPECT_EQ(g.Unflat(17), (CellIndex{3, 2}));
  EXPECT_EQ(g.CellCount(), 35u);
}

TEST(GridGeometry, AnyCellNearSegmentVisitsTheSweptCorridorOnAndOffTheGrid) {
  const GridGeometry g(1.0, {0, 0}, 5, 5);
  // Every cell a corridor of reach 1 along y = 2.5 from x = 0.5 to 2.5 holds,
  // against a brute-force check of every cell round it.
  std::vector<CellIndex> visited;
  EXPECT_FALSE(AnyCellNearSegment(g, {0.5, 2.5}, {2.5, 2.5}, 1.0, [&](const CellIndex& c) {
    visited.push_back(c);
    return false;
  }));
  std::vector<CellIndex> expected;
  for (int y = -3; y <= 8; ++y) {
    for (int x = -3; x <= 8; ++x) {
      if (DistanceToSegment(g.CellCentre({x, y}), {0.5, 2.5}, {2.5, 2.5}) <= 1.0) {
        expected.push_back({x, y});
      }
    }
  }
  EXPECT_EQ(visited, expected);
  // (-1, 2) lies off the grid, a cell from the segment's start: visited.
  EXPECT_TRUE(AnyCellNearSegment(g, {0.5, 2.5}, {2.5, 2.5}, 1.0, [](const CellIndex& c) {
    return c == CellIndex{-1, 2};
  }));
  EXPECT_FALSE(AnyCellNearSegment(g, {0.5, 2.5}, {2.5, 2.5}, 1.0, [](const CellIndex& c) {
    return c == CellIndex{4, 4};
  }));
}

}  // namespace
}  // namespace pirouette::core
