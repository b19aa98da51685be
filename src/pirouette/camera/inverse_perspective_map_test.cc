#include "pirouette/camera/inverse_perspective_map.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "pirouette/core/angle.h"
#include "pirouette/io/camera_file.h"

namespace pirouette::camera {
namespace {

constexpr double kHeight = 0.11;
constexpr double kForward = 0.03;

CameraModel UndistortedCamera(double tilt_deg) {
  return CameraModel("pinhole", 320, 240, {277.13, 270.0, 160.0, 120.0}, {},
                     {kHeight, core::DegToRad(tilt_deg), kForward}, {});
}

// The floor point, in the robot frame, of the ray through normalised image
// coordinates (x, y) (x right, y down) of a pinhole camera at (forward, 0,
// height), its axis pitched down by `tilt`, worked out from the geometry:
// the ray is axis + x·right + y·down with axis = (cos τ, 0, -sin τ),
// right = (0, -1, 0) and down = (-sin τ, 0, -cos τ). It falls by
// sin τ + y cos τ a unit of axis length; it meets the floor when it has
// fallen by the height. nullopt when it does not fall.
std::optional<Eigen::Vector2d> AnalyticFloorPoint(double x, double y, double tilt) {
  const double fall = std::sin(tilt) + y * std::cos(tilt);
  if (fall <= 0.0) return std::nullopt;
  const double scale = kHeight / fall;
  return Eigen::Vector2d(kForward + scale * (std::cos(tilt) - y * std::sin(tilt)), -scale * x);
}

void ExpectClose(const Eigen::Vector2f& actual, const Eigen::Vector2d& expected) {
  // The table holds floats: relative precision about 6e-8.
  const double tolerance = 1e-6 * std::max(1.0, expected.norm());
  EXPECT_NEAR(actual.x(), expected.x(), tolerance);
  EXPECT_NEAR(actual.y(), expected.y(), tolerance);
}

TEST(InversePerspectiveMapTest, Size) {
  const InversePerspectiveMap map(UndistortedCamera(30.0));
  EXPECT_EQ(map.width(), 320);
  EXPECT_EQ(map.height(), 240);
}

TEST(InversePerspectiveMapTest, PrincipalPointSeesForwardPlusHeightOverTanTilt) {
  for (const double tilt_deg : {10.0, 30.0, 45.0, 60.0}) {
    const InversePerspectiveMap map(UndistortedCamera(tilt_deg));
    const std::optional<Eigen::Vector2f> p = map.At(160, 120);
    ASSERT_TRUE(p.has_value());
    ExpectClose(*p, {kForward + kHeight / std::tan(core::DegToRad(tilt_deg)), 0.0});
  }
}

TEST(InversePerspectiveMapTest, CentreColumnFollowsTheDepressionAngle) {
  // Down the centre column a pixel's ray is depressed by tilt + atan(y).
  const double tilt = core::DegToRad(30.0);
  const InversePerspectiveMap map(UndistortedCamera(30.0));
  for (int v = 0; v < 240; ++v) {
    const double depression = tilt + std::atan((v - 120.0) / 270.0);
    ExpectClose(*map.At(160, v), {kForward + kHeight / std::tan(depression), 0.0});
  }
}

TEST(InversePerspectiveMapTest, EveryPixelMatchesTheAnalyticFloorPoint) {
  for (const double tilt_deg : {10.0, 30.0}) {
    const double tilt = core::DegToRad(tilt_deg);
    const InversePerspectiveMap map(UndistortedCamera(tilt_deg));
    int seen = 0;
    int unseen = 0;
    for (int v = 0; v < 240; ++v) {
      for (int u = 0; u < 320; ++u) {
        const double x = (u - 160.0) / 277.13;
        const double y = (v - 120.0) / 270.0;
        const std::optional<Eigen::Vector2d> expected = AnalyticFloorPoint(x, y, tilt);
        // Rays barely below the horizon (beyond a few kilometres) count as not seeing the floor.
        const bool far = expected && expected->norm() > 1000.0;
        if (far) continue;
        ASSERT_EQ(map.SeesFloor(u, v), expected.has_value()) << u << " " << v;
        ASSERT_EQ(map.At(u, v).has_value(), expected.has_value());
        if (expected) {
          ExpectClose(*map.At(u, v), *expected);
          ++seen;
        } else {
          ++unseen;
        }
      }
    }
    EXPECT_GT(seen, 0);
    if (tilt_deg == 30.0) {
      EXPECT_EQ(unseen, 0);  // half the vertical field of view is 24°: all floor
    } else {
      // The horizon is at v = 120 - 270·tan(10°) = 72.4: rows 0..72 see no floor.
      EXPECT_EQ(unseen, 73 * 320);
      EXPECT_FALSE(map.SeesFloor(0, 0));
      EXPECT_FALSE(map.At(160, 72).has_value());
      EXPECT_TRUE(map.At(160, 73).has_value());
    }
  }
}

TEST(InversePerspectiveMapTest, LookingUpSeesNoFloor) {
  const InversePerspectiveMap map(UndistortedCamera(-30.0));
  for (int v = 0; v < 240; ++v) {
    for (int u = 0; u < 320; u += 7) EXPECT_FALSE(map.At(u, v).has_value());
  }
}

TEST(InversePerspectiveMapTest, TableEqualsFloorPointOfADistortedCamera) {
  const CameraModel camera("paper", 320, 240, {277.13, 277.13, 159.5, 119.5},
                           {-0.20, 0.05, 0.001, -0.0005, 0.0},
                           {kHeight, core::DegToRad(15.0), kForward}, {});
  const InversePerspectiveMap map(camera);
  int seen = 0;
  for (int v = 0; v < camera.height(); ++v) {
    for (int u = 0; u < camera.width(); ++u) {
      const std::optional<Eigen::Vector2d> expected = camera.FloorPoint(Eigen::Vector2d(u, v));
      ASSERT_EQ(map.At(u, v).has_value(), expected.has_value());
      if (!expected) continue;
      ++seen;
      EXPECT_EQ(*map.At(u, v), expected->cast<float>());
      // And the floor point projects back onto the pixel.
      if (expected->norm() < 10.0) {
        const Eigen::Vector3d p_robot(expected->x(), expected->y(), 0.0);
        const Eigen::Vector2d pixel = *camera.Project(camera.robot_T_camera().inverse() * p_robot);
        EXPECT_NEAR((pixel - Eigen::Vector2d(u, v)).norm(), 0.0, 1e-6);
      }
    }
  }
  EXPECT_GT(seen, camera.width() * camera.height() / 2);
  EXPECT_LT(seen, camera.width() * camera.height());
}

TEST(InversePerspectiveMapTest, NearRangeOfThePapersCameraIsAboutElevenCentimetres) {
  const camera::CameraModel camera =
      io::LoadCameraFile(std::string(PIROUETTE_WORLDS_DIR) + "/yujin.yaml");
  const double near = NearRange(InversePerspectiveMap(camera));
  EXPECT_GT(near, 0.08);
  EXPECT_LT(near, 0.14);
}

}  // namespace
}  // namespace pirouette::camera
