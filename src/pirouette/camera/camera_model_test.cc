#include "pirouette/camera/camera_model.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/calib3d.hpp>
#include <opencv2/core.hpp>
#include <stdexcept>
#include <vector>

#include "pirouette/core/angle.h"

namespace pirouette::camera {
namespace {

// The paper's camera (a Yujin robot's, 320 × 240) with a strong barrel distortion.
constexpr Intrinsics kPaperIntrinsics{277.13, 277.13, 159.5, 119.5};
constexpr PlumbBob kBarrel{-0.20, 0.05, 0.001, -0.0005, 0.0};
constexpr Mount kMount{0.11, core::DegToRad(30.0), 0.03};

CameraModel PaperCamera(const PlumbBob& distortion = kBarrel, const Vignetting& vignetting = {}) {
  return {"paper", 320, 240, kPaperIntrinsics, distortion, kMount, vignetting};
}

cv::Matx33d CameraMatrix(const Intrinsics& k) {
  return {k.fx, 0.0, k.cx, 0.0, k.fy, k.cy, 0.0, 0.0, 1.0};
}

cv::Mat DistortionCoefficients(const PlumbBob& d) {
  cv::Mat coefficients = (cv::Mat_<double>(1, 5) << d.k1, d.k2, d.p1, d.p2, d.k3);
  return coefficients;
}

// Pixels every 4 columns and rows, with the far edges and a sub-pixel offset.
std::vector<Eigen::Vector2d> DensePixels(const CameraModel& camera) {
  std::vector<Eigen::Vector2d> pixels;
  for (double v = 0.0; v <= camera.height() - 1; v += 4.0) {
    for (double u = 0.0; u <= camera.width() - 1; u += 4.0) {
      pixels.emplace_back(u, v);
      pixels.emplace_back(u + 0.37, v + 0.81);
    }
    pixels.emplace_back(camera.width() - 1, v);
  }
  for (double u = 0.0; u <= camera.width() - 1; u += 4.0) {
    pixels.emplace_back(u, camera.height() - 1);
  }
  pixels.emplace_back(camera.width() - 1, camera.height() - 1);
  return pixels;
}

TEST(CameraModelTest, RefusesBadValues) {
  EXPECT_THROW(CameraModel("bad", 0, 240, kPaperIntrinsics, {}, kMount, {}), std::invalid_argument);
  EXPECT_THROW(CameraModel("bad", 320, 240, {0.0, 277.0, 159.5, 119.5}, {}, kMount, {}),
               std::invalid_argument);
  EXPECT_THROW(CameraModel("bad", 320, 240, kPaperIntrinsics, {}, {0.0, 0.5, 0.0}, {}),
               std::invalid_argument);
}

TEST(CameraModelTest, RefusesCoefficientsItsModelDoesNotUse) {
  Distortion fisheye;
  fisheye.model = Distortion::Model::kEquidistant;
  fisheye.p1 = 0.01;
  EXPECT_THROW(CameraModel("bad", 320, 240, kPaperIntrinsics, fisheye, kMount, {}),
               std::invalid_argument);
  Distortion plumb_bob;
  plumb_bob.k4 = 0.1;
  EXPECT_THROW(CameraModel("bad", 320, 240, kPaperIntrinsics, plumb_bob, kMount, {}),
               std::invalid_argument);
}

TEST(CameraModelTest, BackprojectThenProjectReturnsThePixel) {
  const CameraModel camera = PaperCamera();
  for (const Eigen::Vector2d& pixel : DensePixels(camera)) {
    const Eigen::Vector3d ray = camera.Backproject(pixel);
    EXPECT_NEAR(ray.norm(), 1.0, 1e-12);
    const std::optional<Eigen::Vector2d> projected = camera.Project(ray);
    ASSERT_TRUE(projected.has_value());
    EXPECT_NEAR((*projected - pixel).norm(), 0.0, 1e-6) << pixel.transpose();
    // Any point along the ray projects there too.
    EXPECT_NEAR((*camera.Project(3.7 * ray) - pixel).norm(), 0.0, 1e-6);
  }
}

TEST(CameraModelTest, DistortAgreesWithOpenCvProjectPoints) {
  const CameraModel camera = PaperCamera();
  std::vector<cv::Point3d> points;
  for (double y = -0.5; y <= 0.5; y += 0.05) {
    for (double x = -0.7; x <= 0.7; x += 0.05) points.emplace_back(x, y, 1.0);
  }
  std::vector<cv::Point2d> cv_pixels;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), CameraMatrix(kPaperIntrinsics),
                    DistortionCoefficients(kBarrel), cv_pixels);
  ASSERT_EQ(cv_pixels.size(), points.size());
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d distorted = camera.Distort({points[i].x, points[i].y});
    const double u = kPaperIntrinsics.fx * distorted.x() + kPaperIntrinsics.cx;
    const double v = kPaperIntrinsics.fy * distorted.y() + kPaperIntrinsics.cy;
    EXPECT_NEAR(u, cv_pixels[i].x, 1e-9);
    EXPECT_NEAR(v, cv_pixels[i].y, 1e-9);
    // And Project is the same with the intrinsics.
    const Eigen::Vector2d projected =
        *camera.Project(Eigen::Vector3d(points[i].x, points[i].y, 1.0));
    EXPECT_NEAR(projected.x(), cv_pixels[i].x, 1e-9);
    EXPECT_NEAR(projected.y(), cv_pixels[i].y, 1e-9);
  }
}

TEST(CameraModelTest, DistortWithK3AndTangentialAgreesWithOpenCv) {
  const PlumbBob distortion{-0.31, 0.12, -0.002, 0.003, -0.02};
  const CameraModel camera = PaperCamera(distortion);
  std::vector<cv::Point3d> points;
  for (double y = -0.45; y <= 0.45; y += 0.09) {
    for (double x = -0.6; x <= 0.6; x += 0.08) points.emplace_back(x, y, 1.0);
  }
  std::vector<cv::Point2d> cv_pixels;
  cv::projectPoints(points, cv::Vec3d(0, 0, 0), cv::Vec3d(0, 0, 0), CameraMatrix(kPaperIntrinsics),
                    DistortionCoefficients(distortion), cv_pixels);
  for (std::size_t i = 0; i < points.size(); ++i) {
    const Eigen::Vector2d projected =
        *camera.Project(Eigen::Vector3d(points[i].x, points[i].y, 1.0));
    EXPECT_NEAR(projected.x(), cv_pixels[i].x, 1e-9);
    EXPECT_NEAR(projected.y(), cv_pixels[i].y, 1e-9);
  }
}

TEST(CameraModelTest, UndistortAgreesWithOpenCvUndistortPoints) {
  const CameraModel camera = PaperCamera();
  const std::vector<Eigen::Vector2d> pixels = DensePixels(camera);
  std::vector<cv::Point2d> cv_pixels;
  cv_pixels.reserve(pixels.size());
  for (const Eigen::Vector2d& pixel : pixels) cv_pixels.emplace_back(pixel.x(), pixel.y());
  std::vector<cv::Point2d> cv_undistorted;
  // OpenCV's fixed-point iteration, run until it has converged.
  cv::undistortPoints(
      cv_pixels, cv_undistorted, CameraMatrix(kPaperIntrinsics), DistortionCoefficients(kBarrel),
      cv::noArray(), cv::noArray(),
      cv::TermCriteria(cv::TermCriteria::COUNT | cv::TermCriteria::EPS, 1000, 1e-15));
  ASSERT_EQ(cv_undistorted.size(), pixels.size());
  for (std::size_t i = 0; i < pixels.size(); ++i) {
    const Eigen::Vector2d distorted((pixels[i].x() - kPaperIntrinsics.cx) / kPaperIntrinsics.fx,
                                    (pixels[i].y() - kPaperIntrinsics.cy) / kPaperIntrinsics.fy);
    const Eigen::Vector2d undistorted = camera.Undistort(distorted);
    EXPECT_NEAR(undistorted.x(), cv_undistorted[i].x, 1e-6) << pixels[i].transpose();
    EXPECT_NEAR(undistorted.y(), cv_undistorted[i].y, 1e-6) << pixels[i].transpose();
    // Newton's method converges much further than that.
    EXPECT_NEAR((camera.Distort(undistorted) - distorted).norm(), 0.0, 1e-12);
  }
}

TEST(CameraModelTest, WithoutDistortionUndistortIsTheIdentity) {
  const CameraModel camera = PaperCamera(PlumbBob{});
  const Eigen::Vector2d p(0.31, -0.22);
  EXPECT_EQ(camera.Distort(p), p);
  EXPECT_EQ(camera.Undistort(p), p);
  // The principal point's ray is the optical axis.
  const Eigen::Vector3d axis = camera.Backproject({159.5, 119.5});
  EXPECT_NEAR((axis - Eigen::Vector3d::UnitZ()).norm(), 0.0, 1e-15);
}

TEST(CameraModelTest, PointsBehindTheCameraAreNotSeen) {
  const CameraModel camera = PaperCamera();
  EXPECT_FALSE(camera.Project({0.1, 0.1, -1.0}).has_value());
  EXPECT_FALSE(camera.Project({0.1, 0.1, 0.0}).has_value());
  EXPECT_FALSE(camera.Project({0.0, 0.0, -1e-9}).has_value());
  EXPECT_TRUE(camera.Project({0.0, 0.0, 1e-9}).has_value());
}

TEST(CameraModelTest, RobotTCameraIsAProperRotationLookingForwardAndDown) {
  const CameraModel camera = PaperCamera();
  const Eigen::Isometry3d robot_T_camera = camera.robot_T_camera();
  const Eigen::Matrix3d rotation = robot_T_camera.linear();
  EXPECT_NEAR((rotation.transpose() * rotation - Eigen::Matrix3d::Identity()).norm(), 0.0, 1e-15);
  EXPECT_NEAR(rotation.determinant(), 1.0, 1e-15);
  EXPECT_NEAR((robot_T_camera.translation() - Eigen::Vector3d(0.03, 0.0, 0.11)).norm(), 0.0, 0.0);

  const double tilt = core::DegToRad(30.0);
  // The optical axis (camera z): forward, pitched down by the tilt.
  const Eigen::Vector3d axis = rotation * Eigen::Vector3d::UnitZ();
  EXPECT_NEAR((axis - Eigen::Vector3d(std::cos(tilt), 0.0, -std::sin(tilt))).norm(), 0.0, 1e-15);
  EXPECT_NEAR(std::asin(-axis.z()), tilt, 1e-15);
  // Image right (camera x) is the robot's right, -y.
  EXPECT_NEAR((rotation * Eigen::Vector3d::UnitX() - Eigen::Vector3d(0.0, -1.0, 0.0)).norm(), 0.0,
              1e-15);
  // Image down (camera y) points down and, tilted, a little backward.
  const Eigen::Vector3d down = rotation * Eigen::Vector3d::UnitY();
  EXPECT_NEAR((down - Eigen::Vector3d(-std::sin(tilt), 0.0, -std::cos(tilt))).norm(), 0.0, 1e-15);
}

TEST(CameraModelTest, FloorPointOfThePrincipalPoint) {
  // An undistorted camera with its principal point on a pixel's centre.
  const CameraModel camera("centred", 320, 240, {277.13, 277.13, 160.0, 120.0}, {}, kMount, {});
  const std::optional<Eigen::Vector2d> p = camera.FloorPoint({160.0, 120.0});
  ASSERT_TRUE(p.has_value());
  EXPECT_NEAR(p->x(), 0.03 + 0.11 / std::tan(core::DegToRad(30.0)), 1e-12);
  EXPECT_NEAR(p->y(), 0.0, 1e-15);
  // Image left is the robot's left (+y).
  EXPECT_GT(camera.FloorPoint({0.0, 120.0})->y(), 0.0);
}

TEST(CameraModelTest, VignettingGain) {
  const Vignetting vignetting{{0.35, 0.30, 0.40}};
  const CameraModel camera = PaperCamera(kBarrel, vignetting);
  for (int c = 0; c < 3; ++c) {
    const double k = vignetting.k[static_cast<std::size_t>(c)];
    EXPECT_DOUBLE_EQ(camera.VignettingGain(c, {159.5, 119.5}), 1.0);
    // The principal point is central: every corner is farthest.
    for (const Eigen::Vector2d& corner :
         {Eigen::Vector2d(0.0, 0.0), Eigen::Vector2d(319.0, 0.0), Eigen::Vector2d(0.0, 239.0),
          Eigen::Vector2d(319.0, 239.0)}) {
      EXPECT_NEAR(camera.VignettingGain(c, corner), 1.0 / (1.0 + k), 1e-15);
    }
    // Half way out, r/r_max = 1/2.
    EXPECT_NEAR(camera.VignettingGain(c, {159.5 + 159.5 / 2.0, 119.5 + 119.5 / 2.0}),
                1.0 / (1.0 + k / 4.0), 1e-15);
  }

  // An off-centre principal point: the farthest corner is the one opposite.
  const CameraModel off_centre("off", 320, 240, {277.13, 277.13, 150.0, 100.0}, {}, kMount,
                               vignetting);
  EXPECT_DOUBLE_EQ(off_centre.VignettingGain(0, {150.0, 100.0}), 1.0);
  EXPECT_NEAR(off_centre.VignettingGain(0, {319.0, 239.0}), 1.0 / 1.35, 1e-15);
  EXPECT_GT(off_centre.VignettingGain(0, {0.0, 0.0}), 1.0 / 1.35);

  // No vignetting: a gain of 1 everywhere.
  EXPECT_EQ(PaperCamera().VignettingGain(2, {0.0, 0.0}), 1.0);
}

// A fisheye of about 150° across (cv::fisheye's model, ROS's equidistant).
CameraModel FisheyeCamera() {
  const std::vector<double> k = {0.04, -0.012, 0.003, -0.0005};
  return {"fisheye",
          320,
          240,
          {117.0, 117.0, 159.5, 119.5},
          *Distortion::FromCoefficients(Distortion::Model::kEquidistant, k),
          kMount,
          {}};
}

TEST(CameraModelTest, AFisheyesPixelsBackprojectAndProjectBack) {
  const CameraModel camera = FisheyeCamera();
  int seen = 0;
  for (const Eigen::Vector2d& pixel : DensePixels(camera)) {
    const std::optional<Eigen::Vector3d> ray = camera.SeenRay(pixel);
    if (!ray) continue;  // beyond 90° off the axis: the corners
    ++seen;
    EXPECT_NEAR((camera.Backproject(pixel) - *ray).norm(), 0.0, 1e-15);
    if (!(ray->z() > 1e-6)) continue;
    const std::optional<Eigen::Vector2d> projected = camera.Project(*ray);
    ASSERT_TRUE(projected.has_value());
    EXPECT_NEAR((*projected - pixel).norm(), 0.0, 1e-6) << pixel.transpose();
  }
  EXPECT_GT(seen, static_cast<int>(DensePixels(camera).size() * 9 / 10));
  // Across the middle row: about 150° from edge to edge.
  const double left = std::acos(camera.SeenRay({0.0, 119.5})->z());
  const double right = std::acos(camera.SeenRay({319.0, 119.5})->z());
  EXPECT_NEAR(core::RadToDeg(left + right), 150.0, 2.0);
  // A corner lies past 90° off the axis: it sees nothing, and no floor.
  EXPECT_FALSE(camera.SeenRay({0.0, 0.0}).has_value());
  EXPECT_FALSE(camera.FloorPoint({0.0, 239.0}).has_value());
}

}  // namespace
}  // namespace pirouette::camera
