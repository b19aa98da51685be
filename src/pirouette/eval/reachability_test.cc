#include "pirouette/eval/reachability.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <string>
#include <utility>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/io/world_file.h"
#include "pirouette/mapping/occupancy_grid.h"

// Its own namespace: the unit tests compile together (unity batches).
namespace pirouette::eval::reachability_test {
namespace {

constexpr core::Rgb kWhite{235, 235, 235};

camera::CameraModel TestCamera() {
  return camera::CameraModel("test", 320, 240, {277.13, 277.13, 159.5, 119.5}, {},
                             {0.11, core::DegToRad(30.0), 0.03}, {});
}

// A 1.0 × 0.6 floor, the robot (radius 0.04) starting at `start`.
sim::World MakeWorld(std::vector<sim::Solid> obstacles,
                     const Eigen::Vector2d& start = {0.25, 0.25}) {
  return {"test",
          sim::Floor{{1.0, 0.6}, {25, 25, 25}, 0.0},
          sim::BoundaryWalls{0.1, 0.02, kWhite},
          std::move(obstacles),
          sim::Light{},
          sim::RobotSpec{core::Pose2(start.x(), start.y(), 0.0), 0.04, TestCamera(), {}}};
}

// A closed square of walls 0.04 thick whose inside is [0.62, 0.88] × [0.18, 0.44].
std::vector<sim::Solid> ClosedBox() {
  const double t = 0.04;
  return {sim::MakeWall({0.60, 0.16}, {0.90, 0.16}, t, 0.1, kWhite),
          sim::MakeWall({0.60, 0.46}, {0.90, 0.46}, t, 0.1, kWhite),
          sim::MakeWall({0.60, 0.14}, {0.60, 0.48}, t, 0.1, kWhite),
          sim::MakeWall({0.90, 0.14}, {0.90, 0.48}, t, 0.1, kWhite)};
}

std::size_t Count(const std::vector<std::uint8_t>& cells) {
  std::size_t n = 0;
  for (const std::uint8_t c : cells) n += c != 0;
  return n;
}

const core::GridGeometry kGrid(0.02, {0.0, 0.0}, 50, 30);

TEST(ReachableCellsTest, OpenFloorIsAllReachable) {
  const Reachability truth = ReachableCells(MakeWorld({}), kGrid);
  // The window: the floor's cells with two more a side.
  EXPECT_EQ(truth.window.x0, -2);
  EXPECT_EQ(truth.window.y0, -2);
  EXPECT_GE(truth.window.width, 54);
  EXPECT_GE(truth.window.height, 34);
  // Centres 0.01..0.99 by 0.02: those farther than 0.04 from every edge,
  // 0.05..0.95 (46 columns) × 0.05..0.55 (26 rows).
  EXPECT_EQ(truth.ReachableCount(), 46u * 26u);
  EXPECT_EQ(Count(truth.fits), 46u * 26u);
  EXPECT_EQ(truth.UnreachableFitCount(), 0u);
  EXPECT_EQ(Count(truth.free), 50u * 30u);
}

TEST(ReachableCellsTest, ClosedPocketIsFloorTheRobotCannotReach) {
  const Reachability truth = ReachableCells(MakeWorld(ClosedBox()), kGrid);
  // Inside the box, centres farther than 0.04 from its walls' inner faces:
  // x 0.67..0.83 (9 columns), y 0.23..0.39 (9 rows).
  EXPECT_EQ(truth.UnreachableFitCount(), 9u * 9u);
  EXPECT_EQ(Count(truth.fits), truth.ReachableCount() + std::size_t{9 * 9});

  // Started inside it, the rest of the floor is out of reach instead.
  const Reachability inside = ReachableCells(MakeWorld(ClosedBox(), {0.75, 0.30}), kGrid);
  EXPECT_EQ(inside.ReachableCount(), 9u * 9u);
  EXPECT_EQ(inside.UnreachableFitCount(), truth.ReachableCount());
}

TEST(ReachableCellsTest, StartCellThatDoesNotFitSeedsFromItsNeighbours) {
  // The start's cell (0, 0) has its centre 0.01 from the edges, and none of its 8
  // neighbours' centres is farther than 0.03 from them: R is empty.
  EXPECT_EQ(ReachableCells(MakeWorld({}, {0.01, 0.01}), kGrid).ReachableCount(), 0u);
  // From (0.045, 0.045), in cell (2, 2) whose centre (0.05, 0.05) fits: all of R.
  EXPECT_EQ(ReachableCells(MakeWorld({}, {0.045, 0.045}), kGrid).ReachableCount(), 46u * 26u);
  // From (0.035, 0.035), in cell (1, 1), whose centre does not fit but its neighbour (2, 2)'s does.
  EXPECT_EQ(ReachableCells(MakeWorld({}, {0.035, 0.035}), kGrid).ReachableCount(), 46u * 26u);
}

TEST(ReachableCellsTest, TheGridsSizeDoesNotMatter) {
  const sim::World world = MakeWorld(ClosedBox());
  const Reachability a = ReachableCells(world, kGrid);
  const Reachability b = ReachableCells(world, core::GridGeometry(0.02, {0.0, 0.0}, 3, 2));
  EXPECT_EQ(a.free, b.free);
  EXPECT_EQ(a.fits, b.fits);
  EXPECT_EQ(a.reachable, b.reachable);
}

// The definition, asked of every cell: what ReachableCells's free and fits must be.
void ExpectAsAskingEveryCell(const sim::World& world, const core::GridGeometry& grid,
                             const std::string& what) {
  const Reachability truth = ReachableCells(world, grid);
  const TruthWindow& w = truth.window;
  std::size_t mismatches = 0;
  for (int b = 0; b < w.height; ++b) {
    for (int a = 0; a < w.width; ++a) {
      const Eigen::Vector2d c(
          grid.origin().x() + (static_cast<double>(w.x0 + a) + 0.5) * grid.resolution(),
          grid.origin().y() + (static_cast<double>(w.y0 + b) + 0.5) * grid.resolution());
      const std::size_t i = w.Flat(w.x0 + a, w.y0 + b);
      mismatches += truth.free[i] != (world.IsOccupied(c) ? 0 : 255);
      mismatches += truth.fits[i] != (world.Clearance(c) > world.robot().radius ? 1 : 0);
    }
  }
  EXPECT_EQ(mismatches, 0u) << what;
}

TEST(ReachableCellsTest, SkippingCellsGivesWhatAskingEveryCellGives) {
  ExpectAsAskingEveryCell(MakeWorld(ClosedBox()), kGrid, "closed box");
  for (const char* name : {"soccer_field", "two_rooms", "maze", "cluttered_room", "apartment"}) {
    const sim::World world =
        io::LoadWorldFile(std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml");
    const double cell = mapping::DefaultCellSize(world.robot().radius);
    ExpectAsAskingEveryCell(world, core::GridGeometry(cell, {0.0, 0.0}, 1, 1), name);
    // Off the world's lattice.
    ExpectAsAskingEveryCell(world, core::GridGeometry(cell, {-0.0037, 0.0061}, 1, 1), name);
  }
}

TEST(ReachableCellsTest, AWallOneCellThickWhoseFacesFallOnCentresIsInTheTruth) {
  // Walls 1 cm thick along whole centimetres, on a 1 cm grid from the
  // origin: every face passes through a row (or column) of cell centres,
  // which lie on the wall and so in it. (Before, rounding put each row in
  // the wall or out of it, 1e-17 m either way: generated maze 107's wall
  // along y = 1.76 was missing from the truth.)
  const double t = 0.01;
  std::vector<sim::Solid> walls;
  const std::vector<double> ys = {0.07, 0.13, 0.29, 0.41, 0.53};
  const std::vector<double> xs = {0.11, 0.37, 0.63, 0.89};
  for (const double y : ys) walls.push_back(sim::MakeWall({0.05, y}, {0.95, y}, t, 0.1, kWhite));
  for (const double x : xs) walls.push_back(sim::MakeWall({x, 0.02}, {x, 0.58}, t, 0.1, kWhite));
  const sim::World world = MakeWorld(std::move(walls), {0.2, 0.2});
  const core::GridGeometry grid(0.01, {0.0, 0.0}, 100, 60);
  const Reachability truth = ReachableCells(world, grid);
  const auto occupied = [&](int x, int y) { return truth.free[truth.window.Flat(x, y)] == 0; };
  for (const double y : ys) {
    const int below = static_cast<int>(std::lround(y / 0.01)) - 1;  // the rows either face passes
    for (int x = 6; x <= 94; ++x) {
      EXPECT_TRUE(occupied(x, below) && occupied(x, below + 1)) << "y " << y << " x " << x;
    }
  }
  for (const double x : xs) {
    const int left = static_cast<int>(std::lround(x / 0.01)) - 1;
    for (int y = 3; y <= 56; ++y) {
      EXPECT_TRUE(occupied(left, y) && occupied(left + 1, y)) << "x " << x << " y " << y;
    }
  }
}

}  // namespace
}  // namespace pirouette::eval::reachability_test
