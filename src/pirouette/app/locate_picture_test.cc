#include "pirouette/app/locate_picture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "pirouette/core/angle.h"

namespace pirouette::app {
namespace {

constexpr double kCell = 0.02;

// A 1.0 m by 0.6 m room walled all round (one cell thick), one trial.
LocateResult OneTrial(bool found, bool right, const core::Pose2& truth, const core::Pose2& best) {
  LocateResult result;
  result.map = mapping::TrinaryMap{core::GridGeometry(kCell, Eigen::Vector2d::Zero(), 50, 30), {}};
  mapping::TrinaryMap& map = *result.map;
  const core::GridGeometry& g = map.geometry;
  map.cells.assign(g.CellCount(), mapping::CellState::kFree);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      if (x == 0 || y == 0 || x == g.width() - 1 || y == g.height() - 1) {
        map.cells[g.Flat({x, y})] = mapping::CellState::kOccupied;
      }
    }
  }
  result.coarse_cell_m = 0.04;
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

TEST(LocatePictureTest, ShowsTheMapTheTruthTheAnswerAndWhereTheViewFalls) {
  const core::Pose2 truth(0.30, 0.25, 0.0);
  const cv::Mat3b image = DrawLocatePicture(OneTrial(true, true, truth, truth), 400);
  ASSERT_EQ(image.cols, 400);
  ASSERT_EQ(image.rows, 240);
  EXPECT_TRUE(Near(At(image, 0.01, 0.30), {0, 0, 0}));        // the west wall
  EXPECT_TRUE(Near(At(image, 0.60, 0.45), {255, 255, 255}));  // free floor
  // Found right: a blue disc (below its heading's tick, which the truth's
  // green tick covers).
  EXPECT_TRUE(Near(At(image, 0.30, 0.25 - kCell), {200, 90, 20}));
  // The truth's ring, 3 pixels outside the answer's disc of 16.
  EXPECT_TRUE(Near(At(image, 0.30, 0.25 + 18.5 / 8 * kCell), {40, 170, 40}));
  // The pirouette's one hit, where the answer puts it: on the east wall.
  EXPECT_TRUE(Near(At(image, 0.977, 0.251), {255, 220, 0}));
}

TEST(LocatePictureTest, AResultWithoutItsMapIsRefused) {
  EXPECT_THROW(DrawLocatePicture(LocateResult{}), std::invalid_argument);
}

TEST(LocatePictureTest, AWrongAnswerIsRedAndACannotTellOrange) {
  const core::Pose2 truth(0.30, 0.25, 0.0);
  const core::Pose2 elsewhere(0.70, 0.35, core::DegToRad(180.0));
  const cv::Mat3b wrong = DrawLocatePicture(OneTrial(true, false, truth, elsewhere), 400);
  EXPECT_TRUE(Near(At(wrong, 0.70, 0.35), {30, 30, 220}));
  EXPECT_TRUE(Near(At(wrong, 0.50, 0.30), {30, 30, 220}));  // the line from the truth
  const cv::Mat3b cannot = DrawLocatePicture(OneTrial(false, false, truth, elsewhere), 400);
  EXPECT_TRUE(Near(At(cannot, 0.70, 0.35), {0, 140, 255}));
}

}  // namespace
}  // namespace pirouette::app
