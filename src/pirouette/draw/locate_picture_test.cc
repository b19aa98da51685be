#include "pirouette/draw/locate_picture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/draw/palette.h"

namespace pirouette::draw {
namespace {

constexpr double kCell = 0.02;

// A 1.0 m by 0.6 m room walled all round (one cell thick), one trial.
struct Scene {
  mapping::TrinaryMap map;
  std::vector<localize::LocateTrial> trials;
  double coarse_cell_m = 0.04;
};

Scene OneTrial(bool found, bool right, const core::Pose2& truth, const core::Pose2& best) {
  Scene result{mapping::TrinaryMap{core::GridGeometry(kCell, Eigen::Vector2d::Zero(), 50, 30), {}},
               {}};
  mapping::TrinaryMap& map = result.map;
  const core::GridGeometry& g = map.geometry;
  map.cells.assign(g.CellCount(), mapping::CellState::kFree);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (x == 0 || y == 0 || x == g.width() - 1 || y == g.height() - 1) {
        map.cells[g.Flat({x, y})] = mapping::CellState::kOccupied;
      }
    }
  }
  localize::LocateTrial t;
  t.truth = truth;
  t.answer.found = found;
  t.right = right;
  t.answer.world_T_robot = best;
  t.answer.candidates.push_back({best, 0.9, 300});
  // The pirouette saw the east wall straight ahead (bin 0) and nothing else.
  t.seen.view.ranges_m.assign(360, 0.8);
  t.seen.kinds.assign(360, core::ReadingKind::kClear);
  t.seen.view.ranges_m[0] = 0.98 - truth.x();
  t.seen.kinds[0] = core::ReadingKind::kHit;
  result.trials.push_back(t);
  return result;
}

// The picture's pixel for a point of the map (8 pixels a cell at 400 px).
cv::Vec3b At(const cv::Mat3b& image, double x_m, double y_m) {
  const int u = static_cast<int>(std::floor(x_m / kCell * 8));
  const int v = static_cast<int>(std::floor((30 - y_m / kCell) * 8));
  return image(v, u);
}

bool Near(const cv::Vec3b& pixel, const cv::Vec3b& bgr) {
  return std::abs(pixel[0] - bgr[0]) < 40 && std::abs(pixel[1] - bgr[1]) < 40 &&
         std::abs(pixel[2] - bgr[2]) < 40;
}

cv::Mat3b Draw(const Scene& scene, int width_px) {
  return DrawLocatePicture(scene.map, scene.trials, scene.coarse_cell_m, width_px);
}

TEST(LocatePictureTest, ShowsTheMapTheTruthTheAnswerAndWhereTheViewFalls) {
  const core::Pose2 truth(0.30, 0.25, 0.0);
  const cv::Mat3b image = Draw(OneTrial(true, true, truth, truth), 400);
  ASSERT_EQ(image.cols, 400);
  ASSERT_EQ(image.rows, 240);
  EXPECT_TRUE(Near(At(image, 0.01, 0.30), {0, 0, 0}));        // the west wall
  EXPECT_TRUE(Near(At(image, 0.60, 0.45), {255, 255, 255}));  // free floor
  // Found right: a disc of kRightColour (below its heading's tick, which the truth's
  // tick covers).
  EXPECT_TRUE(Near(At(image, 0.30, 0.25 - kCell), kRightColour));
  // The truth's ring, 3 pixels outside the answer's disc of 16.
  EXPECT_TRUE(Near(At(image, 0.30, 0.25 + 18.5 / 8 * kCell), kTruthColour));
  // The pirouette's one hit, where the answer puts it: on the east wall.
  EXPECT_TRUE(Near(At(image, 0.977, 0.251), kHitColour));
}

TEST(LocatePictureTest, AWrongAnswerAndACannotTellHaveTheirColours) {
  const core::Pose2 truth(0.30, 0.25, 0.0);
  const core::Pose2 elsewhere(0.70, 0.35, core::DegToRad(180.0));
  const cv::Mat3b wrong = Draw(OneTrial(true, false, truth, elsewhere), 400);
  EXPECT_TRUE(Near(At(wrong, 0.70, 0.35), kWrongColour));
  EXPECT_TRUE(Near(At(wrong, 0.50, 0.30), kWrongColour));  // the line from the truth
  const cv::Mat3b cannot = Draw(OneTrial(false, false, truth, elsewhere), 400);
  EXPECT_TRUE(Near(At(cannot, 0.70, 0.35), kCannotTellColour));
}

}  // namespace
}  // namespace pirouette::draw
