#include "pirouette/vision/vignetting_fit.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>
#include <random>
#include <stdexcept>

#include "pirouette/testing/test_camera.h"

namespace pirouette::vision {
namespace {

// A flat field through the camera's vignetting: channel c's level at the
// principal point is `centre` (R, G, B), with Gaussian noise, rounded.
cv::Mat3b FlatField(const camera::CameraModel& camera, const std::array<double, 3>& centre,
                    double sigma, unsigned seed) {
  std::mt19937 rng(seed);
  std::normal_distribution<double> noise(0.0, sigma);
  cv::Mat3b bgr(camera.height(), camera.width());
  for (int v = 0; v < bgr.rows; ++v) {
    for (int u = 0; u < bgr.cols; ++u) {
      for (int c = 0; c < 3; ++c) {
        const double value =
            centre[static_cast<std::size_t>(c)] * camera.VignettingGain(c, Eigen::Vector2d(u, v)) +
            noise(rng);
        bgr(v, u)[2 - c] = cv::saturate_cast<std::uint8_t>(std::round(value));
      }
    }
  }
  return bgr;
}

TEST(VignettingFitTest, RecoversEachChannelsK) {
  const camera::CameraModel camera = testing::PaperCamera();  // k = 0.35, 0.30, 0.40
  const VignettingFit fit = FitVignetting(FlatField(camera, {180, 200, 150}, 2.0, 1), camera);
  EXPECT_NEAR(fit.vignetting.k[0], 0.35, 0.01);
  EXPECT_NEAR(fit.vignetting.k[1], 0.30, 0.01);
  EXPECT_NEAR(fit.vignetting.k[2], 0.40, 0.01);
  EXPECT_NEAR(fit.centre_level[0], 180.0, 1.0);
  EXPECT_NEAR(fit.centre_level[1], 200.0, 1.0);
  EXPECT_NEAR(fit.centre_level[2], 150.0, 1.0);
  EXPECT_GT(fit.blocks_used, fit.blocks * 9 / 10);
  for (int c = 0; c < 3; ++c) {
    EXPECT_LT(fit.rms_relative[static_cast<std::size_t>(c)], 0.01);
    EXPECT_FALSE(fit.clamped[static_cast<std::size_t>(c)]);
  }
}

TEST(VignettingFitTest, IgnoresSaturatedAndStainedPatches) {
  const camera::CameraModel camera = testing::PaperCamera();
  cv::Mat3b bgr = FlatField(camera, {180, 200, 150}, 2.0, 2);
  cv::rectangle(bgr, cv::Rect(150, 110, 30, 20), cv::Scalar(255, 255, 255), cv::FILLED);  // glare
  cv::circle(bgr, cv::Point(60, 60), 12, cv::Scalar(60, 70, 80), cv::FILLED);             // a stain
  const VignettingFit fit = FitVignetting(bgr, camera);
  EXPECT_NEAR(fit.vignetting.k[0], 0.35, 0.015);
  EXPECT_NEAR(fit.vignetting.k[1], 0.30, 0.015);
  EXPECT_NEAR(fit.vignetting.k[2], 0.40, 0.015);
}

TEST(VignettingFitTest, CornersBrighterThanTheCentreGiveZero) {
  const camera::CameraModel camera = testing::PaperCamera();
  cv::Mat3b bgr(camera.height(), camera.width());
  for (int v = 0; v < bgr.rows; ++v) {
    for (int u = 0; u < bgr.cols; ++u) {
      const double rho2 = ((u - 159.5) * (u - 159.5) + (v - 119.5) * (v - 119.5)) /
                          camera.vignetting_r_max_squared();
      bgr(v, u) = cv::Vec3b::all(cv::saturate_cast<std::uint8_t>(100.0 * (1.0 + 0.2 * rho2)));
    }
  }
  const VignettingFit fit = FitVignetting(bgr, camera);
  for (int c = 0; c < 3; ++c) {
    EXPECT_EQ(fit.vignetting.k[static_cast<std::size_t>(c)], 0.0);
    EXPECT_TRUE(fit.clamped[static_cast<std::size_t>(c)]);
  }
}

TEST(VignettingFitTest, RefusesAnOverexposedPhoto) {
  const camera::CameraModel camera = testing::PaperCamera();
  const cv::Mat3b white(camera.height(), camera.width(), cv::Vec3b(255, 255, 255));
  EXPECT_THROW(FitVignetting(white, camera), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::vision
