#include "pirouette/draw/capture_overlay.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pirouette/core/angle.h"
#include "pirouette/draw/palette.h"

namespace pirouette::draw {
namespace {

// 320 × 240, 11 cm up, tilted 30° down.
camera::CameraModel TestCamera() {
  return camera::CameraModel("test", 320, 240, {277.13, 277.13, 159.5, 119.5}, {},
                             {0.11, core::DegToRad(30.0), 0.03}, {});
}

// The reading of the floor point seen at `pixel`.
core::RangeReading ReadingAt(const camera::CameraModel& camera, const Eigen::Vector2d& pixel) {
  const std::optional<Eigen::Vector2d> p = camera.FloorPoint(pixel);
  EXPECT_TRUE(p.has_value());
  return {std::atan2(p->y(), p->x()), p->norm(), core::ReadingKind::kHit};
}

TEST(CaptureOverlayTest, AFootIsCountedAsAHitAndDrawnWhereItIsSeen) {
  const camera::CameraModel camera = TestCamera();
  core::ObstacleProfile profile;
  profile.max_range_m = 1.0;
  for (int u = 0; u < camera.width(); ++u) {
    profile.readings.push_back({0.0, 1.0, core::ReadingKind::kClear});
  }
  profile.feet = {ReadingAt(camera, {100.0, 200.0}), ReadingAt(camera, {250.0, 150.0})};

  // Counted: the columns are all clear, the nearest hit is the nearer foot
  // (the lower in the frame).
  const core::ProfileCounts counts = core::CountReadings(profile);
  EXPECT_EQ(counts.clear, camera.width());
  EXPECT_EQ(counts.hit, 0);
  EXPECT_EQ(counts.feet, 2);
  ASSERT_TRUE(counts.nearest_hit_m.has_value());
  EXPECT_DOUBLE_EQ(*counts.nearest_hit_m, profile.feet[0].range_m);

  // Seen where they were read.
  const std::vector<cv::Point> pixels = FootPixels(profile, camera);
  ASSERT_EQ(pixels.size(), 2u);
  EXPECT_EQ(pixels[0], cv::Point(100, 200));
  EXPECT_EQ(pixels[1], cv::Point(250, 150));

  // Drawn: a ring of the hit colour round each (the frame is black, the
  // floor mask empty, so nothing else there is that colour).
  const cv::Mat3b frame(camera.height(), camera.width(), cv::Vec3b(0, 0, 0));
  const cv::Mat1b mask(frame.size(), uchar{0});
  const std::vector<int> rows = ReadingRows(profile, camera);
  const cv::Mat3b with =
      DrawCaptureOverlay(frame, mask, {0, 0.0, 0.0, counts}, profile, rows, pixels);
  const cv::Mat3b without = DrawCaptureOverlay(frame, mask, {0, 0.0, 0.0, counts}, profile, rows);
  const auto hit_pixels_near = [](const cv::Mat3b& image, const cv::Point& p) {
    int n = 0;
    for (int dy = -3; dy <= 3; ++dy) {
      for (int dx = -3; dx <= 3; ++dx) {
        const cv::Vec3b& c = image(p.y + dy, p.x + dx);
        n += cv::norm(cv::Vec3d(c) - cv::Vec3d(kHitColour)) < 60.0 ? 1 : 0;
      }
    }
    return n;
  };
  // The overlay is 320 wide: scale 1.
  for (const cv::Point& p : pixels) {
    EXPECT_GE(hit_pixels_near(with, p), 4) << p;
    EXPECT_EQ(hit_pixels_near(without, p), 0) << p;
  }
}

}  // namespace
}  // namespace pirouette::draw
