#include "pirouette/sim/ray_caster.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pirouette/core/angle.h"

namespace pirouette::sim {
namespace {

using Eigen::Vector2d;
using Eigen::Vector3d;

// The paper's camera (worlds/yujin.yaml) with the principal point on column
// 160, so that the column sees straight ahead.
camera::CameraModel CentredPaperCamera() {
  return camera::CameraModel("yujin", 320, 240, {277.13, 277.13, 160.0, 119.5},
                             {-0.20, 0.05, 0.0, 0.0, 0.0}, {0.11, core::DegToRad(30.0), 0.03},
                             {{0.35, 0.30, 0.40}});
}

World MakeWorld(const Vector2d& floor_size, std::optional<BoundaryWalls> walls,
                std::vector<Solid> obstacles, const camera::CameraModel& camera) {
  Floor floor{floor_size, core::Rgb{25, 25, 25}, 0.0};
  RobotSpec robot{core::Pose2(0.1, 0.1, 0.0), 0.04, camera, {}};
  return World("ray-caster-test", floor, walls, std::move(obstacles), Light{}, robot);
}

TEST(RayCasterTest, CastsMeetTheFloorTheSolidsAndTheGround) {
  const camera::CameraModel camera = CentredPaperCamera();
  const World world = MakeWorld({2.0, 2.0}, std::nullopt,
                                {MakeBox({1.0, 1.0}, {0.2, 0.2}, 0.0, 0.1, {200, 0, 0}),
                                 MakeCylinder({1.0, 0.4}, 0.1, 0.05, {0, 200, 0})},
                                camera);
  const RayCaster caster(world, camera);
  // Straight down onto the floor.
  RayHit hit = caster.Cast(Vector3d(0.5, 0.5, 0.2), Vector3d(0, 0, -1));
  EXPECT_EQ(hit.kind, RayHit::Kind::kFloor);
  EXPECT_NEAR(hit.distance, 0.2, 1e-12);
  // Down onto the ground beyond the floor.
  hit = caster.Cast(Vector3d(-0.5, 0.5, 0.2), Vector3d(0, 0, -1));
  EXPECT_EQ(hit.kind, RayHit::Kind::kGround);
  // Horizontally into the box's west side.
  hit = caster.Cast(Vector3d(0.5, 1.0, 0.05), Vector3d(1, 0, 0));
  EXPECT_EQ(hit.kind, RayHit::Kind::kSolid);
  EXPECT_EQ(hit.solid, 0);
  EXPECT_NEAR(hit.distance, 0.4, 1e-12);
  EXPECT_NEAR(hit.normal.x(), -1.0, 1e-12);
  // Down onto the box's top.
  hit = caster.Cast(Vector3d(1.0, 1.0, 0.3), Vector3d(0, 0, -1));
  EXPECT_EQ(hit.kind, RayHit::Kind::kSolid);
  EXPECT_NEAR(hit.distance, 0.2, 1e-12);
  // Into the cylinder's exact circle, and over it.
  hit = caster.Cast(Vector3d(0.5, 0.4, 0.02), Vector3d(1, 0, 0));
  EXPECT_EQ(hit.kind, RayHit::Kind::kSolid);
  EXPECT_NEAR(hit.distance, 0.4, 1e-12);
  EXPECT_NEAR(hit.normal.x(), -1.0, 1e-12);
  hit = caster.Cast(Vector3d(0.5, 0.4, 0.06), Vector3d(1, 0, 0));
  EXPECT_EQ(hit.kind, RayHit::Kind::kNothing);  // over the cylinder's top
  // Up into nothing.
  hit = caster.Cast(Vector3d(0.5, 0.5, 0.2), Vector3d(0, 0, 1));
  EXPECT_EQ(hit.kind, RayHit::Kind::kNothing);
}

// Along straight bearings, the true profile's ranges are World::RayCast's
// where the floor's edge is an obstacle's base. Beside an obstacle, a column
// may instead cross the image of its vertical edge (which a tilted camera
// shows slanted, the paper's §5.2): the floor ends there at a point behind
// the obstacle, in its shadow, and the obstacle itself is nearer. Such a
// column reads clear to there when it meets the edge 3 rows or more above
// its foot; nearer the foot it stays a hit a little behind the obstacle.
TEST(RayCasterTest, TrueProfileAgreesWithWorldRayCast) {
  const camera::CameraModel camera = CentredPaperCamera();
  const World world = MakeWorld({1.0, 1.0}, BoundaryWalls{0.1, 0.02, {235, 235, 235}},
                                {MakeBox({0.62, 0.45}, {0.06, 0.10}, 0.3, 0.08, {200, 40, 40}),
                                 MakeCylinder({0.58, 0.62}, 0.04, 0.1, {40, 160, 40})},
                                camera);
  const RayCaster caster(world, camera);
  int hits = 0;
  int shadows = 0;
  int sides = 0;
  for (const double heading_deg : {0.0, 20.0, -35.0, 90.0, 180.0}) {
    const core::Pose2 world_T_robot(0.35, 0.5, core::DegToRad(heading_deg));
    const core::ObstacleProfile profile = caster.TrueProfile(world_T_robot, 0.7);
    ASSERT_EQ(profile.readings.size(), 320u);
    EXPECT_EQ(profile.max_range_m, 0.7);
    for (std::size_t u = 0; u < profile.readings.size(); ++u) {
      const core::RangeReading& r = profile.readings[u];
      const double bearing = world_T_robot.heading() + r.bearing_rad;
      const std::optional<double> truth = world.RayCast(
          world_T_robot.translation(), Vector2d(std::cos(bearing), std::sin(bearing)), 0.7);
      if (r.kind == core::ReadingKind::kHit) {
        ++hits;
        const Vector2d p_world = world_T_robot * Vector2d(r.range_m * std::cos(r.bearing_rad),
                                                          r.range_m * std::sin(r.bearing_rad));
        if (world.Clearance(p_world) < 1e-4) {
          ASSERT_TRUE(truth) << heading_deg << " " << u;
          EXPECT_NEAR(r.range_m, *truth, 2e-4) << heading_deg << " " << u;
        } else {
          ++shadows;
        }
      } else {
        // Clear to the max range, or short of it where the column met an
        // obstacle above its base: the floor is free to there.
        EXPECT_EQ(r.kind, core::ReadingKind::kClear);
        EXPECT_LE(r.range_m, 0.7);
        if (r.range_m < 0.7) ++sides;
        EXPECT_FALSE(truth && *truth < r.range_m - 1e-3) << heading_deg << " " << u;
      }
    }
    // The centre column looks straight ahead.
    EXPECT_NEAR(profile.readings[160].bearing_rad, 0.0, 1e-9);
  }
  EXPECT_GT(hits, 500);
  // The box's and the cylinder's sides: columns that meet them above their
  // base read clear, so hits off the obstacles (silhouettes) are rare.
  EXPECT_GT(sides, 0);
  EXPECT_LT(shadows, hits / 100);
}

TEST(RayCasterTest, OpenFloorIsClearAndAnObstacleAtTheFeetIsBlind) {
  const camera::CameraModel camera = CentredPaperCamera();
  const World open = MakeWorld({4.0, 4.0}, std::nullopt, {}, camera);
  const core::ObstacleProfile clear =
      RayCaster(open, camera).TrueProfile(core::Pose2(2.0, 2.0, 0.3), 0.4);
  for (const core::RangeReading& r : clear.readings) {
    EXPECT_EQ(r.kind, core::ReadingKind::kClear);
    EXPECT_EQ(r.range_m, 0.4);
  }
  // A wall 6 cm ahead of the centre: the camera (3 cm ahead, looking down at
  // 53° at its bottom row, ~8 cm) sees none of the floor in front of it.
  const World blocked =
      MakeWorld({4.0, 4.0}, std::nullopt,
                {MakeWall({2.06, 1.0}, {2.06, 3.0}, 0.01, 0.2, {235, 235, 235})}, camera);
  const RayCaster caster(blocked, camera);
  const core::ObstacleProfile blind = caster.TrueProfile(core::Pose2(2.0, 2.0, 0.0), 0.4);
  EXPECT_EQ(blind.readings[160].kind, core::ReadingKind::kBlind);
  EXPECT_NEAR(blind.readings[160].range_m, camera.FloorPoint({160.0, 239.0})->norm(), 1e-12);
  // The floor mask agrees: nothing of the centre column is floor.
  const std::vector<std::uint8_t> mask = caster.FloorMask(core::Pose2(2.0, 2.0, 0.0));
  for (int v = 0; v < 240; ++v) EXPECT_EQ(mask[static_cast<std::size_t>(v) * 320 + 160], 0);
}

TEST(RayCasterTest, RenderShadesFloorAndSolids) {
  const camera::CameraModel camera("plain", 64, 48, {55.0, 55.0, 31.5, 23.5}, {},
                                   {0.11, core::DegToRad(30.0), 0.03}, {});
  const World world = MakeWorld({4.0, 4.0}, std::nullopt,
                                {MakeWall({2.3, 1.0}, {2.3, 3.0}, 0.02, 0.3, {200, 0, 0})}, camera);
  const core::ImageRgb8 image = RayCaster(world, camera).Render(core::Pose2(2.0, 2.0, 0.0));
  const double floor_shade =
      world.light().ambient +
      world.light().intensity * Vector3d::UnitZ().dot(-world.light().direction.normalized());
  EXPECT_NEAR(image.At(32, 47).r, 25 * floor_shade, 0.51);
  EXPECT_EQ(image.At(32, 0).g, 0);  // the red wall fills the top
  EXPECT_GT(image.At(32, 0).r, 50);
}

}  // namespace
}  // namespace pirouette::sim
