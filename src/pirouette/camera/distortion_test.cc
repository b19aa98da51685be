#include "pirouette/camera/distortion.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <vector>

namespace pirouette::camera {
namespace {

using Model = Distortion::Model;

// How far off the axis (radians) the lenses below see.
constexpr double kWideAngleMax = 1.04;  // 60°: a 120° field of view
constexpr double kFisheyeMax = 1.5;     // 86°: a 172° field of view

// A wide-angle lens (120° across its diagonal) in OpenCV's rational model.
Distortion WideAngle() {
  const std::array<double, 8> d = {0.1, 0.01, 0.001, -0.0008, 0.0005, 0.45, 0.02, 0.0001};
  return *Distortion::FromCoefficients(Model::kRationalPolynomial, d);
}

// A fisheye lens as cv::fisheye::calibrate fits it.
Distortion Fisheye() {
  const std::array<double, 4> d = {0.04, -0.012, 0.003, -0.0005};
  return *Distortion::FromCoefficients(Model::kEquidistant, d);
}

cv::Mat OpenCvCoefficients(const Distortion& d) {
  const std::vector<double> c = d.Coefficients();
  return cv::Mat(c, true).reshape(1, 1);
}

// Undistorted normalised points up to `max_angle` off the axis, at 24 bearings.
std::vector<Eigen::Vector2d> PointsWithin(double max_angle) {
  std::vector<Eigen::Vector2d> points = {Eigen::Vector2d::Zero()};
  for (double theta = 0.01; theta <= max_angle; theta += 0.02) {
    for (int i = 0; i < 24; ++i) {
      const double bearing = 2.0 * std::numbers::pi * i / 24.0 + 0.1;
      points.push_back(std::tan(theta) * Eigen::Vector2d(std::cos(bearing), std::sin(bearing)));
    }
  }
  return points;
}

TEST(DistortionTest, CoefficientCountsFitTheModel) {
  const std::vector<double> five = {1, 2, 3, 4, 5};
  EXPECT_TRUE(Distortion::FromCoefficients(Model::kPlumbBob, five).has_value());
  EXPECT_FALSE(Distortion::FromCoefficients(Model::kRationalPolynomial, five).has_value());
  EXPECT_FALSE(Distortion::FromCoefficients(Model::kEquidistant, five).has_value());
  EXPECT_EQ(WideAngle().Coefficients(),
            (std::vector<double>{0.1, 0.01, 0.001, -0.0008, 0.0005, 0.45, 0.02, 0.0001}));
  EXPECT_EQ(Fisheye().Coefficients(), (std::vector<double>{0.04, -0.012, 0.003, -0.0005}));
  EXPECT_EQ(Fisheye().k1, 0.04);
  EXPECT_EQ(Fisheye().k4, -0.0005);
  const Distortion plumb_bob(PlumbBob{-0.2, 0.05, 0.001, -0.002, 0.01});
  EXPECT_EQ(plumb_bob.model, Model::kPlumbBob);
  EXPECT_EQ(plumb_bob, *Distortion::FromCoefficients(Model::kPlumbBob,
                                                     std::vector{-0.2, 0.05, 0.001, -0.002, 0.01}));
}

TEST(DistortionTest, ModelNamesAreRos) {
  EXPECT_EQ(ModelName(Model::kPlumbBob), "plumb_bob");
  EXPECT_EQ(ModelNamed("rational_polynomial"), Model::kRationalPolynomial);
  EXPECT_EQ(ModelNamed("equidistant"), Model::kEquidistant);
  EXPECT_FALSE(ModelNamed("fisheye").has_value());
}

TEST(DistortionTest, RationalAgreesWithOpenCvProjectPoints) {
  const Distortion d = WideAngle();
  std::vector<cv::Point3d> points;
  for (const Eigen::Vector2d& p : PointsWithin(kWideAngleMax))
    points.emplace_back(p.x(), p.y(), 1.0);
  std::vector<cv::Point2d> projected;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), cv::Matx33d::eye(),
                    OpenCvCoefficients(d), projected);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d distorted = d.Distort({points[i].x, points[i].y});
    EXPECT_NEAR(distorted.x(), projected[i].x, 1e-12);
    EXPECT_NEAR(distorted.y(), projected[i].y, 1e-12);
  }
}

TEST(DistortionTest, RationalUndistortInvertsDistortAndAgreesWithOpenCv) {
  const Distortion d = WideAngle();
  std::vector<cv::Point2d> distorted;
  for (const Eigen::Vector2d& p : PointsWithin(kWideAngleMax)) {
    const Eigen::Vector2d q = d.Distort(p);
    distorted.emplace_back(q.x(), q.y());
    const std::optional<Eigen::Vector2d> back = d.Undistort(q);
    ASSERT_TRUE(back.has_value()) << p.transpose();
    EXPECT_NEAR((*back - p).norm(), 0.0, 1e-10) << p.transpose();
  }
  std::vector<cv::Point2d> cv_undistorted;
  cv::undistortPoints(
      distorted, cv_undistorted, cv::Matx33d::eye(), OpenCvCoefficients(d), cv::noArray(),
      cv::noArray(),
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 1000, 1e-15));
  for (std::size_t i = 0; i < distorted.size(); ++i) {
    const Eigen::Vector2d ours = *d.Undistort({distorted[i].x, distorted[i].y});
    EXPECT_NEAR(ours.x(), cv_undistorted[i].x, 1e-6);
    EXPECT_NEAR(ours.y(), cv_undistorted[i].y, 1e-6);
  }
}

TEST(DistortionTest, EquidistantAgreesWithOpenCvFisheye) {
  const Distortion d = Fisheye();
  std::vector<cv::Point3d> points;
  std::vector<cv::Point2d> normalised;
  for (const Eigen::Vector2d& p : PointsWithin(kFisheyeMax)) {
    points.emplace_back(p.x(), p.y(), 1.0);
    normalised.emplace_back(p.x(), p.y());
  }
  std::vector<cv::Point2d> projected;
  cv::fisheye::projectPoints(points, projected, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0),
                             cv::Matx33d::eye(), OpenCvCoefficients(d));
  std::vector<cv::Point2d> distorted;
  cv::fisheye::distortPoints(normalised, distorted, cv::Matx33d::eye(), OpenCvCoefficients(d));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d ours = d.Distort({points[i].x, points[i].y});
    EXPECT_NEAR(ours.x(), projected[i].x, 1e-12);
    EXPECT_NEAR(ours.y(), projected[i].y, 1e-12);
    EXPECT_NEAR(ours.x(), distorted[i].x, 1e-12);
    EXPECT_NEAR(ours.y(), distorted[i].y, 1e-12);
  }
  std::vector<cv::Point2d> cv_undistorted;
  cv::fisheye::undistortPoints(
      distorted, cv_undistorted, cv::Matx33d::eye(), OpenCvCoefficients(d), cv::noArray(),
      cv::noArray(),
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 1000, 1e-15));
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d p(points[i].x, points[i].y);
    const std::optional<Eigen::Vector2d> ours = d.Undistort({distorted[i].x, distorted[i].y});
    ASSERT_TRUE(ours.has_value()) << p.transpose();
    // Relative to the point's distance: tan θ is large near 90°.
    const double scale = 1.0 + p.norm();
    EXPECT_NEAR((*ours - p).norm() / scale, 0.0, 1e-10) << p.transpose();
    EXPECT_NEAR(ours->x(), cv_undistorted[i].x, 1e-6 * scale) << p.transpose();
    EXPECT_NEAR(ours->y(), cv_undistorted[i].y, 1e-6 * scale) << p.transpose();
  }
}

TEST(DistortionTest, EquidistantRaysReachNinetyDegrees) {
  const Distortion d = Fisheye();
  for (const double theta : {0.0, 0.3, 1.2, 1.55, 1.5707}) {
    const Eigen::Vector3d truth(std::sin(theta) * std::cos(0.7), std::sin(theta) * std::sin(0.7),
                                std::cos(theta));
    const Eigen::Vector2d image = d.Distort(truth.head<2>() / truth.z());
    const std::optional<Eigen::Vector3d> ray = d.Ray(image);
    ASSERT_TRUE(ray.has_value()) << theta;
    EXPECT_NEAR((*ray - truth).norm(), 0.0, 1e-12) << theta;
    EXPECT_NEAR(ray->norm(), 1.0, 1e-15);
  }
  // Beyond the image of 90°, a fisheye's image circle: nothing is seen.
  const double edge = d.Distort({1e9, 0.0}).x();
  EXPECT_FALSE(d.Ray({edge * 1.01, 0.0}).has_value());
  EXPECT_FALSE(d.Undistort({0.0, -edge * 1.01}).has_value());
  EXPECT_TRUE(d.Undistort({0.0, -edge * 0.99}).has_value());
}

TEST(DistortionTest, AFisheyeThatTurnsBackSeesOnlyItsIncreasingPart) {
  // θd = θ (1 - 0.3 θ²) peaks at θ = 1/√0.9 (about 61°).
  const Distortion d =
      *Distortion::FromCoefficients(Model::kEquidistant, std::vector{-0.3, 0.0, 0.0, 0.0});
  const double peak_theta = 1.0 / std::sqrt(0.9);
  const double peak = peak_theta * (1.0 - 0.3 * peak_theta * peak_theta);
  const std::optional<Eigen::Vector3d> below = d.Ray({0.98 * peak, 0.0});
  ASSERT_TRUE(below.has_value());
  EXPECT_LT(std::acos(below->z()), peak_theta);
  EXPECT_FALSE(d.Ray({1.01 * peak, 0.0}).has_value());
}

TEST(DistortionTest, PlumbBobIsUnchangedByTheWidening) {
  const Distortion d(PlumbBob{-0.2, 0.05, 0.001, -0.0005, 0.0});
  const Eigen::Vector2d p(0.4, -0.3);
  const double r2 = p.squaredNorm();
  const double radial = 1.0 + r2 * (-0.2 + r2 * 0.05);
  EXPECT_NEAR(d.Distort(p).x(),
              p.x() * radial + 2 * 0.001 * p.x() * p.y() - 0.0005 * (r2 + 2 * p.x() * p.x()),
              1e-15);
  EXPECT_NEAR((d.Distort(*d.Undistort(p)) - p).norm(), 0.0, 1e-12);
}

}  // namespace
}  // namespace pirouette::camera
