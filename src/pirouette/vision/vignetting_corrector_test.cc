#include "pirouette/vision/vignetting_corrector.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "pirouette/sim/renderer.h"
#include "pirouette/testing/bgr_frame.h"
#include "pirouette/testing/test_camera.h"

namespace pirouette::vision {
namespace {

// A floor far larger than the view, one colour, no texture, no walls: every
// pixel of the frame sees the same flat floor under the same light.
cv::Mat3b RenderUniformFloor(const camera::CameraModel& camera) {
  sim::Floor floor{Eigen::Vector2d(40.0, 40.0), core::Rgb{150, 140, 120}, 0.0};
  sim::RobotSpec robot{core::Pose2(20.0, 20.0, 0.0), 0.04, camera, {}};
  const sim::World world("uniform", floor, std::nullopt, {}, sim::Light{}, robot);
  sim::RenderOptions options;
  options.noise_sigma = 0.0;
  sim::Renderer renderer(world, camera, options);
  return testing::BgrFrame(renderer.Render(core::Pose2(20.0, 20.0, 0.0)));
}

double ChannelSpread(const cv::Mat3b& image, int channel) {
  double lo = 255.0;
  double hi = 0.0;
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      lo = std::min<double>(lo, image(v, u)[channel]);
      hi = std::max<double>(hi, image(v, u)[channel]);
    }
  }
  return hi - lo;
}

TEST(VignettingCorrectorTest, FlattensARenderedUniformFloor) {
  const camera::CameraModel camera = testing::PaperCamera();
  const cv::Mat3b raw = RenderUniformFloor(camera);
  const VignettingCorrector corrector(camera);
  const cv::Mat3b corrected = corrector.Apply(raw);
  for (int c = 0; c < 3; ++c) {
    SCOPED_TRACE(c);
    EXPECT_GT(ChannelSpread(raw, c), 20.0);       // the corners are visibly darker
    EXPECT_LE(ChannelSpread(corrected, c), 3.0);  // flat to rounding
  }
  // The corrected centre keeps its colour: the gain there is 1.
  const cv::Vec3b& centre = corrected(120, 160);
  const cv::Vec3b& raw_centre = raw(120, 160);
  for (int c = 0; c < 3; ++c) EXPECT_NEAR(centre[c], raw_centre[c], 1);
}

TEST(VignettingCorrectorTest, FactorIsTheInverseOfTheCameraGainPerChannel) {
  const camera::CameraModel camera = testing::PaperCamera();
  const VignettingCorrector corrector(camera);
  // OpenCV's channel 0 is blue, the camera's channel 2.
  for (const auto& [u, v] : {std::pair{0, 0}, std::pair{319, 239}, std::pair{100, 50}}) {
    for (int c = 0; c < 3; ++c) {
      const double expected = 1.0 / camera.VignettingGain(2 - c, Eigen::Vector2d(u, v));
      EXPECT_NEAR(corrector.Factor(u, v, c), expected, 1e-3);
    }
  }
  EXPECT_NEAR(corrector.Factor(0, 0, 0), 1.40, 1e-3);  // blue, k = 0.40, at the far corner
}

TEST(VignettingCorrectorTest, SaturatesInsteadOfWrapping) {
  const camera::CameraModel camera = testing::PaperCamera();
  const VignettingCorrector corrector(camera);
  const cv::Mat3b white(240, 320, cv::Vec3b(255, 255, 255));
  const cv::Mat3b out = corrector.Apply(white);
  EXPECT_EQ(out(0, 0), cv::Vec3b(255, 255, 255));
}

TEST(VignettingCorrectorTest, AReducedGridTakesItsBlocksMeanFactor) {
  const camera::CameraModel camera = testing::PaperCamera();
  const VignettingCorrector full(camera);
  const VignettingCorrector reduced(camera, 2);
  EXPECT_EQ(reduced.width(), 160);
  EXPECT_EQ(reduced.height(), 120);
  EXPECT_EQ(reduced.scale(), 2);
  for (const auto& [u, v] : {std::pair{0, 0}, std::pair{80, 60}, std::pair{159, 119}}) {
    for (int c = 0; c < 3; ++c) {
      const double mean =
          0.25 * (full.Factor(2 * u, 2 * v, c) + full.Factor(2 * u + 1, 2 * v, c) +
                  full.Factor(2 * u, 2 * v + 1, c) + full.Factor(2 * u + 1, 2 * v + 1, c));
      EXPECT_NEAR(reduced.Factor(u, v, c), mean, 1e-3);
    }
  }
}

TEST(VignettingCorrectorTest, ReducingAndCorrectingInOnePass) {
  const camera::CameraModel camera = testing::PaperCamera();
  cv::Mat3b raw(240, 320);
  cv::RNG rng(9);
  rng.fill(raw, cv::RNG::UNIFORM, 0, 200);
  for (const int scale : {1, 2, 3, 4}) {
    const VignettingCorrector reduced(camera, scale);
    cv::Mat3b direct;
    reduced.ReduceAndApply(raw, direct);
    cv::Mat3b means;
    ReduceByBlockMean(raw, scale, means);
    ASSERT_EQ(direct.size(), means.size());
    // Correcting the block means (rounded) against correcting the exact sums.
    EXPECT_LE(cv::norm(direct, reduced.Apply(means), cv::NORM_INF), 1.0) << "scale " << scale;
  }
}

TEST(VignettingCorrectorTest, BlockMeansAreOpenCvsAreaReduction) {
  cv::Mat3b raw(48, 64);
  cv::RNG rng(10);
  rng.fill(raw, cv::RNG::UNIFORM, 0, 256);
  for (const int scale : {1, 2, 3, 4}) {
    cv::Mat3b means;
    ReduceByBlockMean(raw, scale, means);
    cv::Mat3b area;
    cv::resize(raw(cv::Rect(0, 0, 64 / scale * scale, 48 / scale * scale)), area,
               cv::Size(64 / scale, 48 / scale), 0.0, 0.0, cv::INTER_AREA);
    EXPECT_LE(cv::norm(means, area, cv::NORM_INF), 1.0) << "scale " << scale;
  }
}

}  // namespace
}  // namespace pirouette::vision
