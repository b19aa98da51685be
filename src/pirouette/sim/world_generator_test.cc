#include "pirouette/sim/world_generator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <set>
#include <string>
#include <variant>

#include "pirouette/sim/maze_plan.h"
#include "pirouette/sim/obstacle_placer.h"
#include "pirouette/sim/room_plan.h"
#include "pirouette/sim/seeded_random.h"
#include "pirouette/sim/world_style.h"

// Its own namespace: the unit tests compile together (unity batches).
namespace pirouette::sim::world_generator_test {
namespace {

constexpr core::Rgb kGrey{128, 128, 128};

void ExpectSameObstacle(const ObstacleSpec& a, const ObstacleSpec& b) {
  ASSERT_EQ(a.shape.index(), b.shape.index());
  EXPECT_EQ(a.height, b.height);
  EXPECT_EQ(a.colour, b.colour);
  if (const auto* box = std::get_if<BoxSpec>(&a.shape)) {
    const auto& other = std::get<BoxSpec>(b.shape);
    EXPECT_EQ(box->centre, other.centre);
    EXPECT_EQ(box->size, other.size);
    EXPECT_EQ(box->yaw_deg, other.yaw_deg);
  } else if (const auto* cylinder = std::get_if<CylinderSpec>(&a.shape)) {
    EXPECT_EQ(cylinder->centre, std::get<CylinderSpec>(b.shape).centre);
    EXPECT_EQ(cylinder->radius, std::get<CylinderSpec>(b.shape).radius);
  } else if (const auto* wall = std::get_if<WallSpec>(&a.shape)) {
    EXPECT_EQ(wall->from, std::get<WallSpec>(b.shape).from);
    EXPECT_EQ(wall->to, std::get<WallSpec>(b.shape).to);
    EXPECT_EQ(wall->thickness, std::get<WallSpec>(b.shape).thickness);
  } else {
    EXPECT_EQ(std::get<PrismSpec>(a.shape).points, std::get<PrismSpec>(b.shape).points);
  }
}

TEST(WorldGeneratorTest, KindsHaveNames) {
  for (const WorldKind kind : kWorldKinds) EXPECT_EQ(ParseWorldKind(WorldKindName(kind)), kind);
  EXPECT_EQ(ParseWorldKind("house"), std::nullopt);
  EXPECT_EQ(ParseWorldKind("Rooms"), std::nullopt);
}

TEST(WorldGeneratorTest, TheSameSeedGivesTheSameWorld) {
  for (const WorldKind kind : kWorldKinds) {
    for (std::uint64_t seed = 1; seed <= 5; ++seed) {
      const WorldSpec a = GenerateWorld(kind, seed);
      const WorldSpec b = GenerateWorld(kind, seed);
      EXPECT_EQ(a.comment, b.comment);
      EXPECT_EQ(a.floor.size, b.floor.size);
      EXPECT_EQ(a.floor.colour, b.floor.colour);
      EXPECT_EQ(a.robot.start, b.robot.start);
      EXPECT_EQ(a.robot.start_heading_deg, b.robot.start_heading_deg);
      ASSERT_EQ(a.obstacles.size(), b.obstacles.size());
      for (std::size_t i = 0; i < a.obstacles.size(); ++i) {
        ExpectSameObstacle(a.obstacles[i], b.obstacles[i]);
      }
    }
  }
  // And another seed another world.
  EXPECT_NE(GenerateWorld(WorldKind::kRooms, 1).comment,
            GenerateWorld(WorldKind::kRooms, 2).comment);
}

TEST(WorldGeneratorTest, SizesAreDrawnInTheKindsRangeOrGiven) {
  for (const WorldKind kind : kWorldKinds) {
    const WorldSizeLimits limits = SizeLimitsOf(kind);
    for (std::uint64_t seed = 1; seed <= 20; ++seed) {
      const Eigen::Vector2d size = GenerateWorld(kind, seed).floor.size;
      for (const double side : {size.x(), size.y()}) {
        EXPECT_GE(side, limits.default_min);
        EXPECT_LE(side, limits.default_max);
      }
    }
  }
  EXPECT_EQ(GenerateWorld(WorldKind::kMaze, 3, Eigen::Vector2d(2.3456, 1.5)).floor.size,
            Eigen::Vector2d(2.346, 1.5));
  EXPECT_EQ(GenerateWorld(WorldKind::kApartment, 3, Eigen::Vector2d(9.0, 6.5)).floor.size,
            Eigen::Vector2d(9.0, 6.5));
  EXPECT_THROW(GenerateWorld(WorldKind::kRooms, 1, Eigen::Vector2d(0.2, 2.0)),
               std::invalid_argument);
  EXPECT_THROW(GenerateWorld(WorldKind::kApartment, 1, Eigen::Vector2d(10.0, 31.0)),
               std::invalid_argument);
}

TEST(WorldGeneratorTest, EachKindHasItsRobotAndItsStartIsClear) {
  for (const WorldKind kind : kWorldKinds) {
    const bool apartment = kind == WorldKind::kApartment;
    for (std::uint64_t seed = 1; seed <= 10; ++seed) {
      const WorldSpec spec = GenerateWorld(kind, seed);
      EXPECT_EQ(spec.robot.radius, apartment ? 0.15 : 0.04);
      EXPECT_EQ(spec.robot.camera.name(), apartment ? "webcam640" : "yujin");
      const World world = BuildWorld(spec);
      EXPECT_TRUE(world.DiscFits(spec.robot.start, spec.robot.radius))
          << WorldKindName(kind) << " seed " << seed;
      EXPECT_EQ(std::fmod(spec.robot.start_heading_deg, 15.0), 0.0);
      for (const Solid& solid : world.obstacles()) {
        // On the floor, but for the rounding of a footprint's corner (1e-17 m).
        for (const Eigen::Vector2d& p : solid.footprint) {
          const Eigen::Vector2d on_floor = p.cwiseMax(0.0).cwiseMin(world.floor().size);
          EXPECT_LT((p - on_floor).norm(), 1e-12)
              << WorldKindName(kind) << " seed " << seed << ": (" << p.transpose() << ")";
        }
      }
    }
  }
}

TEST(WorldGeneratorTest, LooksVaryAndTheHardOnesComeUp) {
  std::set<std::string> seen;
  const std::string kWords[] = {"floor dark",
                                "floor wood",
                                "floor carpet",
                                "floor pale",
                                "floor close to the walls' colour",
                                "floor close to the colour the walls shade to",
                                "walls light",
                                "walls dark",
                                "as high as the camera",
                                "lower than the camera",
                                "taller than the camera"};
  std::set<std::size_t> shapes;
  for (std::uint64_t seed = 1; seed <= 100; ++seed) {
    const WorldSpec spec = GenerateWorld(WorldKind::kClutter, seed);
    for (const std::string& words : kWords) {
      if (spec.comment.find(words) != std::string::npos) seen.insert(words);
    }
    for (const ObstacleSpec& o : spec.obstacles) shapes.insert(o.shape.index());
  }
  for (const std::string& words : kWords) EXPECT_TRUE(seen.contains(words)) << words;
  EXPECT_EQ(shapes.size(), 4u) << "boxes, cylinders, walls and prisms";
}

// How unlike the lit floor a face of `colour` looks at its least, found the
// slow way: a face every fifth of a degree round, and a top.
double LeastContrastTheSlowWay(const Light& light, const core::Rgb& colour,
                               const core::Rgb& floor) {
  // The renderer's flat shading: ambient + Lambert towards the light.
  const auto shade = [&](const Eigen::Vector3d& normal) {
    return light.ambient +
           light.intensity * std::max(0.0, -normal.dot(light.direction.normalized()));
  };
  const double up = shade(Eigen::Vector3d::UnitZ());
  const auto channel = [&](int c, const core::Rgb& rgb) {
    return c == 0 ? rgb.r : c == 1 ? rgb.g : rgb.b;
  };
  const auto contrast = [&](double shade) {
    double most = 0.0;
    for (int c = 0; c < 3; ++c) {
      most = std::max(most, std::abs(std::min(255.0, channel(c, colour) * shade) -
                                     std::min(255.0, channel(c, floor) * up)));
    }
    return most;
  };
  double least = contrast(up);
  for (int i = 0; i < 1800; ++i) {
    const double a = i * std::numbers::pi / 900.0;
    least = std::min(least, contrast(shade({std::cos(a), std::sin(a), 0.0})));
  }
  return least;
}

TEST(WorldStyleTest, PictureContrastIsTheLeastOverTheFacesOfTheShadedColour) {
  // Light straight down: every vertical face gets the ambient alone.
  const Light overhead{0.5, {0.0, 0.0, -1.0}, 0.5};
  const core::Rgb floor{100, 100, 100};  // lit: 100
  // A wall twice as light shades to the floor's grey on its faces...
  EXPECT_NEAR(PictureContrast(overhead, {200, 200, 200}, floor), 0.0, 1e-9);
  // ...a dark one is unlike it on every face and on its top (30 against 100).
  EXPECT_NEAR(PictureContrast(overhead, {30, 30, 30}, floor), 70.0, 1e-9);
  // The largest channel's difference counts: a red only in red.
  EXPECT_NEAR(PictureContrast(overhead, {100, 200, 200}, {100, 100, 100}), 50.0, 1e-9);
  // A slanting light lights some faces more than others: the least over all.
  const Light slanting{0.4, {0.6, 0.3, -1.0}, 0.6};
  for (const core::Rgb colour : {core::Rgb{40, 200, 90}, core::Rgb{180, 170, 160}}) {
    EXPECT_NEAR(PictureContrast(slanting, colour, {150, 140, 130}),
                LeastContrastTheSlowWay(slanting, colour, {150, 140, 130}), 0.5);
  }
}

TEST(WorldGeneratorTest, EveryWallAndObstacleStandsOutFromTheFloorInThePicture) {
  // The hard cases (floors close to the walls' colour or to what they shade
  // to, obstacles close to the floor's) come up, but never closer to the
  // floor than the camera's noise lets it tell them apart.
  for (const WorldKind kind : kWorldKinds) {
    for (std::uint64_t seed = 1; seed <= 25; ++seed) {
      const WorldSpec spec = GenerateWorld(kind, seed);
      const auto check = [&](const core::Rgb& colour, const std::string& what) {
        EXPECT_GE(LeastContrastTheSlowWay(spec.light, colour, spec.floor.colour),
                  kMinPictureContrast - 0.5)
            << WorldKindName(kind) << " " << seed << ": " << what;
      };
      ASSERT_TRUE(spec.walls.has_value());
      check(spec.walls->colour, "the walls");
      for (std::size_t i = 0; i < spec.obstacles.size(); ++i) {
        check(spec.obstacles[i].colour, "obstacle " + std::to_string(i));
      }
    }
  }
}

TEST(MazePlanTest, CorridorsFillTheFloorWithinTheirRange) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    SeededRandom random(seed);
    const Mm width = random.Between(1500, 3000);
    const Mm height = random.Between(1500, 3000);
    const MazePlan plan = DrawMazePlan(random, {width, height, 20, 120, 240});
    for (const auto& [corridors, length] : {std::pair{plan.columns, width}, {plan.rows, height}}) {
      Mm sum = 20 * static_cast<Mm>(corridors.size() - 1);
      for (const Mm w : corridors) {
        EXPECT_GE(w, 120);
        EXPECT_LE(w, 240);
        sum += w;
      }
      EXPECT_EQ(sum, length);
    }
    EXPECT_EQ(plan.cells.size(), plan.columns.size() * plan.rows.size());
  }
}

TEST(RoomPlanTest, RoomsKeepTheirSizeAndDoorsTheirWidth) {
  for (std::uint64_t seed = 1; seed <= 30; ++seed) {
    SeededRandom random(seed);
    const RoomPlan plan =
        DrawRoomPlan(random, {3000, 2000, 20, 550, 5, 120, 160, 240, 0.25, 60, 40, 120});
    EXPECT_GE(plan.rooms.size(), 2u);
    EXPECT_LE(plan.rooms.size(), 5u);
    // One door a wall between two rooms: a tree of rooms.
    EXPECT_EQ(plan.door_widths.size() + 1, plan.rooms.size());
    for (const MmRect& room : plan.rooms) {
      EXPECT_GE(room.x1 - room.x0, 550);
      EXPECT_GE(room.y1 - room.y0, 550);
    }
    for (const Mm width : plan.door_widths) {
      EXPECT_GE(width, 120);
      EXPECT_LE(width, 240);
    }
  }
}

TEST(ObstaclePlacerTest, YawDirectionsAreTheCosinesAndSines) {
  for (int k = 0; k < 24; ++k) {
    const double angle = k * 15.0 * std::numbers::pi / 180.0;
    EXPECT_NEAR(YawDirection(k).x(), std::cos(angle), 1e-15) << k;
    EXPECT_NEAR(YawDirection(k).y(), std::sin(angle), 1e-15) << k;
  }
  EXPECT_EQ(YawDirection(6), Eigen::Vector2d(0.0, 1.0));
}

TEST(ObstaclePlacerTest, KeepsGapsOrStandsFlush) {
  ObstaclePlacer placer({1.0, 1.0});
  const auto box = [](double x, double y, double sx, double sy) {
    return ObstacleSpec{BoxSpec{{x, y}, {sx, sy}, 0.0}, 0.1, kGrey};
  };
  // Flush against the floor's edge: only when drawn against a wall.
  EXPECT_FALSE(placer.TryAdd(box(0.05, 0.5, 0.1, 0.2), 0.12, false));
  EXPECT_TRUE(placer.TryAdd(box(0.05, 0.5, 0.1, 0.2), 0.12, true));
  // Flush against a wall, 0.05 from the floor's edge: too close to the edge.
  placer.AddWall({WallSpec{{0.5, 0.0}, {0.5, 0.4}, 0.02}, 0.1, kGrey});
  EXPECT_FALSE(placer.TryAdd(box(0.55, 0.10, 0.08, 0.1), 0.12, true));
  EXPECT_TRUE(placer.TryAdd(box(0.55, 0.20, 0.08, 0.1), 0.12, true));
  // 0.01 from the wall: neither flush nor the gap.
  EXPECT_FALSE(placer.TryAdd(box(0.56, 0.30, 0.08, 0.1), 0.12, true));
  // A cylinder 0.11 from the first box: closer than the gap.
  EXPECT_FALSE(placer.TryAdd({CylinderSpec{{0.25, 0.5}, 0.04}, 0.1, kGrey}, 0.12, false));
  EXPECT_TRUE(placer.TryAdd({CylinderSpec{{0.27, 0.5}, 0.04}, 0.1, kGrey}, 0.12, false));
  // Nothing in a doorway.
  placer.AddKeepOut({0.7, 0.7}, {0.9, 0.9});
  EXPECT_FALSE(placer.TryAdd({CylinderSpec{{0.75, 0.75}, 0.01}, 0.1, kGrey}, 0.0, false));
  EXPECT_EQ(placer.obstacles().size(), 4u);
  EXPECT_NEAR(placer.Clearance({0.27, 0.6}), 0.06, 1e-12);
}

}  // namespace
}  // namespace pirouette::sim::world_generator_test
