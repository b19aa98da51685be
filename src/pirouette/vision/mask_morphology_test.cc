#include "pirouette/vision/mask_morphology.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

namespace pirouette::vision {
namespace {

// A random mask (255 on), `density` of it on, smoothed into blobs by `blur`.
cv::Mat1b RandomMask(cv::Size size, double density, int blur, int seed) {
  cv::Mat1f noise(size);
  cv::RNG rng(static_cast<std::uint64_t>(seed));
  rng.fill(noise, cv::RNG::UNIFORM, 0.0, 1.0);
  if (blur > 1) cv::blur(noise, noise, cv::Size(blur, blur));
  cv::Mat1f sorted = noise.clone().reshape(1, 1);
  cv::sort(sorted, sorted, cv::SORT_ASCENDING);
  const float cut = sorted(0, static_cast<int>((1.0 - density) * (sorted.cols - 1)));
  return noise > cut;
}

cv::Mat1b ConnectedToSeedsReference(const cv::Mat1b& candidate, const cv::Mat1b& seeds) {
  cv::Mat1i labels;
  const int count = cv::connectedComponents(candidate, labels, 4, CV_32S);
  std::vector<bool> keep(static_cast<std::size_t>(count), false);
  for (int v = 0; v < labels.rows; ++v) {
    for (int u = 0; u < labels.cols; ++u) {
      if (seeds(v, u) != 0 && candidate(v, u) != 0) keep[labels(v, u)] = true;
    }
  }
  cv::Mat1b out(candidate.size(), std::uint8_t{0});
  for (int v = 0; v < labels.rows; ++v) {
    for (int u = 0; u < labels.cols; ++u) {
      if (candidate(v, u) != 0 && keep[labels(v, u)]) out(v, u) = 255;
    }
  }
  return out;
}

TEST(MaskMorphologyTest, FillFromSeedsKeepsTheComponentsHoldingASeed) {
  int seed = 0;
  for (const double density : {0.3, 0.5, 0.6, 0.8}) {
    for (const int blur : {1, 3, 7}) {
      const cv::Mat1b candidate = RandomMask(cv::Size(83, 61), density, blur, ++seed);
      cv::Mat1b seeds(candidate.size(), std::uint8_t{0});
      seeds.rowRange(50, 61).colRange(20, 60).setTo(255);  // a block near the bottom
      seeds(5, 5) = 255;                                   // and a lone pixel
      cv::Mat1b filled;
      FillFromSeeds(candidate, seeds, filled);
      EXPECT_EQ(cv::countNonZero(filled != ConnectedToSeedsReference(candidate, seeds)), 0)
          << "density " << density << ", blur " << blur;
    }
  }
}

TEST(MaskMorphologyTest, FillFromSeedsFollowsWindingComponents) {
  // A spiral corridor: the fill must turn back up and down many times.
  cv::Mat1b candidate(41, 41, std::uint8_t{0});
  for (int r = 1; r < 20; r += 4) {
    cv::rectangle(candidate, cv::Rect(r, r, 41 - 2 * r, 41 - 2 * r), cv::Scalar(255), 1);
    candidate(r + 1, r) = 255;  // a gap into the next ring
    candidate(r + 2, r) = 255;
    candidate(r + 2, r + 1) = 255;
  }
  cv::Mat1b seeds(candidate.size(), std::uint8_t{0});
  seeds(1, 20) = 255;
  cv::Mat1b filled;
  FillFromSeeds(candidate, seeds, filled);
  EXPECT_EQ(cv::countNonZero(filled != ConnectedToSeedsReference(candidate, seeds)), 0);
}

TEST(MaskMorphologyTest, CloserEqualsMorphologyEx) {
  int seed = 100;
  for (const int size : {1, 3, 5, 9, 4}) {  // 4: not centred, left to OpenCV
    for (const double density : {0.4, 0.7, 0.95}) {
      const cv::Mat1b mask = RandomMask(cv::Size(57, 43), density, 3, ++seed);
      cv::Mat1b expected;
      cv::morphologyEx(mask, expected, cv::MORPH_CLOSE,
                       cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size)));
      MaskCloser closer(size);
      cv::Mat1b closed = mask.clone();
      closer.Close(closed);
      EXPECT_EQ(cv::countNonZero(closed != expected), 0) << "size " << size;
      // Again, with its buffers kept.
      cv::morphologyEx(expected, expected, cv::MORPH_CLOSE,
                       cv::getStructuringElement(cv::MORPH_ELLIPSE, cv::Size(size, size)));
      closer.Close(closed);
      EXPECT_EQ(cv::countNonZero(closed != expected), 0) << "size " << size;
    }
  }
}

TEST(MaskMorphologyTest, GrowerEqualsRepeatedConditionalDilation) {
  const cv::Mat cross = cv::getStructuringElement(cv::MORPH_CROSS, cv::Size(3, 3));
  int seed = 200;
  MaskGrower grower;
  for (const int steps : {0, 1, 2, 8}) {
    for (const double density : {0.3, 0.7}) {
      const cv::Mat1b start = RandomMask(cv::Size(64, 48), 0.2, 5, ++seed);
      const cv::Mat1b allowed = RandomMask(cv::Size(64, 48), density, 1, ++seed);
      cv::Mat1b expected = start.clone();
      for (int step = 0; step < steps; ++step) {
        cv::Mat1b grown;
        cv::dilate(expected, grown, cross);
        expected |= grown & allowed;
      }
      cv::Mat1b mask = start.clone();
      grower.Grow(mask, allowed, steps);
      EXPECT_EQ(cv::countNonZero(mask != expected), 0) << steps << " steps";
    }
  }
}

}  // namespace
}  // namespace pirouette::vision
