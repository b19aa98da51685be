#include "pirouette/camera/range_resolution.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pirouette/core/angle.h"
#include "pirouette/io/camera_file.h"

namespace pirouette::camera {
namespace {

// An ideal pinhole: no distortion, so the centre column's geometry is closed form.
CameraModel Pinhole(double height_m, double tilt_deg, double forward_m) {
  return {"pinhole", 320,
          240,       {277.0, 277.0, 159.5, 119.5},
          {},        {height_m, core::DegToRad(tilt_deg), forward_m},
          {}};
}

// The range of the floor point that the pinhole's centre column sees at `row`.
double PinholeRange(double row, double height_m, double tilt_deg, double forward_m) {
  const double below_horizon = core::DegToRad(tilt_deg) + std::atan((row - 119.5) / 277.0);
  return height_m / std::tan(below_horizon) + forward_m;
}

TEST(RangeResolutionTest, PinholeMatchesClosedForm) {
  const CameraModel camera = Pinhole(0.11, 30.0, 0.03);
  for (const double range : {0.15, 0.25, 0.40, 0.60}) {
    const std::optional<RangeError> error = RangeErrorAt(camera, range);
    ASSERT_TRUE(error) << range;
    EXPECT_NEAR(error->range_m, range, 1e-9);
    EXPECT_NEAR(PinholeRange(error->row, 0.11, 30.0, 0.03), range, 1e-9);
    EXPECT_NEAR(error->farther_m, PinholeRange(error->row - 1.0, 0.11, 30.0, 0.03) - range, 1e-9);
    EXPECT_NEAR(error->nearer_m, range - PinholeRange(error->row + 1.0, 0.11, 30.0, 0.03), 1e-9);
    EXPECT_GT(error->farther_m, error->nearer_m);  // perspective: a pixel up spans more floor
    EXPECT_EQ(error->worst_m(), error->farther_m);
  }
}

TEST(RangeResolutionTest, ErrorGrowsWithRange) {
  const CameraModel camera = Pinhole(0.11, 30.0, 0.03);
  const std::vector<RangeError> table = RangeErrorTable(camera, 0.05, 10.0);
  ASSERT_GT(table.size(), 5u);
  for (std::size_t i = 1; i < table.size(); ++i) {
    EXPECT_NEAR(table[i].range_m - table[i - 1].range_m, 0.05, 1e-9);
    EXPECT_GT(table[i].worst_m(), table[i - 1].worst_m());
  }
}

TEST(RangeResolutionTest, EveryColumnSeesTheFloorOutToItsTopRowsNearestPoint) {
  const CameraModel camera = Pinhole(0.11, 30.0, 0.03);
  // The pinhole's top row is nearest the robot at its centre column (x 159.5,
  // between two columns: the nearest whole column sees a hair farther).
  const double top = PinholeRange(0.0, 0.11, 30.0, 0.03);
  EXPECT_GE(FloorSeenInEveryColumn(camera), top);
  EXPECT_NEAR(FloorSeenInEveryColumn(camera), top, 1e-3);
  // Tilted up so that the top row lies above the horizon: every column sees
  // the floor out to the horizon.
  EXPECT_TRUE(std::isinf(FloorSeenInEveryColumn(Pinhole(0.11, 10.0, 0.03))));

  EXPECT_DOUBLE_EQ(LongRange(camera, 0.40, 2.0), 0.80);
  EXPECT_DOUBLE_EQ(LongRange(camera, 0.40, 3.0), FloorSeenInEveryColumn(camera));  // < 1.2 m
  EXPECT_DOUBLE_EQ(LongRange(camera, 0.40, 1.0), 0.40);
  EXPECT_DOUBLE_EQ(LongRange(camera, 1.50, 3.0), 1.50);  // never below the map's range
}

TEST(RangeResolutionTest, OutsideTheViewIsNotMeasured) {
  const CameraModel camera = Pinhole(0.11, 30.0, 0.03);
  const std::optional<RangeInterval> ranges = MeasurableRanges(camera);
  ASSERT_TRUE(ranges);
  EXPECT_NEAR(ranges->near_m, PinholeRange(239.0, 0.11, 30.0, 0.03), 1e-9);
  EXPECT_NEAR(ranges->far_m, PinholeRange(0.0, 0.11, 30.0, 0.03), 1e-9);
  EXPECT_FALSE(RangeErrorAt(camera, 0.5 * ranges->near_m));
  EXPECT_FALSE(RangeErrorAt(camera, 2.0 * ranges->far_m));
}

TEST(RangeResolutionTest, MaxRangeKeepsOnePixelWithinHalfACell) {
  const CameraModel camera = Pinhole(0.11, 30.0, 0.03);
  const double max_range = MaxRange(camera, 0.01);
  const std::optional<RangeError> at = RangeErrorAt(camera, max_range);
  ASSERT_TRUE(at);
  EXPECT_NEAR(at->worst_m(), 0.005, 1e-6);
  // Coarser cells allow farther ranges.
  EXPECT_GT(MaxRange(camera, 0.02), max_range);
}

TEST(RangeResolutionTest, PaperCameraMaxRangeIsAboutFortyCentimetres) {
  const CameraModel camera = io::LoadCameraFile(std::string(PIROUETTE_WORLDS_DIR) + "/yujin.yaml");
  const double max_range = MaxRange(camera, 0.01);
  EXPECT_GE(max_range, 0.35);
  EXPECT_LE(max_range, 0.45);
  // The paper's figure: under half a centimetre up to 35 cm.
  const std::optional<RangeError> at35 = RangeErrorAt(camera, 0.35);
  ASSERT_TRUE(at35);
  EXPECT_LT(at35->worst_m(), 0.005);
}

}  // namespace
}  // namespace pirouette::camera
