#include "pirouette/sim/world.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pirouette/core/angle.h"

namespace pirouette::sim {
namespace {

constexpr double kTolerance = 1e-12;
constexpr core::Rgb kRed{200, 40, 40};
constexpr core::Rgb kWhite{235, 235, 235};

double TwiceSignedArea(const std::vector<Eigen::Vector2d>& polygon) {
  double sum = 0.0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Eigen::Vector2d& a = polygon[i];
    const Eigen::Vector2d& b = polygon[(i + 1) % polygon.size()];
    sum += a.x() * b.y() - a.y() * b.x();
  }
  return sum;
}

void ExpectNear(const Eigen::Vector2d& actual, const Eigen::Vector2d& expected, double tolerance) {
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
}

camera::CameraModel WorldTestCamera() {
  return camera::CameraModel("test", 320, 240, {277.13, 277.13, 159.5, 119.5}, {},
                             {0.11, core::DegToRad(30.0), 0.03}, {});
}

RobotSpec TestRobot() { return RobotSpec{core::Pose2(1.0, 1.0, 0.0), 0.04, WorldTestCamera(), {}}; }

// L-shaped prism, clockwise as given; its notch is [0.4, 0.6] × [0.4, 0.6].
std::vector<Eigen::Vector2d> ClockwiseL() {
  return {{0.2, 0.2}, {0.2, 0.6}, {0.4, 0.6}, {0.4, 0.4}, {0.6, 0.4}, {0.6, 0.2}};
}

// A 2 × 1.5 floor with one solid of each kind:
//   0 box [0.9, 1.1] × [0.25, 0.35]
//   1 cylinder at (1.6, 1.0), radius 0.1
//   2 wall [0.2, 0.8] × [1.18, 1.22]
//   3 the L prism
//   4 a square of side 0.2 at (1.5, 0.4) turned by 45°: a diamond, half-diagonal 0.1·√2
World TestWorld(bool with_walls) {
  std::vector<Solid> obstacles = {
      MakeBox({1.0, 0.3}, {0.2, 0.1}, 0.0, 0.08, kRed),
      MakeCylinder({1.6, 1.0}, 0.1, 0.1, kRed),
      MakeWall({0.2, 1.2}, {0.8, 1.2}, 0.04, 0.1, kWhite),
      MakePrism(ClockwiseL(), 0.06, kRed),
      MakeBox({1.5, 0.4}, {0.2, 0.2}, core::DegToRad(45.0), 0.08, kRed),
  };
  std::optional<BoundaryWalls> walls;
  if (with_walls) walls = BoundaryWalls{0.1, 0.05, kWhite};
  return World("test", Floor{{2.0, 1.5}, {25, 25, 25}, 0.0}, walls, std::move(obstacles), Light{},
               TestRobot());
}

TEST(MakeBoxTest, RotatedBoxHasCounterClockwiseCorners) {
  // Size x lies along the yaw: turned by 90°, the long side runs north.
  const Solid box = MakeBox({1.0, 1.0}, {0.2, 0.1}, core::DegToRad(90.0), 0.08, kRed);
  EXPECT_EQ(box.kind, Solid::Kind::kBox);
  EXPECT_FALSE(box.circle.has_value());
  EXPECT_EQ(box.height, 0.08);
  EXPECT_EQ(box.colour, kRed);
  ASSERT_EQ(box.footprint.size(), 4u);
  ExpectNear(box.footprint[0], {1.05, 0.9}, kTolerance);
  ExpectNear(box.footprint[1], {1.05, 1.1}, kTolerance);
  ExpectNear(box.footprint[2], {0.95, 1.1}, kTolerance);
  ExpectNear(box.footprint[3], {0.95, 0.9}, kTolerance);
  EXPECT_NEAR(TwiceSignedArea(box.footprint), 2.0 * 0.02, kTolerance);
}

TEST(MakeBoxTest, SignedDistanceOfRotatedBox) {
  const Solid box = MakeBox({1.0, 1.0}, {0.2, 0.1}, core::DegToRad(90.0), 0.08, kRed);
  EXPECT_NEAR(box.SignedDistance({1.0, 1.0}), -0.05, kTolerance);   // the half width
  EXPECT_NEAR(box.SignedDistance({1.0, 1.08}), -0.02, kTolerance);  // nearer the north end
  EXPECT_NEAR(box.SignedDistance({1.2, 1.0}), 0.15, kTolerance);    // east of the long side
  EXPECT_NEAR(box.SignedDistance({1.0, 0.7}), 0.2, kTolerance);     // south of the short side
  // Beyond the north-east corner (1.05, 1.1).
  EXPECT_NEAR(box.SignedDistance({1.15, 1.2}), std::sqrt(0.02), kTolerance);
  EXPECT_NEAR(box.SignedDistance({1.05, 1.0}), 0.0, kTolerance);  // on an edge
}

TEST(MakeBoxTest, DiamondAtFortyFiveDegrees) {
  const Solid box = MakeBox({1.5, 0.4}, {0.2, 0.2}, core::DegToRad(45.0), 0.08, kRed);
  const double half_diagonal = 0.1 * std::numbers::sqrt2;
  ExpectNear(box.footprint[0], {1.5, 0.4 - half_diagonal}, kTolerance);
  ExpectNear(box.footprint[1], {1.5 + half_diagonal, 0.4}, kTolerance);
  ExpectNear(box.footprint[2], {1.5, 0.4 + half_diagonal}, kTolerance);
  ExpectNear(box.footprint[3], {1.5 - half_diagonal, 0.4}, kTolerance);
  // East of the east vertex: the distance to that vertex.
  EXPECT_NEAR(box.SignedDistance({1.8, 0.4}), 0.3 - half_diagonal, kTolerance);
  // Off the north-east edge, x + y = 1.9 + √2/10: along the edge's normal.
  EXPECT_NEAR(box.SignedDistance({1.6, 0.5}), (0.2 - half_diagonal) / std::numbers::sqrt2,
              kTolerance);
  EXPECT_NEAR(box.SignedDistance({1.5, 0.4}), -0.1, kTolerance);
}

TEST(MakeCylinderTest, InscribedPolygonAndExactCircle) {
  const Solid cylinder = MakeCylinder({1.6, 1.0}, 0.1, 0.12, kRed);
  EXPECT_EQ(cylinder.kind, Solid::Kind::kCylinder);
  ASSERT_TRUE(cylinder.circle.has_value());
  ExpectNear(cylinder.circle->centre, {1.6, 1.0}, 0.0);
  EXPECT_EQ(cylinder.circle->radius, 0.1);
  EXPECT_EQ(cylinder.height, 0.12);
  ASSERT_EQ(cylinder.footprint.size(), static_cast<std::size_t>(kCylinderSides));
  for (const Eigen::Vector2d& vertex : cylinder.footprint) {
    EXPECT_NEAR((vertex - Eigen::Vector2d(1.6, 1.0)).norm(), 0.1, kTolerance);
  }
  // Regular and counter-clockwise: the area of the inscribed regular n-gon.
  const double n = kCylinderSides;
  EXPECT_NEAR(TwiceSignedArea(cylinder.footprint), n * 0.01 * std::sin(2.0 * std::numbers::pi / n),
              kTolerance);
}

TEST(MakeCylinderTest, SignedDistanceIsToTheCircle) {
  const Solid cylinder = MakeCylinder({1.6, 1.0}, 0.1, 0.12, kRed);
  EXPECT_NEAR(cylinder.SignedDistance({1.6, 1.0}), -0.1, kTolerance);
  EXPECT_NEAR(cylinder.SignedDistance({1.9, 1.4}), 0.4, kTolerance);
  // Midway between two vertices of the polygon, just inside the circle but
  // outside the polygon: the circle decides.
  const double angle = std::numbers::pi / kCylinderSides;
  const Eigen::Vector2d p =
      Eigen::Vector2d(1.6, 1.0) + 0.0999 * Eigen::Vector2d(std::cos(angle), std::sin(angle));
  EXPECT_NEAR(cylinder.SignedDistance(p), -0.0001, kTolerance);
}

TEST(MakeWallTest, ThickenedSegmentNotExtendedPastItsEnds) {
  const Solid wall = MakeWall({0.0, 0.65}, {0.8, 0.65}, 0.02, 0.1, kWhite);
  EXPECT_EQ(wall.kind, Solid::Kind::kWall);
  ASSERT_EQ(wall.footprint.size(), 4u);
  ExpectNear(wall.footprint[0], {0.0, 0.64}, kTolerance);
  ExpectNear(wall.footprint[1], {0.8, 0.64}, kTolerance);
  ExpectNear(wall.footprint[2], {0.8, 0.66}, kTolerance);
  ExpectNear(wall.footprint[3], {0.0, 0.66}, kTolerance);
  EXPECT_NEAR(wall.SignedDistance({0.4, 0.65}), -0.01, kTolerance);
  EXPECT_NEAR(wall.SignedDistance({0.4, 0.75}), 0.09, kTolerance);
  EXPECT_NEAR(wall.SignedDistance({-0.1, 0.65}), 0.1, kTolerance);  // past the `from` end
  EXPECT_NEAR(wall.SignedDistance({0.9, 0.65}), 0.1, kTolerance);   // past the `to` end
}

TEST(MakeWallTest, DiagonalWall) {
  // From (0, 0) to (0.3, 0.4): length 0.5, unit direction (0.6, 0.8), left normal (-0.8, 0.6).
  const Solid wall = MakeWall({0.0, 0.0}, {0.3, 0.4}, 0.1, 0.1, kWhite);
  ExpectNear(wall.footprint[0], {0.04, -0.03}, kTolerance);
  ExpectNear(wall.footprint[1], {0.34, 0.37}, kTolerance);
  ExpectNear(wall.footprint[2], {0.26, 0.43}, kTolerance);
  ExpectNear(wall.footprint[3], {-0.04, 0.03}, kTolerance);
  EXPECT_NEAR(TwiceSignedArea(wall.footprint), 2.0 * 0.5 * 0.1, kTolerance);
  // 0.2 along the left normal from the midpoint: 0.15 beyond the face.
  EXPECT_NEAR(wall.SignedDistance(Eigen::Vector2d(0.15, 0.2) + 0.2 * Eigen::Vector2d(-0.8, 0.6)),
              0.15, kTolerance);
}

TEST(MakePrismTest, ClockwiseInputIsReoriented) {
  const Solid prism = MakePrism(ClockwiseL(), 0.06, kRed);
  EXPECT_EQ(prism.kind, Solid::Kind::kPrism);
  ASSERT_EQ(prism.footprint.size(), 6u);
  EXPECT_NEAR(TwiceSignedArea(prism.footprint), 2.0 * 0.12, kTolerance);
  // The same vertices.
  for (const Eigen::Vector2d& vertex : ClockwiseL()) {
    EXPECT_NE(std::find(prism.footprint.begin(), prism.footprint.end(), vertex),
              prism.footprint.end());
  }
}

TEST(MakePrismTest, CounterClockwiseInputAndClosedRingAreKept) {
  std::vector<Eigen::Vector2d> points = {{1.0, 1.0}, {1.2, 1.0}, {1.1, 1.2}, {1.0, 1.0}};
  const Solid prism = MakePrism(points, 0.06, kRed);
  ASSERT_EQ(prism.footprint.size(), 3u);  // the repeated first point is dropped
  ExpectNear(prism.footprint[0], {1.0, 1.0}, 0.0);
  ExpectNear(prism.footprint[1], {1.2, 1.0}, 0.0);
  ExpectNear(prism.footprint[2], {1.1, 1.2}, 0.0);
}

TEST(MakePrismTest, SignedDistanceOfConcaveL) {
  const Solid prism = MakePrism(ClockwiseL(), 0.06, kRed);
  // In the notch, outside: nearest are its inner faces, or past them the reflex corner.
  EXPECT_NEAR(prism.SignedDistance({0.5, 0.5}), 0.1, kTolerance);
  EXPECT_NEAR(prism.SignedDistance({0.45, 0.45}), 0.05, kTolerance);
  EXPECT_NEAR(prism.SignedDistance({0.55, 0.45}), 0.05, kTolerance);
  EXPECT_NEAR(prism.SignedDistance({0.3, 0.3}), -0.1, kTolerance);
  EXPECT_NEAR(prism.SignedDistance({0.38, 0.5}), -0.02, kTolerance);  // inside the upright
  EXPECT_NEAR(prism.SignedDistance({0.5, 0.25}), -0.05, kTolerance);  // inside the foot
  EXPECT_NEAR(prism.SignedDistance({0.1, 0.4}), 0.1, kTolerance);
  // Beyond the notch: the nearest vertices are (0.6, 0.4) and (0.4, 0.6).
  EXPECT_NEAR(prism.SignedDistance({0.7, 0.7}), std::sqrt(0.1), kTolerance);
}

TEST(WorldTest, StoresWhatItIsGiven) {
  const World world = TestWorld(true);
  EXPECT_EQ(world.name(), "test");
  EXPECT_EQ(world.floor().size, Eigen::Vector2d(2.0, 1.5));
  ASSERT_TRUE(world.walls().has_value());
  EXPECT_EQ(world.walls()->thickness, 0.05);
  EXPECT_EQ(world.obstacles().size(), 5u);
  EXPECT_EQ(world.robot().radius, 0.04);
  EXPECT_EQ(world.robot().camera.width(), 320);
}

TEST(WorldTest, RefusesAnEmptyFloor) {
  EXPECT_THROW(World("bad", Floor{{0.0, 1.0}, {}, 0.0}, std::nullopt, {}, Light{}, TestRobot()),
               std::invalid_argument);
}

TEST(WorldTest, SolidsAreTheObstaclesAndFourBoundaryWallsOutsideTheFloor) {
  const World world = TestWorld(true);
  ASSERT_EQ(world.solids().size(), 9u);
  for (int i = 0; i < 5; ++i) {
    EXPECT_EQ(world.solids()[i].kind, world.obstacles()[i].kind);
    EXPECT_EQ(world.solids()[i].footprint, world.obstacles()[i].footprint);
  }
  for (int i = 5; i < 9; ++i) {
    const Solid& wall = world.solids()[i];
    EXPECT_EQ(wall.kind, Solid::Kind::kBoundaryWall);
    EXPECT_EQ(wall.height, 0.1);
    EXPECT_EQ(wall.colour, kWhite);
    EXPECT_GT(TwiceSignedArea(wall.footprint), 0.0);
    // Outside the floor: no floor point lies inside.
    for (double x = 0.0; x <= 2.0; x += 0.05) {
      for (double y = 0.0; y <= 1.5; y += 0.05) {
        EXPECT_GE(wall.SignedDistance({x, y}), -kTolerance);
      }
    }
  }
  // Every point of the band [-t, 0) around the floor, corners included, is in a wall.
  const auto in_a_wall = [&world](const Eigen::Vector2d& p) {
    for (int i = 5; i < 9; ++i) {
      if (world.solids()[i].SignedDistance(p) < 0.0) return true;
    }
    return false;
  };
  for (double s = -0.049; s < 2.049; s += 0.01) {
    EXPECT_TRUE(in_a_wall({s, -0.025}));
    EXPECT_TRUE(in_a_wall({s, 1.525}));
  }
  for (double s = -0.049; s < 1.549; s += 0.01) {
    EXPECT_TRUE(in_a_wall({-0.025, s}));
    EXPECT_TRUE(in_a_wall({2.025, s}));
  }
  EXPECT_TRUE(in_a_wall({-0.049, -0.049}));
  EXPECT_TRUE(in_a_wall({2.049, 1.549}));
  EXPECT_FALSE(in_a_wall({-0.051, 0.5}));

  EXPECT_EQ(TestWorld(false).solids().size(), 5u);
}

TEST(WorldTest, OnFloor) {
  const World world = TestWorld(false);
  EXPECT_TRUE(world.OnFloor({1.0, 0.75}));
  EXPECT_TRUE(world.OnFloor({0.0, 0.0}));
  EXPECT_TRUE(world.OnFloor({2.0, 1.5}));
  EXPECT_FALSE(world.OnFloor({-0.001, 0.75}));
  EXPECT_FALSE(world.OnFloor({2.001, 0.75}));
  EXPECT_FALSE(world.OnFloor({1.0, -0.001}));
  EXPECT_FALSE(world.OnFloor({1.0, 1.501}));
}

TEST(WorldTest, IsOccupied) {
  const World world = TestWorld(true);
  EXPECT_TRUE(world.IsOccupied({1.0, 0.3}));    // box
  EXPECT_TRUE(world.IsOccupied({1.65, 1.05}));  // cylinder
  EXPECT_TRUE(world.IsOccupied({0.5, 1.2}));    // wall
  EXPECT_TRUE(world.IsOccupied({0.3, 0.5}));    // L
  EXPECT_TRUE(world.IsOccupied({1.55, 0.4}));   // diamond
  EXPECT_TRUE(world.IsOccupied({-0.01, 0.5}));  // off the floor (in a boundary wall)
  EXPECT_TRUE(world.IsOccupied({-1.0, 0.5}));   // off the floor (beyond the walls)
  EXPECT_FALSE(world.IsOccupied({0.5, 0.5}));   // the L's notch
  EXPECT_FALSE(world.IsOccupied({1.0, 0.75}));
  EXPECT_FALSE(world.IsOccupied({1.6, 0.53}));  // just off the diamond's corner
  EXPECT_TRUE(TestWorld(false).IsOccupied({-0.01, 0.5}));
}

TEST(WorldTest, Clearance) {
  for (const bool with_walls : {false, true}) {
    const World world = TestWorld(with_walls);
    EXPECT_NEAR(world.Clearance({0.55, 0.55}), 0.15, kTolerance);  // the notch's inner sides
    EXPECT_NEAR(world.Clearance({0.1, 0.75}), 0.1, kTolerance);    // the floor's west edge
    EXPECT_NEAR(world.Clearance({1.6, 0.75}), 0.15, kTolerance);   // the cylinder
    EXPECT_NEAR(world.Clearance({1.0, 0.5}), 0.15, kTolerance);    // the box's north face
    EXPECT_NEAR(world.Clearance({0.5, 1.3}), 0.08, kTolerance);    // the wall's north face
    EXPECT_NEAR(world.Clearance({1.95, 1.45}), 0.05, kTolerance);  // the north-east corner
    EXPECT_EQ(world.Clearance({1.0, 0.3}), 0.0);
    EXPECT_EQ(world.Clearance({-0.1, 0.3}), 0.0);
    EXPECT_TRUE(world.DiscFits({0.55, 0.55}, 0.1));
    EXPECT_FALSE(world.DiscFits({0.55, 0.55}, 0.2));
  }
}

TEST(WorldTest, RayCastHitsEachKindOfSolid) {
  const World world = TestWorld(true);
  constexpr double kRange = 10.0;
  // The box's north face y = 0.35.
  EXPECT_NEAR(*world.RayCast({1.0, 0.75}, {0.0, -1.0}, kRange), 0.4, kTolerance);
  // The cylinder, off its axis: the exact circle, not the polygon.
  EXPECT_NEAR(*world.RayCast({1.65, 0.5}, {0.0, 1.0}, kRange), 0.5 - std::sqrt(0.0075), kTolerance);
  // The wall's south face y = 1.18.
  EXPECT_NEAR(*world.RayCast({0.5, 0.9}, {0.0, 1.0}, kRange), 0.28, kTolerance);
  // Into the L's notch: its inner faces, and its reflex corner on the diagonal.
  EXPECT_NEAR(*world.RayCast({0.55, 0.55}, {0.0, -1.0}, kRange), 0.15, kTolerance);
  EXPECT_NEAR(*world.RayCast({0.55, 0.55}, {-1.0, 0.0}, kRange), 0.15, kTolerance);
  EXPECT_NEAR(*world.RayCast({0.55, 0.55}, Eigen::Vector2d(-1.0, -1.0).normalized(), kRange),
              0.15 * std::numbers::sqrt2, kTolerance);
  // The diamond: its east vertex, then its north-east face.
  const double half_diagonal = 0.1 * std::numbers::sqrt2;
  EXPECT_NEAR(*world.RayCast({1.9, 0.4}, {-1.0, 0.0}, kRange), 0.4 - half_diagonal, kTolerance);
  EXPECT_NEAR(*world.RayCast({1.9, 0.45}, {-1.0, 0.0}, kRange), 0.4 - (half_diagonal - 0.05),
              kTolerance);
}

TEST(WorldTest, RayCastToTheFloorsEdge) {
  for (const bool with_walls : {false, true}) {
    const World world = TestWorld(with_walls);
    // East from the notch, passing between the diamond and the cylinder.
    EXPECT_NEAR(*world.RayCast({0.55, 0.55}, {1.0, 0.0}, 10.0), 1.45, kTolerance);
    // North-west from (1.0, 0.75): the wall's south face y = 1.18 at x = 0.57.
    EXPECT_NEAR(*world.RayCast({1.0, 0.75}, Eigen::Vector2d(-1.0, 1.0).normalized(), 10.0),
                0.43 * std::numbers::sqrt2, kTolerance);
    // North-east, between the cylinder and the diamond, to the north edge at (1.75, 1.5).
    EXPECT_NEAR(*world.RayCast({1.0, 0.75}, Eigen::Vector2d(1.0, 1.0).normalized(), 10.0),
                0.75 * std::numbers::sqrt2, kTolerance);
    EXPECT_NEAR(*world.RayCast({1.0, 1.4}, {0.0, 1.0}, 10.0), 0.1, kTolerance);
  }
}

TEST(WorldTest, RayCastRangeAndOrigin) {
  const World world = TestWorld(true);
  EXPECT_FALSE(world.RayCast({1.0, 0.75}, {0.0, -1.0}, 0.39).has_value());
  EXPECT_NEAR(*world.RayCast({1.0, 0.75}, {0.0, -1.0}, 0.4), 0.4, kTolerance);
  EXPECT_EQ(*world.RayCast({1.0, 0.3}, {0.0, 1.0}, 1.0), 0.0);   // inside the box
  EXPECT_EQ(*world.RayCast({-0.5, 0.3}, {1.0, 0.0}, 1.0), 0.0);  // off the floor
  // A ray grazing the box's north face hits it where it reaches it.
  EXPECT_NEAR(*world.RayCast({0.7, 0.35}, {1.0, 0.0}, 10.0), 0.2, kTolerance);
}

}  // namespace
}  // namespace pirouette::sim
