#include "pirouette/eval/map_evaluation.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/draw/palette.h"

namespace pirouette::eval {
namespace {

using mapping::CellState;
using mapping::TrinaryMap;

constexpr core::Rgb kRed{200, 40, 40};
constexpr core::Rgb kWhite{235, 235, 235};

camera::CameraModel TestCamera() {
  return camera::CameraModel("test", 320, 240, {277.13, 277.13, 159.5, 119.5}, {},
                             {0.11, core::DegToRad(30.0), 0.03}, {});
}

// A 1.0 × 0.6 floor, the robot (radius 0.04) starting at (0.25, 0.25).
sim::World MakeWorld(std::vector<sim::Solid> obstacles) {
  return {"test",
          sim::Floor{{1.0, 0.6}, {25, 25, 25}, 0.0},
          sim::BoundaryWalls{0.1, 0.02, kWhite},
          std::move(obstacles),
          sim::Light{},
          sim::RobotSpec{core::Pose2(0.25, 0.25, 0.0), 0.04, TestCamera(), {}}};
}

// One box filling exactly the cell (7, 3) of a 0.1 m grid at the origin.
sim::World BoxWorld() {
  return MakeWorld({sim::MakeBox({0.75, 0.35}, {0.1, 0.1}, 0.0, 0.08, kRed)});
}

// A wall across the floor at x = 0.6, with a gap of `gap` metres centred at y = 0.3.
sim::World TwoRoomWorld(double gap) {
  return MakeWorld({sim::MakeWall({0.6, 0.0}, {0.6, 0.3 - gap / 2}, 0.04, 0.1, kWhite),
                    sim::MakeWall({0.6, 0.3 + gap / 2}, {0.6, 0.6}, 0.04, 0.1, kWhite)});
}

// A map on `geometry` whose cell states are `state(centre)`.
TrinaryMap MapOf(const core::GridGeometry& geometry,
                 const std::function<CellState(const Eigen::Vector2d&)>& state) {
  TrinaryMap map{geometry, {}};
  for (std::size_t i = 0; i < geometry.CellCount(); ++i) {
    map.cells.push_back(state(geometry.CellCentre(geometry.Unflat(i))));
  }
  return map;
}

// The map that says exactly what the truth says.
TrinaryMap PerfectMap(const sim::World& world, const core::GridGeometry& geometry) {
  return MapOf(geometry, [&world](const Eigen::Vector2d& c) {
    return world.IsOccupied(c) ? CellState::kOccupied : CellState::kFree;
  });
}

const core::GridGeometry kFloorGrid(0.1, {0.0, 0.0}, 10, 6);

TEST(EvaluateMapTest, PerfectMapIsPerfect) {
  const sim::World world = BoxWorld();
  const MapEvaluation e = EvaluateMap(PerfectMap(world, kFloorGrid), world);
  EXPECT_EQ(e.coverage, 1.0);
  EXPECT_EQ(e.false_free, 0.0);
  EXPECT_EQ(e.false_occupied, 0.0);
  EXPECT_EQ(e.wall_error_m, 0.0);
  EXPECT_EQ(e.free, 59u);
  EXPECT_EQ(e.occupied, 1u);
  EXPECT_EQ(e.unknown, 0u);
  // Every free centre is 0.05 from the floor's edge or the box: the disc fits.
  EXPECT_EQ(e.reachable, 59u);
}

TEST(EvaluateMapTest, KnownErrorsGiveExactFractions) {
  const sim::World world = BoxWorld();
  TrinaryMap map = PerfectMap(world, kFloorGrid);
  const auto set = [&map](int x, int y, CellState s) { map.cells[map.geometry.Flat({x, y})] = s; };
  set(7, 3, CellState::kFree);      // the box, called free
  set(2, 2, CellState::kOccupied);  // 3 cells from the nearest truth (the floor's edge): false
  set(2, 3, CellState::kOccupied);  // likewise 3 cells
  set(0, 0, CellState::kOccupied);  // 1 cell from the edge: near enough
  set(1, 1, CellState::kOccupied);  // 2 cells from the edge: still near enough
  for (int x = 4; x < 9; ++x) set(x, 5, CellState::kUnknown);  // 5 reachable cells not seen

  const MapEvaluation e = EvaluateMap(map, world);
  EXPECT_EQ(e.free, 51u);
  EXPECT_EQ(e.occupied, 4u);
  EXPECT_EQ(e.unknown, 5u);
  EXPECT_EQ(e.reachable, 59u);
  // R is the 59 free cells; the map calls 51 free, 50 of them in R.
  EXPECT_DOUBLE_EQ(e.coverage, 50.0 / 59.0);
  EXPECT_DOUBLE_EQ(e.false_free, 1.0 / 51.0);
  EXPECT_DOUBLE_EQ(e.false_occupied, 2.0 / 4.0);
  EXPECT_NEAR(e.wall_error_m, (3.0 + 3.0 + 1.0 + 2.0) * 0.1 / 4.0, 1e-6);
}

TEST(JudgeMapTest, EachCellsVerdictAgreesWithTheCounts) {
  const sim::World world = BoxWorld();
  TrinaryMap map = PerfectMap(world, kFloorGrid);
  const auto set = [&map](int x, int y, CellState s) { map.cells[map.geometry.Flat({x, y})] = s; };
  set(7, 3, CellState::kFree);      // the box, called free
  set(2, 2, CellState::kOccupied);  // 3 cells from the truth: false
  set(1, 1, CellState::kOccupied);  // 2 cells: near enough
  set(5, 5, CellState::kUnknown);   // reachable floor not seen
  const JudgedMap judged = JudgeMap(map, world);
  const auto verdict = [&](int x, int y) { return judged.verdicts[kFloorGrid.Flat({x, y})]; };
  EXPECT_EQ(verdict(7, 3), CellVerdict::kFalseFree);
  EXPECT_EQ(verdict(2, 2), CellVerdict::kFalseOccupied);
  EXPECT_EQ(verdict(1, 1), CellVerdict::kOccupied);
  EXPECT_EQ(verdict(5, 5), CellVerdict::kMissedFloor);
  EXPECT_EQ(verdict(4, 4), CellVerdict::kFree);
  const MapEvaluation plain = EvaluateMap(map, world);
  EXPECT_EQ(judged.evaluation.false_free, plain.false_free);
  EXPECT_EQ(judged.evaluation.coverage, plain.coverage);
  EXPECT_EQ(judged.evaluation.false_occupied, plain.false_occupied);

  // The picture: 80 pixels a cell at 800 wide, north up; each wrong cell in its colour.
  const cv::Mat3b picture = DrawJudgedMap(map, judged, 800);
  ASSERT_EQ(picture.cols, 800);
  ASSERT_EQ(picture.rows, 480);
  const auto pixel = [&](int x, int y) { return picture((5 - y) * 80 + 40, x * 80 + 40); };
  EXPECT_EQ(pixel(7, 3), draw::kFalseFreeColour);
  EXPECT_EQ(pixel(2, 2), draw::kFalseOccupiedColour);
  EXPECT_EQ(pixel(5, 5), draw::kMissedFloorColour);
  EXPECT_EQ(pixel(1, 1), cv::Vec3b(0, 0, 0));
  EXPECT_EQ(pixel(4, 4), cv::Vec3b(255, 255, 255));
}

TEST(EvaluateMapTest, DistancesAreEuclideanBetweenCentres) {
  const sim::World world = MakeWorld({sim::MakeBox({0.55, 0.35}, {0.1, 0.1}, 0.0, 0.08, kRed)});
  // The box fills cell (5, 3). Cell (3, 2) is 4 cells from the off-floor cells left of it, 3
  // from those below it, and √(2² + 1²) = √5 from the box.
  TrinaryMap map = MapOf(kFloorGrid, [](const Eigen::Vector2d&) { return CellState::kUnknown; });
  map.cells[kFloorGrid.Flat({3, 2})] = CellState::kOccupied;
  const MapEvaluation e = EvaluateMap(map, world);
  EXPECT_NEAR(e.wall_error_m, std::sqrt(5.0) * 0.1, 1e-6);
  EXPECT_EQ(e.false_occupied, 1.0);  // √5 > 2 cells
}

TEST(EvaluateMapTest, EmptyMapHasZeroesNotNaNs) {
  const sim::World world = BoxWorld();
  const TrinaryMap map =
      MapOf(kFloorGrid, [](const Eigen::Vector2d&) { return CellState::kUnknown; });
  const MapEvaluation e = EvaluateMap(map, world);
  EXPECT_EQ(e.coverage, 0.0);
  EXPECT_EQ(e.false_free, 0.0);
  EXPECT_EQ(e.false_occupied, 0.0);
  EXPECT_EQ(e.wall_error_m, 0.0);
  EXPECT_EQ(e.unknown, 60u);
  EXPECT_EQ(e.reachable, 59u);
}

TEST(EvaluateMapTest, RoomBehindAClosedWallIsNotInR) {
  const sim::World world = TwoRoomWorld(0.0);
  const core::GridGeometry grid(0.02, {0.0, 0.0}, 50, 30);
  const MapEvaluation perfect = EvaluateMap(PerfectMap(world, grid), world);
  EXPECT_EQ(perfect.coverage, 1.0);
  // Left room: centres x < 0.58 - 0.04 and 0.04 < y < 0.56 clear the disc:
  // x = 0.05..0.53 (25 columns), y = 0.05..0.55 (26 rows).
  EXPECT_EQ(perfect.reachable, 25u * 26u);

  // A map that knows only the right room covers nothing of R.
  const TrinaryMap right_only = MapOf(grid, [&world](const Eigen::Vector2d& c) {
    if (c.x() < 0.6) return CellState::kUnknown;
    return world.IsOccupied(c) ? CellState::kOccupied : CellState::kFree;
  });
  const MapEvaluation right = EvaluateMap(right_only, world);
  EXPECT_EQ(right.coverage, 0.0);
  EXPECT_EQ(right.false_free, 0.0);

  // One that knows only the left room covers all of it.
  const TrinaryMap left_only = MapOf(grid, [&world](const Eigen::Vector2d& c) {
    if (c.x() > 0.6) return CellState::kUnknown;
    return world.IsOccupied(c) ? CellState::kOccupied : CellState::kFree;
  });
  EXPECT_EQ(EvaluateMap(left_only, world).coverage, 1.0);
}

TEST(EvaluateMapTest, GapNarrowerThanTheRobotKeepsTheRoomOutOfR) {
  const core::GridGeometry grid(0.02, {0.0, 0.0}, 50, 30);
  const sim::World closed = TwoRoomWorld(0.0);
  const sim::World narrow = TwoRoomWorld(0.06);  // the disc is 0.08 across
  const sim::World wide = TwoRoomWorld(0.2);
  const std::size_t left = EvaluateMap(PerfectMap(closed, grid), closed).reachable;
  EXPECT_EQ(EvaluateMap(PerfectMap(narrow, grid), narrow).reachable, left);
  EXPECT_GT(EvaluateMap(PerfectMap(wide, grid), wide).reachable, left * 3 / 2);
}

TEST(EvaluateMapTest, MapCoveringPartOfTheFloorCoversPartOfR) {
  const sim::World world = BoxWorld();
  // The left half of the floor only.
  const core::GridGeometry half(0.1, {0.0, 0.0}, 5, 6);
  const MapEvaluation e = EvaluateMap(PerfectMap(world, half), world);
  EXPECT_EQ(e.reachable, 59u);
  EXPECT_DOUBLE_EQ(e.coverage, 30.0 / 59.0);
  EXPECT_EQ(e.false_free, 0.0);
}

TEST(EvaluateMapTest, CellsOffTheFloorAreTrulyOccupied) {
  const sim::World world = BoxWorld();
  // Two cells more on every side, shifted by a third of a cell.
  const core::GridGeometry wide(0.1, {-0.2 - 0.1 / 3, -0.2 - 0.1 / 3}, 14, 10);
  const MapEvaluation perfect = EvaluateMap(PerfectMap(world, wide), world);
  EXPECT_EQ(perfect.coverage, 1.0);
  EXPECT_EQ(perfect.false_free, 0.0);
  EXPECT_EQ(perfect.false_occupied, 0.0);
  EXPECT_EQ(perfect.wall_error_m, 0.0);

  // Calling everything free: the off-floor cells and the box are false.
  const TrinaryMap all_free = MapOf(wide, [](const Eigen::Vector2d&) { return CellState::kFree; });
  const MapEvaluation e = EvaluateMap(all_free, world);
  EXPECT_EQ(e.coverage, 1.0);
  EXPECT_DOUBLE_EQ(e.false_free,
                   static_cast<double>(perfect.occupied) / static_cast<double>(14 * 10));
}

TEST(EvaluateMapTest, MapFarFromTheFloor) {
  const sim::World world = BoxWorld();
  const core::GridGeometry far(0.1, {50.0, -30.0}, 4, 4);
  const TrinaryMap occupied =
      MapOf(far, [](const Eigen::Vector2d&) { return CellState::kOccupied; });
  const MapEvaluation e = EvaluateMap(occupied, world);
  EXPECT_EQ(e.coverage, 0.0);
  EXPECT_EQ(e.false_occupied, 0.0);  // off the floor is occupied
  EXPECT_EQ(e.wall_error_m, 0.0);
  EXPECT_EQ(e.reachable, 59u);
}

TEST(EvaluateMapTest, RefusesCellsThatDoNotMatchTheGeometry) {
  TrinaryMap map = PerfectMap(BoxWorld(), kFloorGrid);
  map.cells.pop_back();
  EXPECT_THROW(EvaluateMap(map, BoxWorld()), std::invalid_argument);
}

TEST(MapEvaluationJsonTest, HasSpecFields) {
  MapEvaluation e;
  e.coverage = 0.5;
  e.false_free = 0.25;
  e.false_occupied = 0.125;
  e.wall_error_m = 0.01;
  e.free = 10;
  e.occupied = 3;
  e.unknown = 7;
  e.reachable = 20;
  const nlohmann::json j = nlohmann::json::parse(MapEvaluationJson(e));
  EXPECT_EQ(j, MapEvaluationToJson(e));
  EXPECT_EQ(j.at("coverage").get<double>(), 0.5);
  EXPECT_EQ(j.at("false_free").get<double>(), 0.25);
  EXPECT_EQ(j.at("false_occupied").get<double>(), 0.125);
  EXPECT_EQ(j.at("wall_error_m").get<double>(), 0.01);
  EXPECT_EQ(j.at("cells").at("free").get<int>(), 10);
  EXPECT_EQ(j.at("cells").at("occupied").get<int>(), 3);
  EXPECT_EQ(j.at("cells").at("unknown").get<int>(), 7);
  EXPECT_EQ(j.at("reachable_cells").get<int>(), 20);
  EXPECT_EQ(j.size(), 6u);
}

}  // namespace
}  // namespace pirouette::eval
