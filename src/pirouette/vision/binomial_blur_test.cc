#include "pirouette/vision/binomial_blur.h"

#include <gtest/gtest.h>

#include <cmath>
#include <opencv2/imgproc.hpp>

namespace pirouette::vision {
namespace {

cv::Mat RandomImage(int rows, int cols, int type, int seed) {
  cv::Mat image(rows, cols, type);
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  return image;
}

// The binomial kernel of `order` as OpenCV's separable filter, in floating
// point, rounded to nearest (halves up) at the end only.
cv::Mat Reference(const cv::Mat& src, int order) {
  cv::Mat kernel(1, order + 1, CV_64F);
  double c = 1.0;
  for (int k = 0; k <= order; ++k) {
    kernel.at<double>(0, k) = c / std::pow(2.0, order);
    c = c * (order - k) / (k + 1);
  }
  cv::Mat wide;
  src.convertTo(wide, CV_64F);
  cv::Mat filtered;
  cv::sepFilter2D(wide, filtered, CV_64F, kernel, kernel, cv::Point(-1, -1), 0.0,
                  cv::BORDER_REFLECT_101);
  cv::Mat out(src.size(), src.type());
  const cv::Mat flat = filtered.reshape(1);
  cv::Mat flat_out = out.reshape(1);
  for (int v = 0; v < flat.rows; ++v) {
    for (int u = 0; u < flat.cols; ++u) {
      flat_out.at<std::uint8_t>(v, u) =
          cv::saturate_cast<std::uint8_t>(std::floor(flat.at<double>(v, u) + 0.5));
    }
  }
  return out;
}

TEST(BinomialBlurTest, OrderHasTheGaussiansVariance) {
  EXPECT_EQ(BinomialOrder(0.0), 0);
  EXPECT_EQ(BinomialOrder(-1.0), 0);
  EXPECT_EQ(BinomialOrder(1.0), 4);  // [1 4 6 4 1] / 16, variance 1
  EXPECT_EQ(BinomialOrder(0.7), 2);  // [1 2 1] / 4, variance 0.5
  EXPECT_EQ(BinomialOrder(1.5), 10);
}

TEST(BinomialBlurTest, EqualsTheSeparableFilterOnOneAndThreeChannels) {
  for (const int type : {CV_8UC1, CV_8UC3}) {
    for (const int order : {2, 4}) {
      const cv::Mat src = RandomImage(37, 53, type, order);
      cv::Mat blurred;
      BinomialBlur(src, blurred, order);
      ASSERT_EQ(blurred.size(), src.size());
      ASSERT_EQ(blurred.type(), src.type());
      EXPECT_EQ(cv::norm(blurred, Reference(src, order), cv::NORM_INF), 0.0);
    }
  }
}

TEST(BinomialBlurTest, HigherOrdersArePassesOfAtMostFour) {
  const cv::Mat src = RandomImage(30, 40, CV_8UC3, 3);
  cv::Mat blurred;
  BinomialBlur(src, blurred, 10);
  EXPECT_LE(cv::norm(blurred, Reference(src, 10), cv::NORM_INF), 2.0);  // rounded between passes
  cv::Mat copy;
  BinomialBlur(src, copy, 0);
  EXPECT_EQ(cv::norm(copy, src, cv::NORM_INF), 0.0);
  EXPECT_NE(copy.data, src.data);
}

TEST(BinomialBlurTest, KeepsTheOutputBuffer) {
  const cv::Mat src = RandomImage(20, 20, CV_8UC1, 4);
  cv::Mat blurred(src.size(), src.type());
  const std::uint8_t* buffer = blurred.data;
  BinomialBlur(src, blurred, 4);
  EXPECT_EQ(blurred.data, buffer);
}

}  // namespace
}  // namespace pirouette::vision
