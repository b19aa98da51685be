#include "pirouette/localize/locate.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pirouette/core/angle.h"
#include "pirouette/localize/map_view.h"
#include "pirouette/mapping/radial_profile.h"
#include "pirouette/testing/walled_room.h"

namespace pirouette::localize {
namespace {

constexpr double kMaxRange = 0.8;

using testing::MakeWalledRoom;
using testing::WalledRoom;

// What a perfect pirouette at `pose` would see: the map's own view, in the
// robot's frame.
struct Query {
  PlaceView view;
  std::vector<core::ReadingKind> kinds;
};

Query ViewFrom(const WalledRoom& room, const core::Pose2& pose) {
  const MapView v = CastMapView(room.map, pose.translation(), kMaxRange, room.colours);
  const int shift = static_cast<int>(std::lround(core::RadToDeg(pose.heading())));
  Query q;
  for (int b = 0; b < mapping::kRadialProfileBins; ++b) {
    const auto m = static_cast<std::size_t>((b + shift + 360) % 360);
    q.view.ranges_m.push_back(v.ranges_m[m]);
    q.view.colours.push_back(v.colours[m]);
    q.kinds.push_back(v.kinds[m] == MapRayKind::kHit ? core::ReadingKind::kHit
                                                     : core::ReadingKind::kClear);
  }
  return q;
}

TEST(LocateTest, ColoursTellASymmetricRoomFromItsMirrorImage) {
  const WalledRoom room = MakeWalledRoom();
  const core::Pose2 truth(0.30, 0.25, core::DegToRad(20.0));
  const Query q = ViewFrom(room, truth);
  constexpr double kSpacing = 0.1;
  constexpr double kCoarse = 0.04;
  LocateOptions options;
  options.candidates = 8;  // a small room: a few refined places suffice

  // Ranges alone: the pose and its mirror, (0.70, 0.35, 200 deg), agree as
  // well with the map, so the answer is "cannot tell".
  const ColourMap none;
  const PlaceTable grey = BuildMapPlaceTable(room.map, none, 0.04, kSpacing, kMaxRange);
  const LocateAnswer blind =
      Locate(room.map, none, grey, q.view, q.kinds, kSpacing, kCoarse, options);
  EXPECT_FALSE(blind.found);
  EXPECT_NE(blind.reason.find("ambiguous"), std::string::npos) << blind.reason;

  // With the colour layer the mirror sees blue where the pirouette saw red.
  const PlaceTable coloured = BuildMapPlaceTable(room.map, room.colours, 0.04, kSpacing, kMaxRange);
  const LocateAnswer seen =
      Locate(room.map, room.colours, coloured, q.view, q.kinds, kSpacing, kCoarse, options);
  ASSERT_TRUE(seen.found) << seen.reason;
  EXPECT_LT((seen.world_T_robot.translation() - truth.translation()).norm(), kCoarse);
  EXPECT_LT(std::abs(core::RadToDeg(
                core::NormalizeAngle(seen.world_T_robot.heading() - truth.heading()))),
            2.0);
  EXPECT_GT(seen.agreement - seen.runner_up, 0.08);
}

TEST(LocateTest, TheTableNameChangesWithTheColours) {
  const WalledRoom room = MakeWalledRoom();
  EXPECT_NE(MapTableName(room.map, {}, 0.04, 0.1, kMaxRange),
            MapTableName(room.map, room.colours, 0.04, 0.1, kMaxRange));
}

TEST(LocateTest, TheMapViewHasItsHitsColours) {
  const WalledRoom room = MakeWalledRoom();
  const MapView v = CastMapView(room.map, {0.5, 0.3}, kMaxRange, room.colours);
  ASSERT_EQ(v.colours.size(), 360u);
  EXPECT_EQ(v.colours[0], core::ColourClass::kHue8);    // east, 0.48 m
  EXPECT_EQ(v.colours[180], core::ColourClass::kHue0);  // west
  EXPECT_EQ(v.colours[90], core::ColourClass::kGrey);   // north
  EXPECT_TRUE(CastMapView(room.map, {0.5, 0.3}, kMaxRange).colours.empty());
}

TEST(LocateTest, ARayThroughAGapInAnObstaclesOutlineMeetsTheObstacle) {
  WalledRoom room = MakeWalledRoom();
  const core::GridGeometry& g = room.map.geometry;
  std::vector<core::ColourClass> colours = room.colours.cells();
  // A block of cells x 35..39, y 13..17: its outline occupied (hue 4), its
  // inside unknown, and a hole in its west face at (35, 15).
  for (int y = 13; y <= 17; ++y) {
    for (int x = 35; x <= 39; ++x) {
      const bool outline = x == 35 || x == 39 || y == 13 || y == 17;
      room.map.cells[g.Flat({x, y})] =
          outline ? mapping::CellState::kOccupied : mapping::CellState::kUnknown;
      if (outline) colours[g.Flat({x, y})] = core::ColourClass::kHue4;
    }
  }
  room.map.cells[g.Flat({35, 15})] = mapping::CellState::kUnknown;
  colours[g.Flat({35, 15})] = core::ColourClass::kNone;
  // Unseen floor north, with no obstacle beside it; and south-west, in the
  // shadow of one obstacle cell (beside one edge only).
  for (int y = 20; y <= 22; ++y) room.map.cells[g.Flat({25, y})] = mapping::CellState::kUnknown;
  room.map.cells[g.Flat({22, 10})] = mapping::CellState::kOccupied;
  room.map.cells[g.Flat({21, 11})] = mapping::CellState::kUnknown;
  room.colours = ColourMap(g, std::move(colours));

  const MapView v = CastMapView(room.map, {0.51, 0.31}, kMaxRange, room.colours);
  EXPECT_EQ(v.kinds[0], MapRayKind::kHit);  // east, through the hole
  EXPECT_NEAR(v.ranges_m[0], 0.19, 0.01);
  EXPECT_EQ(v.colours[0], core::ColourClass::kHue4);
  EXPECT_EQ(v.kinds[90], MapRayKind::kUnknown);  // north: the map cannot say
  EXPECT_NEAR(v.ranges_m[90], 0.09, 0.01);
  EXPECT_EQ(v.kinds[225], MapRayKind::kUnknown);  // south-west, the shadow
  EXPECT_NEAR(v.ranges_m[225], 0.10, 0.01);
}

TEST(LocateTest, ARayPassesFilledPinholes) {
  WalledRoom room = MakeWalledRoom();
  const core::GridGeometry& g = room.map.geometry;
  const auto set = [&](int x, int y, mapping::CellState s) { room.map.cells[g.Flat({x, y})] = s; };
  set(10, 10, mapping::CellState::kUnknown);  // a pinhole
  set(20, 10, mapping::CellState::kUnknown);  // a pinhole of 4 cells
  set(21, 10, mapping::CellState::kUnknown);
  set(20, 11, mapping::CellState::kUnknown);
  set(21, 11, mapping::CellState::kUnknown);
  for (int x = 30; x <= 34; ++x) set(x, 10, mapping::CellState::kUnknown);  // 5 cells: kept
  // A ray east along row 10 stops at the first pinhole; once they are filled
  // it passes both and stops at the group of 5.
  EXPECT_NEAR(CastMapView(room.map, {0.05, 0.21}, kMaxRange).ranges_m[0], 0.15, 0.01);
  const MapView v = CastMapView(mapping::FillPinholes(room.map, 4), {0.05, 0.21}, kMaxRange);
  EXPECT_EQ(v.kinds[0], MapRayKind::kUnknown);
  EXPECT_NEAR(v.ranges_m[0], 0.55, 0.01);
}

}  // namespace
}  // namespace pirouette::localize
