#include "pirouette/vision/chessboard_detector.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>
#include <vector>

namespace pirouette::vision {
namespace {

// A printed board seen through a homography: `pattern` inner corners,
// squares of `square` pixels and a white margin, warped into an image of
// `size`, blurred a little as a lens does. `corners` receives the true corners.
cv::Mat WarpedBoard(cv::Size pattern, int square, cv::Size size, const cv::Matx33d& homography,
                    std::vector<cv::Point2f>* corners) {
  const int cols = pattern.width + 3;  // squares plus a margin of one square each side
  const int rows = pattern.height + 3;
  cv::Mat board(rows * square, cols * square, CV_8UC1, cv::Scalar(230));
  for (int j = 1; j < rows - 1; ++j) {
    for (int i = 1; i < cols - 1; ++i) {
      if ((i + j) % 2 == 0) {
        cv::rectangle(board, cv::Rect(i * square, j * square, square, square), cv::Scalar(25),
                      cv::FILLED);
      }
    }
  }
  std::vector<cv::Point2f> flat;
  for (int r = 0; r < pattern.height; ++r) {
    for (int c = 0; c < pattern.width; ++c) {
      // A corner between squares lies on a pixel boundary: at -0.5 in pixel-centre coordinates.
      flat.emplace_back(static_cast<float>((c + 2) * square - 0.5),
                        static_cast<float>((r + 2) * square - 0.5));
    }
  }
  cv::Mat image;
  cv::warpPerspective(board, image, homography, size, cv::INTER_AREA, cv::BORDER_CONSTANT,
                      cv::Scalar(110));
  cv::GaussianBlur(image, image, cv::Size(0, 0), 0.7);
  cv::perspectiveTransform(flat, *corners, homography);
  return image;
}

// The largest distance from a found corner to the true one, either order of the grid.
double WorstError(const std::vector<cv::Point2f>& found, const std::vector<cv::Point2f>& truth) {
  double forward = 0.0;
  double backward = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    forward = std::max(forward, static_cast<double>(cv::norm(found[i] - truth[i])));
    backward =
        std::max(backward, static_cast<double>(cv::norm(found[i] - truth[truth.size() - 1 - i])));
  }
  return std::min(forward, backward);
}

TEST(ChessboardDetectorTest, FindsTheCornersOfAWarpedBoardToAFractionOfAPixel) {
  const cv::Size pattern(9, 6);
  const cv::Matx33d homography(0.9, 0.15, 60.0, -0.05, 0.8, 50.0, 0.0002, 0.0004, 1.0);
  std::vector<cv::Point2f> truth;
  const cv::Mat image = WarpedBoard(pattern, 40, cv::Size(640, 480), homography, &truth);
  cv::Mat bgr;
  cv::cvtColor(image, bgr, cv::COLOR_GRAY2BGR);
  const auto found = ChessboardDetector(pattern).Find(bgr);
  ASSERT_TRUE(found.has_value());
  ASSERT_EQ(found->size(), truth.size());
  EXPECT_LT(WorstError(*found, truth), 0.25);
}

TEST(ChessboardDetectorTest, LargePhotosAreSearchedReducedAndRefinedInFull) {
  const cv::Size pattern(7, 5);
  const cv::Matx33d homography(2.2, 0.3, 300.0, -0.1, 2.0, 250.0, 0.0001, 0.0002, 1.0);
  std::vector<cv::Point2f> truth;
  const cv::Mat image = WarpedBoard(pattern, 80, cv::Size(3000, 2200), homography, &truth);
  const auto found = ChessboardDetector(pattern).Find(image);
  ASSERT_TRUE(found.has_value());
  EXPECT_LT(WorstError(*found, truth), 0.2);
}

TEST(ChessboardDetectorTest, NoBoardOrAnotherPatternIsNotFound) {
  const cv::Mat blank(240, 320, CV_8UC3, cv::Scalar(120, 120, 120));
  EXPECT_FALSE(ChessboardDetector(cv::Size(9, 6)).Find(blank).has_value());
  EXPECT_FALSE(ChessboardDetector(cv::Size(9, 6)).Find(cv::Mat()).has_value());
  std::vector<cv::Point2f> truth;
  const cv::Mat image = WarpedBoard(cv::Size(5, 4), 40, cv::Size(480, 360),
                                    cv::Matx33d(1, 0, 40, 0, 1, 40, 0, 0, 1), &truth);
  EXPECT_FALSE(ChessboardDetector(cv::Size(9, 6)).Find(image).has_value());
  EXPECT_TRUE(ChessboardDetector(cv::Size(5, 4)).Find(image).has_value());
}

}  // namespace
}  // namespace pirouette::vision
