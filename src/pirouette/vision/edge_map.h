#pragma once

#include <array>
#include <cstdint>
#include <opencv2/core.hpp>
#include <vector>

#include "pirouette/vision/vertical_direction_field.h"

namespace pirouette::vision {

struct EdgeMapOptions {
  double canny_low = 30.0;  // Canny's hysteresis thresholds, on the L2 gradient of 3×3 Sobel
  double canny_high = 90.0;
  // An edge pixel whose edge runs within this angle of the world-vertical
  // direction at that pixel is a vertical edge (the side of an obstacle).
  double vertical_tolerance_deg = 15.0;
};

struct EdgeMap {
  cv::Mat1b edges;     // 255 on every Canny edge pixel
  cv::Mat1b vertical;  // 255 on the edge pixels judged vertical in the world (a subset)
};

// Canny edges of an already low-passed colour image, with the near-vertical
// ones marked (Taylor, Geva & Boles 2005, §5.2). The gradient at a pixel is
// the 3×3 Sobel gradient of the channel where it is strongest (as OpenCV's
// Canny does for colour images), so that edges between colours of the same
// brightness are found. The edge's direction is perpendicular to the
// gradient; it runs along the world vertical when
// |gradient · vertical| <= |gradient| · sin(tolerance).
EdgeMap FindEdges(const cv::Mat3b& bgr, const VerticalDirectionField& vertical,
                  const EdgeMapOptions& options);

// FindEdges for a stream of frames of the field's size, keeping its buffers
// from frame to frame; it also gives the barrier the segmenters use.
class EdgeDetector {
 public:
  EdgeDetector(VerticalDirectionField vertical, const EdgeMapOptions& options);

  const VerticalDirectionField& vertical() const { return vertical_; }

  // The edges of `bgr`, as FindEdges finds them; valid until the next call.
  const EdgeMap& Find(const cv::Mat3b& bgr);
  // The edges of the last Find (empty images before the first).
  const EdgeMap& edges() const { return map_; }
  // The edge pixels of the last Find that are not vertical (255): those that
  // bound the floor.
  const cv::Mat1b& barrier() const { return barrier_; }

 private:
  VerticalDirectionField vertical_;
  EdgeMapOptions options_;
  float sin_tolerance_;
  cv::Mat1s dx_;  // the gradient of the strongest channel
  cv::Mat1s dy_;
  std::array<cv::Mat, 3> planes_;   // the frame's B, G and R apart
  std::vector<std::int16_t> rows_;  // per-row scratch of the Sobel sums
  EdgeMap map_;
  cv::Mat1b barrier_;
};

}  // namespace pirouette::vision
