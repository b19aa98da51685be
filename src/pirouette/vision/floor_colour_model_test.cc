#include "pirouette/vision/floor_colour_model.h"

#include <gtest/gtest.h>

namespace pirouette::vision {
namespace {

const cv::Vec3b kBeige(150, 180, 200);  // BGR
const cv::Vec3b kRed(40, 40, 200);
const cv::Vec3b kBlue(200, 60, 30);

TEST(FloorColourModelTest, KnowsNothingBeforeLearning) {
  const FloorColourModel model;
  EXPECT_FALSE(model.learnt());
  EXPECT_EQ(model.Likelihood(kBeige), 0.0f);
}

TEST(FloorColourModelTest, CoverageIsTheShareOfARegionCalledFloor) {
  cv::Mat3b image(20, 20, kBeige);
  image(cv::Rect(0, 0, 20, 5)).setTo(kRed);  // a quarter red
  const cv::Mat1b all(20, 20, std::uint8_t{255});
  const std::vector<double> histogram = FloorColourModel::Histogram(image, all);
  ASSERT_EQ(histogram.size(), static_cast<std::size_t>(FloorColourModel::kBins));
  FloorColourModel beige;
  EXPECT_EQ(beige.Coverage(histogram, 0.1f), 0.0);  // nothing learnt
  beige.Learn(cv::Mat3b(20, 20, kBeige), all);
  EXPECT_NEAR(beige.Coverage(histogram, 0.1f), 0.75, 1e-9);
  // Learning a histogram is learning its region.
  FloorColourModel from_image;
  FloorColourModel from_histogram;
  from_image.Learn(image, all);
  from_histogram.Learn(histogram);
  EXPECT_EQ(from_image.Likelihood(kRed), from_histogram.Likelihood(kRed));
  EXPECT_EQ(from_image.histogram(), from_histogram.histogram());
  EXPECT_TRUE(FloorColourModel::Histogram(image, cv::Mat1b(20, 20, std::uint8_t{0})).empty());
}

TEST(FloorColourModelTest, LearntColourIsFloorAndOthersAreNot) {
  FloorColourModel model;
  const cv::Mat3b image(20, 20, kBeige);
  model.Learn(image, cv::Mat1b(20, 20, std::uint8_t{255}));
  EXPECT_TRUE(model.learnt());
  EXPECT_FLOAT_EQ(model.Likelihood(kBeige), 1.0f);
  EXPECT_LT(model.Likelihood(kRed), 0.01f);
  // 10% darker: nearly the same chroma, one lightness bin at most away.
  EXPECT_GT(model.Likelihood(cv::Vec3b(135, 162, 180)), 0.2f);
}

// A dark grey floor with a fine grain (values 52-60), and a box of its
// colour whose face is lit a shade darker (40: about 7 L* units), as in
// generated clutter world 102 (docs/worlds.md, fix 15).
cv::Mat3b GrainyGrey(int low, int high) {
  cv::Mat3b image(20, 20);
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) {
      const auto g = static_cast<std::uint8_t>(low + (u * 7 + v * 3) % (high - low + 1));
      image(v, u) = cv::Vec3b(g, static_cast<std::uint8_t>(g + 2), g);
    }
  }
  return image;
}

TEST(FloorColourModelTest, ThePlainFloorsToleranceInLightnessIsItsOwnSpread) {
  const cv::Mat1b all(20, 20, std::uint8_t{255});
  const cv::Vec3b face(40, 42, 40);
  FloorColourModel plain;
  plain.Learn(GrainyGrey(52, 60), all);
  EXPECT_GT(plain.Likelihood(cv::Vec3b(56, 58, 56)), 0.5f);
  // 0.77 with bins of 12.5 L* units and one smoothing pass.
  EXPECT_LT(plain.Likelihood(face), 0.25f);
  // The same grain, half of it in the light (values 92-100): the floor's own
  // lightness spread widens the model along L*, and the face is more likely.
  cv::Mat3b image = GrainyGrey(52, 60);
  GrainyGrey(92, 100)(cv::Rect(0, 0, 20, 10)).copyTo(image(cv::Rect(0, 0, 20, 10)));
  FloorColourModel broad;
  broad.Learn(image, all);
  EXPECT_GT(broad.Likelihood(face), 1.5f * plain.Likelihood(face));
}

TEST(FloorColourModelTest, LearnsOnlyInsideTheRegion) {
  FloorColourModel model;
  cv::Mat3b image(10, 10, kRed);
  image(cv::Rect(0, 5, 10, 5)).setTo(kBeige);
  cv::Mat1b region(10, 10, std::uint8_t{0});
  region(cv::Rect(0, 5, 10, 5)).setTo(255);
  model.Learn(image, region);
  const cv::Mat1f likelihood = model.Likelihood(image);
  EXPECT_FLOAT_EQ(likelihood(9, 0), 1.0f);
  EXPECT_LT(likelihood(0, 0), 0.01f);
}

TEST(FloorColourModelTest, AdaptsWithExponentialForgetting) {
  FloorColourModelOptions options;
  options.forgetting = 0.5;
  FloorColourModel model(options);
  const cv::Mat1b all(8, 8, std::uint8_t{255});
  model.Learn(cv::Mat3b(8, 8, kBeige), all);
  model.Learn(cv::Mat3b(8, 8, kBlue), all);
  // Half and half now: both are floor.
  EXPECT_GT(model.Likelihood(kBeige), 0.5f);
  EXPECT_GT(model.Likelihood(kBlue), 0.5f);
  for (int i = 0; i < 6; ++i) model.Learn(cv::Mat3b(8, 8, kBlue), all);
  EXPECT_LT(model.Likelihood(kBeige), 0.05f);  // the old light is forgotten
  EXPECT_FLOAT_EQ(model.Likelihood(kBlue), 1.0f);
}

TEST(FloorColourModelTest, EmptyRegionChangesNothing) {
  FloorColourModel model;
  model.Learn(cv::Mat3b(4, 4, kBeige), cv::Mat1b(4, 4, std::uint8_t{255}));
  model.Learn(cv::Mat3b(4, 4, kRed), cv::Mat1b(4, 4, std::uint8_t{0}));
  EXPECT_FLOAT_EQ(model.Likelihood(kBeige), 1.0f);
  EXPECT_LT(model.Likelihood(kRed), 0.01f);
}

TEST(FloorColourModelTest, BinsAndHistogramsFromBinsAgreeWithThePixels) {
  cv::Mat3b image(12, 17);
  cv::RNG rng(5);
  rng.fill(image, cv::RNG::UNIFORM, 0, 256);
  cv::Mat1b region(image.size(), std::uint8_t{0});
  region(cv::Rect(3, 2, 9, 7)).setTo(255);
  cv::Mat1w bins;
  FloorColourModel::Bins(image, bins);
  ASSERT_EQ(bins.size(), image.size());
  for (int v = 0; v < image.rows; ++v) {
    for (int u = 0; u < image.cols; ++u) EXPECT_EQ(bins(v, u), FloorColourModel::Bin(image(v, u)));
  }
  EXPECT_EQ(FloorColourModel::Histogram(bins, region), FloorColourModel::Histogram(image, region));
  const auto [inside, outside] = FloorColourModel::Histograms(bins, region);
  EXPECT_EQ(inside, FloorColourModel::Histogram(image, region));
  EXPECT_EQ(outside, FloorColourModel::Histogram(image, ~region));
  const auto [all, none] = FloorColourModel::Histograms(bins, cv::Mat1b(image.size(), uchar{255}));
  EXPECT_FALSE(all.empty());
  EXPECT_TRUE(none.empty());
}

TEST(FloorColourModelTest, RelearningIsLearningAfresh) {
  const cv::Mat1b all(8, 8, std::uint8_t{255});
  FloorColourModel model;
  model.Learn(cv::Mat3b(8, 8, kBeige), all);
  model.Relearn(FloorColourModel::Histogram(cv::Mat3b(8, 8, kBlue), all));
  FloorColourModel fresh;
  fresh.Learn(cv::Mat3b(8, 8, kBlue), all);
  EXPECT_EQ(model.histogram(), fresh.histogram());
  EXPECT_EQ(model.likelihoods(), fresh.likelihoods());
  EXPECT_EQ(model.densities(), fresh.densities());
  EXPECT_EQ(model.Likelihood(kBeige), 0.0f);
}

}  // namespace
}  // namespace pirouette::vision
