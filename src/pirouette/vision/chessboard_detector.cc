#include "pirouette/vision/chessboard_detector.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <opencv2/calib3d.hpp>
#include <opencv2/imgproc.hpp>

namespace pirouette::vision {
namespace {

cv::Mat ToGrey8(const cv::Mat& image) {
  cv::Mat eight = image;
  if (image.depth() != CV_8U) {
    double lo = 0.0;
    double hi = 0.0;
    cv::minMaxLoc(image.reshape(1), &lo, &hi);
    image.convertTo(eight, CV_8U, hi > lo ? 255.0 / (hi - lo) : 1.0,
                    hi > lo ? -lo * 255.0 / (hi - lo) : 0.0);
  }
  cv::Mat grey;
  switch (eight.channels()) {
    case 1:
      grey = eight;
      break;
    case 3:
      cv::cvtColor(eight, grey, cv::COLOR_BGR2GRAY);
      break;
    case 4:
      cv::cvtColor(eight, grey, cv::COLOR_BGRA2GRAY);
      break;
    default:
      CV_Error(cv::Error::StsBadArg, "ChessboardDetector: expected 1, 3 or 4 channels");
  }
  return grey;
}

std::optional<std::vector<cv::Point2f>> Detect(const cv::Mat& grey, cv::Size pattern) {
  std::vector<cv::Point2f> corners;
  if (cv::findChessboardCorners(grey, pattern, corners,
                                cv::CALIB_CB_ADAPTIVE_THRESH | cv::CALIB_CB_NORMALIZE_IMAGE)) {
    return corners;
  }
  corners.clear();
  if (cv::findChessboardCornersSB(
          grey, pattern, corners,
          cv::CALIB_CB_NORMALIZE_IMAGE | cv::CALIB_CB_EXHAUSTIVE | cv::CALIB_CB_ACCURACY)) {
    return corners;
  }
  return std::nullopt;
}

// Corner (c, r)'s index in OpenCV's row-by-row order.
std::size_t CornerIndex(cv::Size pattern, int c, int r) {
  return static_cast<std::size_t>(r) * static_cast<std::size_t>(pattern.width) +
         static_cast<std::size_t>(c);
}

// The distance from corner (c, r) to its nearest neighbour in the grid.
double NeighbourDistance(const std::vector<cv::Point2f>& corners, cv::Size pattern, int c, int r) {
  double nearest = std::numeric_limits<double>::infinity();
  const cv::Point2f& p = corners[CornerIndex(pattern, c, r)];
  for (const auto& [dc, dr] :
       {std::pair{1, 0}, std::pair{-1, 0}, std::pair{0, 1}, std::pair{0, -1}}) {
    const int nc = c + dc;
    const int nr = r + dr;
    if (nc < 0 || nc >= pattern.width || nr < 0 || nr >= pattern.height) continue;
    nearest = std::min(nearest, cv::norm(p - corners[CornerIndex(pattern, nc, nr)]));
  }
  return nearest;
}

}  // namespace

ChessboardDetector::ChessboardDetector(cv::Size pattern) : pattern_(pattern) {
  CV_Assert(pattern.width >= 2 && pattern.height >= 2);
}

std::optional<std::vector<cv::Point2f>> ChessboardDetector::Find(const cv::Mat& image) const {
  if (image.empty()) return std::nullopt;
  const cv::Mat grey = ToGrey8(image);
  const int side = std::max(grey.cols, grey.rows);
  std::optional<std::vector<cv::Point2f>> found;
  if (side > kDetectMaxSide) {
    const double scale = static_cast<double>(kDetectMaxSide) / side;
    cv::Mat small;
    cv::resize(grey, small, cv::Size(), scale, scale, cv::INTER_AREA);
    found = Detect(small, pattern_);
    if (found) {
      // A pixel centre (u, v) of the reduced image lies at ((u + ½) / s - ½, …) in the full one.
      for (cv::Point2f& p : *found) {
        p.x = static_cast<float>((p.x + 0.5) / scale - 0.5);
        p.y = static_cast<float>((p.y + 0.5) / scale - 0.5);
      }
    }
  } else {
    found = Detect(grey, pattern_);
  }
  if (!found || found->size() != static_cast<std::size_t>(pattern_.area())) return std::nullopt;

  // cornerSubPix's window must hold one corner only: at most ~0.4 of the
  // distance to the nearest neighbour, so each corner gets its own window.
  std::vector<cv::Point2f>& corners = *found;
  const std::vector<cv::Point2f> coarse = corners;
  const cv::TermCriteria criteria(cv::TermCriteria::EPS + cv::TermCriteria::COUNT, 50, 1e-3);
  for (int r = 0; r < pattern_.height; ++r) {
    for (int c = 0; c < pattern_.width; ++c) {
      const double spacing = NeighbourDistance(coarse, pattern_, c, r);
      const int half = std::clamp(static_cast<int>(0.4 * spacing), 1, 15);
      std::vector<cv::Point2f> one = {coarse[CornerIndex(pattern_, c, r)]};
      cv::cornerSubPix(grey, one, cv::Size(half, half), cv::Size(-1, -1), criteria);
      corners[CornerIndex(pattern_, c, r)] = one[0];
    }
  }
  return found;
}

}  // namespace pirouette::vision
