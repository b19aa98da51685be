#include "pirouette/vision/vertical_direction_field.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pirouette/testing/test_camera.h"

namespace pirouette::vision {
namespace {

// The angle, in degrees, between two image directions.
double AngleDeg(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return std::acos(std::clamp(a.normalized().dot(b.normalized()), -1.0, 1.0)) * 180.0 / M_PI;
}

TEST(VerticalDirectionFieldTest, MatchesProjectedVerticalLines) {
  const camera::CameraModel camera = testing::PaperCamera();
  const VerticalDirectionField field(camera);
  const Eigen::Isometry3d camera_T_robot = camera.robot_T_camera().inverse();
  int checked = 0;
  double largest_lean = 0.0;
  // Vertical lines standing on the floor ahead of the robot, across the view.
  for (double x = 0.15; x <= 0.6; x += 0.05) {
    for (double y = -0.4; y <= 0.4; y += 0.05) {
      const auto foot = camera.Project(camera_T_robot * Eigen::Vector3d(x, y, 0.0));
      const auto head = camera.Project(camera_T_robot * Eigen::Vector3d(x, y, 0.004));
      if (!foot || !head) continue;
      const int u = static_cast<int>(std::lround(foot->x()));
      const int v = static_cast<int>(std::lround(foot->y()));
      if (u < 2 || v < 2 || u >= camera.width() - 2 || v >= camera.height() - 2) continue;
      const cv::Vec2f d = field.At(u, v);
      const Eigen::Vector2d expected = *head - *foot;
      EXPECT_LT(AngleDeg(Eigen::Vector2d(d[0], d[1]), expected), 1.0) << x << ", " << y;
      largest_lean = std::max(largest_lean, AngleDeg(expected, Eigen::Vector2d(0.0, -1.0)));
      ++checked;
    }
  }
  EXPECT_GT(checked, 50);
  // In the tilted camera verticals lean visibly away from the image's columns.
  EXPECT_GT(largest_lean, 10.0);
}

TEST(VerticalDirectionFieldTest, PointsUpTheImageAtTheCentreColumn) {
  const VerticalDirectionField field(testing::PaperCamera());
  const cv::Vec2f d = field.At(160, 200);
  EXPECT_NEAR(d[0], 0.0, 0.01);
  EXPECT_NEAR(d[1], -1.0, 0.01);
}

TEST(VerticalDirectionFieldTest, WithoutACameraVerticalIsUpTheImage) {
  const VerticalDirectionField field(160, 120);
  EXPECT_EQ(field.width(), 160);
  EXPECT_EQ(field.height(), 120);
  EXPECT_EQ(field.At(0, 0), cv::Vec2f(0.0f, -1.0f));
}

TEST(VerticalDirectionFieldTest, AReducedGridTakesTheDirectionAtItsBlocksCentre) {
  const camera::CameraModel camera = testing::PaperCamera();
  const VerticalDirectionField full(camera);
  const VerticalDirectionField reduced(camera, 2);
  EXPECT_EQ(reduced.width(), 160);
  EXPECT_EQ(reduced.height(), 120);
  for (int v = 0; v < 120; v += 7) {
    for (int u = 0; u < 160; u += 9) {
      // The block's centre lies between four pixels; the field is smooth.
      const cv::Vec2f a = reduced.At(u, v);
      const cv::Vec2f b = full.At(2 * u, 2 * v);
      EXPECT_LT(AngleDeg({a[0], a[1]}, {b[0], b[1]}), 1.0) << u << ", " << v;
    }
  }
}

}  // namespace
}  // namespace pirouette::vision
