#include "pirouette/vision/texture_feature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "pirouette/vision/binomial_blur.h"

namespace pirouette::vision {
namespace {

// A frame with smooth areas, fine noise and a few edges.
cv::Mat3b TexturedFrame(cv::Size size, int seed) {
  cv::Mat3b frame(size, cv::Vec3b(90, 110, 130));
  cv::Mat noise(size, CV_16SC3);
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  rng.fill(noise, cv::RNG::NORMAL, 0, 6);
  cv::Mat3s wide;
  frame.convertTo(wide, CV_16SC3);
  wide(cv::Rect(0, size.height / 2, size.width, size.height / 2)) +=
      noise(cv::Rect(0, size.height / 2, size.width, size.height / 2));
  wide.convertTo(frame, CV_8UC3);
  cv::rectangle(frame, cv::Rect(size.width / 4, size.height / 5, size.width / 3, size.height / 4),
                cv::Scalar(40, 200, 60), cv::FILLED);
  return frame;
}

// The feature by its definition, with OpenCV: the low-passed grey's
// |Sobel_x| + |Sobel_y| over 8, its mean over each cell's window.
cv::Mat1b Reference(const cv::Mat3b& frame, int scale, int window) {
  cv::Mat1b grey;
  cv::cvtColor(frame, grey, cv::COLOR_BGR2GRAY);
  cv::Mat blurred;
  BinomialBlur(grey, blurred, 4);
  cv::Mat1f dx;
  cv::Mat1f dy;
  cv::Sobel(blurred, dx, CV_32F, 1, 0, 3, 0.125);
  cv::Sobel(blurred, dy, CV_32F, 0, 1, 3, 0.125);
  const cv::Mat1f magnitude = cv::abs(dx) + cv::abs(dy);
  cv::Mat1f padded;
  const int before = window / 2;
  const int after = window - 1 - before;
  cv::copyMakeBorder(magnitude, padded, before, after + scale, before, after + scale,
                     cv::BORDER_REFLECT_101);
  cv::Mat1b bins(frame.rows / scale, frame.cols / scale);
  const int side = scale + window - 1;
  for (int cy = 0; cy < bins.rows; ++cy) {
    for (int cx = 0; cx < bins.cols; ++cx) {
      // (A mean right on a bin's bound, such as m = 3 on a uniform step,
      // comes out of the floating-point sum a hair below it.)
      const double mean = cv::mean(padded(cv::Rect(cx * scale, cy * scale, side, side)))[0];
      bins(cy, cx) = static_cast<std::uint8_t>(std::min(15.0, 3.0 * std::log2(1.0 + mean) + 1e-9));
    }
  }
  return bins;
}

TEST(TextureFeatureTest, MatchesItsDefinitionAtScaleOneAndReduced) {
  const cv::Mat3b frame = TexturedFrame(cv::Size(96, 72), 1);
  for (const int scale : {1, 2, 3, 4}) {
    TextureFeature feature(scale, 5, 4, std::nullopt);
    const cv::Mat1b& bins = feature.Bins(frame);
    const cv::Mat1b expected = Reference(frame, scale, 5);
    ASSERT_EQ(bins.size(), expected.size()) << "scale " << scale;
    EXPECT_EQ(cv::countNonZero(bins != expected), 0) << "scale " << scale;
  }
}

TEST(TextureFeatureTest, SmoothIsLowTexturedIsHigh) {
  const cv::Mat3b frame = TexturedFrame(cv::Size(160, 120), 2);
  TextureFeature feature(2, 5, 4, std::nullopt);
  const cv::Mat1b& bins = feature.Bins(frame);
  EXPECT_EQ(bins(5, 70), 0);   // the smooth top, away from the box
  EXPECT_GE(bins(50, 40), 2);  // the noisy bottom half
  EXPECT_GE(bins(12, 30), 4);  // on the box's top edge (full-resolution row 24)
}

}  // namespace
}  // namespace pirouette::vision
