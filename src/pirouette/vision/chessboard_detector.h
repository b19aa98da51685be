#pragma once

#include <opencv2/core.hpp>
#include <optional>
#include <vector>

namespace pirouette::vision {

// Finds a printed calibration chessboard's inner corners in a photo, to a
// fraction of a pixel. Robust to uneven light and large photos: OpenCV's
// findChessboardCorners (adaptive threshold, normalised image) first, then
// findChessboardCornersSB (the sector-based detector, Duda & Frese 2018) when
// that fails; photos larger than kDetectMaxSide are searched at a reduced
// size, and every corner is then refined with cornerSubPix on the full image,
// in a window sized to its distance to its neighbours.
class ChessboardDetector {
 public:
  static constexpr int kDetectMaxSide = 1600;  // pixels: larger photos are reduced to search

  // `pattern`: the board's inner corners, (cols, rows) as OpenCV's patternSize,
  // both >= 2 (a bug otherwise: callers check input).
  explicit ChessboardDetector(cv::Size pattern);

  cv::Size pattern() const { return pattern_; }

  // The cols × rows inner corners in pixels (pixel centres at integers), in
  // OpenCV's order (row by row, starting from one end of the board), or nullopt
  // when the whole board is not found. `image`: 8-bit grey, BGR or BGRA
  // (16-bit images are scaled to 8 bits).
  std::optional<std::vector<cv::Point2f>> Find(const cv::Mat& image) const;

 private:
  cv::Size pattern_;
};

}  // namespace pirouette::vision
