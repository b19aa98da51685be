#include "pirouette/vision/mask_upsampler.h"

#include <gtest/gtest.h>

#include <opencv2/imgproc.hpp>

#include "pirouette/vision/vignetting_corrector.h"

namespace pirouette::vision {
namespace {

const cv::Vec3b kFloor(120, 110, 100);
const cv::Vec3b kWall(60, 70, 200);

// A frame whose floor (below) meets a wall along a slanted line that crosses
// the cells anywhere, and the floor mask of its reduced copy: a cell is floor
// where most of its pixels are.
struct Scene {
  cv::Mat3b frame;
  cv::Mat1b truth;
  cv::Mat3b cells;
  cv::Mat1b cell_mask;
};

Scene SlantedEdge(cv::Size size, int scale) {
  Scene scene;
  scene.frame = cv::Mat3b(size, kWall);
  scene.truth = cv::Mat1b(size, std::uint8_t{0});
  for (int v = 0; v < size.height; ++v) {
    for (int u = 0; u < size.width; ++u) {
      if (v > 0.37 * u + 0.4 * size.height) {
        scene.frame(v, u) = kFloor;
        scene.truth(v, u) = 255;
      }
    }
  }
  ReduceByBlockMean(scene.frame, scale, scene.cells);
  cv::Mat1b truth_cells;
  cv::resize(scene.truth(cv::Rect(0, 0, size.width / scale * scale, size.height / scale * scale)),
             truth_cells, scene.cells.size(), 0.0, 0.0, cv::INTER_AREA);
  scene.cell_mask = truth_cells > 127;
  return scene;
}

TEST(MaskUpsamplerTest, ScaleOneIsTheMaskItself) {
  const Scene scene = SlantedEdge(cv::Size(40, 30), 1);
  const cv::Mat1b mask = UpsampleFloorMask(scene.cell_mask, scene.cells, scene.frame, 1, {});
  EXPECT_EQ(cv::countNonZero(mask != scene.cell_mask), 0);
}

TEST(MaskUpsamplerTest, PlacesTheBoundaryToThePixel) {
  for (const int scale : {2, 3, 4}) {
    const Scene scene = SlantedEdge(cv::Size(120, 90), scale);
    const cv::Mat1b mask =
        UpsampleFloorMask(scene.cell_mask, scene.cells, scene.frame, scale, std::nullopt);
    ASSERT_EQ(mask.size(), scene.frame.size());
    // Without refinement a pixel is wrong wherever its cell straddles the
    // edge; with it, only where the low-pass mixes the two colours evenly.
    cv::Mat1b nearest;
    cv::resize(scene.cell_mask, nearest, scene.frame.size(), 0.0, 0.0, cv::INTER_NEAREST);
    const int wrong = cv::countNonZero(mask != scene.truth);
    EXPECT_GT(cv::countNonZero(nearest != scene.truth), 5 * std::max(wrong, 1)) << scale;
    EXPECT_LE(wrong, 3) << "scale " << scale;
  }
}

TEST(MaskUpsamplerTest, FramesNotAMultipleOfTheScaleTakeTheNearestCell) {
  const Scene scene = SlantedEdge(cv::Size(61, 47), 2);  // a column and a row left over
  const cv::Mat1b mask =
      UpsampleFloorMask(scene.cell_mask, scene.cells, scene.frame, 2, std::nullopt);
  ASSERT_EQ(mask.size(), scene.frame.size());
  for (int v = 0; v < 46; ++v) EXPECT_EQ(mask(v, 60), mask(v, 59)) << v;
  for (int u = 0; u < 60; ++u) EXPECT_EQ(mask(46, u), mask(45, u)) << u;
}

}  // namespace
}  // namespace pirouette::vision
