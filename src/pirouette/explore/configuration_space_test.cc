#include "pirouette/explore/configuration_space.h"

#include <gtest/gtest.h>

#include <Eigen/Core>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <random>
#include <stdexcept>

namespace pirouette::explore {
namespace {

using mapping::CellState;

mapping::TrinaryMap Uniform(int w, int h, double resolution, CellState state) {
  return {core::GridGeometry(resolution, {0.0, 0.0}, w, h),
          std::vector<CellState>(static_cast<std::size_t>(w) * h, state)};
}

int Count(const mapping::TrinaryMap& map, CellState state) {
  return static_cast<int>(std::count(map.cells.begin(), map.cells.end(), state));
}

TEST(ConfigurationSpaceTest, OneObstacleGrowsByTheRadiusAroundItsSquare) {
  mapping::TrinaryMap map = Uniform(21, 21, 0.01, CellState::kFree);
  map.cells[map.geometry.Flat({10, 10})] = CellState::kOccupied;
  const mapping::TrinaryMap cspace = MakeConfigurationSpace(map, 0.05);
  // Along an axis, the centres within the radius of the obstacle's centre.
  EXPECT_EQ(cspace.At({15, 10}), CellState::kOccupied);  // 4.5 cells from its face
  EXPECT_EQ(cspace.At({16, 10}), CellState::kFree);      // 5.5 cells
  EXPECT_EQ(cspace.At({14, 13}), CellState::kOccupied);
  // Off the axes, nearer than the radius to the square's corner though
  // farther from its centre: (3.5, 3.5) from the corner is 4.95 cells.
  EXPECT_EQ(cspace.At({14, 14}), CellState::kOccupied);  // 5.66 cells from the centre
  EXPECT_EQ(cspace.At({15, 14}), CellState::kFree);      // 5.70 cells from the corner
  EXPECT_EQ(cspace.geometry, map.geometry);
}

TEST(ConfigurationSpaceTest, KeepsALegRoundAWallsEndOffItsCorner) {
  // Generated maze 101: a wall ending at a cell's edge; a leg turning
  // round it at 45° passed 3.5 mm inside the radius of its corner when
  // grown from the cell's centre. Every cell centre left free is at least
  // the radius from every point of the wall's cells.
  mapping::TrinaryMap map = Uniform(30, 30, 0.01, CellState::kFree);
  for (int x = 0; x <= 10; ++x) map.cells[map.geometry.Flat({x, 20})] = CellState::kOccupied;
  const double radius = 0.04;
  const mapping::TrinaryMap cspace = MakeConfigurationSpace(map, radius);
  for (int y = 0; y < 30; ++y) {
    for (int x = 0; x < 30; ++x) {
      if (cspace.At({x, y}) != CellState::kFree) continue;
      const Eigen::Vector2d p = map.geometry.CellCentre({x, y});
      // The nearest point of the wall's cells, [0, 0.11] × [0.20, 0.21].
      const Eigen::Vector2d q(std::clamp(p.x(), 0.0, 0.11), std::clamp(p.y(), 0.20, 0.21));
      EXPECT_GE((p - q).norm(), radius - 1e-9) << x << ", " << y;
    }
  }
}

TEST(ConfigurationSpaceTest, UnknownIsNotGrownAndStaysUnknown) {
  mapping::TrinaryMap map = Uniform(15, 15, 0.01, CellState::kUnknown);
  map.cells[map.geometry.Flat({2, 2})] = CellState::kFree;
  map.cells[map.geometry.Flat({12, 12})] = CellState::kFree;
  map.cells[map.geometry.Flat({3, 2})] = CellState::kOccupied;
  const mapping::TrinaryMap cspace = MakeConfigurationSpace(map, 0.02);
  EXPECT_EQ(cspace.At({2, 2}), CellState::kOccupied);  // free but next to an obstacle
  EXPECT_EQ(cspace.At({12, 12}), CellState::kFree);
  EXPECT_EQ(cspace.At({5, 2}), CellState::kOccupied);  // unknown within the radius is blocked
  EXPECT_EQ(cspace.At({8, 8}), CellState::kUnknown);
  EXPECT_EQ(Count(cspace, CellState::kOccupied), 21);  // the 5 × 5 square but its corners
}

TEST(ConfigurationSpaceTest, ZeroRadiusChangesNothing) {
  mapping::TrinaryMap map = Uniform(4, 3, 0.1, CellState::kFree);
  map.cells[5] = CellState::kOccupied;
  map.cells[7] = CellState::kUnknown;
  EXPECT_EQ(MakeConfigurationSpace(map, 0.0).cells, map.cells);
}

TEST(ConfigurationSpaceTest, EqualsBruteForceOnRandomMaps) {
  std::mt19937 rng(42);
  for (int trial = 0; trial < 30; ++trial) {
    const int w = 5 + static_cast<int>(rng() % 40);
    const int h = 5 + static_cast<int>(rng() % 40);
    const double radius = 0.01 * static_cast<double>(rng() % 70) / 10.0;
    mapping::TrinaryMap map = Uniform(w, h, 0.01, CellState::kFree);
    const std::uint32_t density = rng() % 30;
    for (CellState& c : map.cells) {
      const std::uint32_t roll = rng() % 100;
      c = roll < density ? CellState::kOccupied
          : roll < 50    ? CellState::kFree
                         : CellState::kUnknown;
    }
    const mapping::TrinaryMap cspace = MakeConfigurationSpace(map, radius);
    const double r_cells = radius / 0.01;
    for (int y = 0; y < h; ++y) {
      for (int x = 0; x < w; ++x) {
        bool near = false;
        for (int oy = 0; oy < h && !near; ++oy) {
          for (int ox = 0; ox < w && !near; ++ox) {
            const double gx = std::max(std::abs(ox - x) - 0.5, 0.0);
            const double gy = std::max(std::abs(oy - y) - 0.5, 0.0);
            near =
                map.At({ox, oy}) == CellState::kOccupied && gx * gx + gy * gy < r_cells * r_cells;
          }
        }
        const CellState expected = near ? CellState::kOccupied : map.At({x, y});
        ASSERT_EQ(cspace.At({x, y}), expected)
            << "trial " << trial << " cell " << x << ", " << y << " radius " << radius;
      }
    }
  }
}

TEST(ConfigurationSpaceTest, ClearingTheFootprintFreesTheRobotsCellAndNothingBeyondItsDisc) {
  // Generated maze 109: a robot of radius 4 cm stopped 5.2 cm from a wall's
  // true face, which the map drew 1.2 cm thicker than it is; its own cell
  // lay inside the grown wall and no plan started there. Here the map's
  // face is 3.3 cm off.
  mapping::TrinaryMap map = Uniform(40, 40, 0.01, CellState::kFree);
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x <= 11; ++x) map.cells[map.geometry.Flat({x, y})] = CellState::kOccupied;
  }
  map.cells[map.geometry.Flat({30, 30})] = CellState::kUnknown;
  const double radius = 0.04;
  const Eigen::Vector2d robot(0.153, 0.204);  // 3.3 cm from the wall's face at x = 0.12
  ASSERT_EQ(MakeConfigurationSpace(map, radius).At({15, 20}), CellState::kOccupied);
  mapping::TrinaryMap cleared = map;
  const int freed = ClearFootprint(cleared, robot, radius);
  EXPECT_GT(freed, 0);
  EXPECT_EQ(MakeConfigurationSpace(cleared, radius).At({15, 20}), CellState::kFree);
  // Only occupied cells whose squares lie within the radius of the robot's
  // cell's centre (0.155, 0.205) changed; the unknown cell stays unknown.
  int changed = 0;
  for (int y = 0; y < 40; ++y) {
    for (int x = 0; x < 40; ++x) {
      if (cleared.At({x, y}) == map.At({x, y})) continue;
      ++changed;
      EXPECT_EQ(map.At({x, y}), CellState::kOccupied);
      EXPECT_EQ(cleared.At({x, y}), CellState::kFree);
      const Eigen::Vector2d q(std::clamp(0.155, x * 0.01, (x + 1) * 0.01),
                              std::clamp(0.205, y * 0.01, (y + 1) * 0.01));
      EXPECT_LT((Eigen::Vector2d(0.155, 0.205) - q).norm(), radius) << x << ", " << y;
    }
  }
  EXPECT_EQ(changed, freed);
  EXPECT_EQ(cleared.At({30, 30}), CellState::kUnknown);
  // Off the map: nothing.
  mapping::TrinaryMap off = map;
  EXPECT_EQ(ClearFootprint(off, {-1.0, 0.2}, radius), 0);
  EXPECT_EQ(off.cells, map.cells);
}

TEST(ConfigurationSpaceTest, RejectsBadRadius) {
  mapping::TrinaryMap map = Uniform(2, 2, 0.1, CellState::kFree);
  EXPECT_THROW(MakeConfigurationSpace(map, -0.1), std::invalid_argument);
  EXPECT_THROW(MakeConfigurationSpace(map, std::nan("")), std::invalid_argument);
  EXPECT_THROW(ClearFootprint(map, {0.1, 0.1}, -0.1), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::explore
