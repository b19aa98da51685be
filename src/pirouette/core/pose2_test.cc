#include "pirouette/core/pose2.h"

#include <gtest/gtest.h>

#include <numbers>

namespace pirouette::core {
namespace {

constexpr double kPi = std::numbers::pi;

TEST(AngleTest, NormalizesIntoHalfOpenInterval) {
  EXPECT_DOUBLE_EQ(NormalizeAngle(kPi), kPi);
  EXPECT_DOUBLE_EQ(NormalizeAngle(-kPi), kPi);
  EXPECT_NEAR(NormalizeAngle(3 * kPi + 0.1), -kPi + 0.1, 1e-12);
  EXPECT_NEAR(NormalizeAngle(DegToRad(370)), DegToRad(10), 1e-12);
  EXPECT_DOUBLE_EQ(RadToDeg(DegToRad(123.5)), 123.5);
}

TEST(Pose2Test, TransformsPointsIntoTheParentFrame) {
  const Pose2 world_T_robot(1.0, 2.0, kPi / 2);
  const Eigen::Vector2d p_world = world_T_robot * Eigen::Vector2d(1.0, 0.0);
  EXPECT_NEAR(p_world.x(), 1.0, 1e-12);
  EXPECT_NEAR(p_world.y(), 3.0, 1e-12);
}

TEST(Pose2Test, ComposesAndInverts) {
  const Pose2 a(0.3, -1.2, 0.7);
  const Pose2 b(-2.0, 0.5, -2.9);
  const Pose2 ab = a * b;
  const Eigen::Vector2d p(0.25, 4.0);
  EXPECT_TRUE(((ab * p) - (a * (b * p))).norm() < 1e-12);
  const Pose2 identity = a * a.Inverse();
  EXPECT_NEAR(identity.x(), 0.0, 1e-12);
  EXPECT_NEAR(identity.y(), 0.0, 1e-12);
  EXPECT_NEAR(identity.heading(), 0.0, 1e-12);
}

}  // namespace
}  // namespace pirouette::core
