#include "pirouette/mapping/trinary_map.h"

#include <gtest/gtest.h>

#include "pirouette/testing/walled_room.h"

namespace pirouette::mapping {
namespace {

TEST(TrinaryMapTest, DiscKnownFreeNeedsEveryCellUnderTheDiscFree) {
  TrinaryMap map{core::GridGeometry(0.01, Eigen::Vector2d::Zero(), 20, 20), {}};
  map.cells.assign(map.geometry.CellCount(), CellState::kFree);
  EXPECT_TRUE(DiscKnownFree(map, {0.10, 0.10}, 0.04));
  map.cells[map.geometry.Flat({12, 10})] = CellState::kUnknown;  // 2.5 cm off the centre
  EXPECT_FALSE(DiscKnownFree(map, {0.10, 0.10}, 0.04));
  EXPECT_TRUE(DiscKnownFree(map, {0.10, 0.10}, 0.02));
  EXPECT_FALSE(DiscKnownFree(map, {0.02, 0.10}, 0.04));  // leaves the map
}

TEST(TrinaryMapTest, CorridorKnownFreeNeedsEveryCellAlongTheDiscFree) {
  TrinaryMap map{core::GridGeometry(0.01, Eigen::Vector2d::Zero(), 50, 20), {}};
  map.cells.assign(map.geometry.CellCount(), CellState::kFree);
  const Eigen::Vector2d from(0.10, 0.10);
  const Eigen::Vector2d to(0.40, 0.10);
  EXPECT_TRUE(CorridorKnownFree(map, from, to, 0.04));
  // An unknown cell 3 cm beside the path, inside the disc's sweep.
  map.cells[map.geometry.Flat({25, 13})] = CellState::kUnknown;
  EXPECT_FALSE(CorridorKnownFree(map, from, to, 0.04));
  // The same cell is outside a thinner robot's sweep.
  EXPECT_TRUE(CorridorKnownFree(map, from, to, 0.02));
  // A corridor leaving the map is not known free.
  EXPECT_FALSE(CorridorKnownFree(map, from, Eigen::Vector2d(0.10, 0.19), 0.04));
}

TEST(TrinaryMapTest, PinholesInSeenFloorAreFilledAndTheRestKept) {
  testing::WalledRoom room = testing::MakeWalledRoom();
  const core::GridGeometry& g = room.map.geometry;
  const auto set = [&](int x, int y, CellState s) { room.map.cells[g.Flat({x, y})] = s; };
  set(10, 10, CellState::kUnknown);  // a pinhole
  set(20, 10, CellState::kUnknown);  // a pinhole of 4 cells
  set(21, 10, CellState::kUnknown);
  set(20, 11, CellState::kUnknown);
  set(21, 11, CellState::kUnknown);
  for (int x = 30; x <= 34; ++x) set(x, 10, CellState::kUnknown);  // 5 cells: kept
  set(10, 20, CellState::kUnknown);                                // beside an obstacle cell: kept
  set(11, 21, CellState::kOccupied);
  set(1, 15, CellState::kUnknown);  // beside the west wall: kept

  const TrinaryMap filled = FillPinholes(room.map, 4);
  EXPECT_EQ(filled.At({10, 10}), CellState::kFree);
  EXPECT_EQ(filled.At({21, 11}), CellState::kFree);
  EXPECT_EQ(filled.At({32, 10}), CellState::kUnknown);
  EXPECT_EQ(filled.At({10, 20}), CellState::kUnknown);
  EXPECT_EQ(filled.At({1, 15}), CellState::kUnknown);
  EXPECT_EQ(filled.At({11, 21}), CellState::kOccupied);
}

}  // namespace
}  // namespace pirouette::mapping
