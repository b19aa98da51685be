#include "pirouette/tools/rop.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <string>

#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/draw/radial_profile_plot.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::tools {
namespace {

namespace fs = std::filesystem;

// The plot goes into `dir`.
RopRequest TruthRequest(const testing::TempDir& dir, double heading_deg) {
  RopRequest request;
  request.world_path = std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml";
  request.world_T_robot = core::Pose2(0.75, 0.65, core::DegToRad(heading_deg));
  request.out_path = dir / "rop.png";
  request.method = vision::MaskSource::kTruth;
  return request;
}

double Median(std::vector<double> values) {
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

// With the true floor masks, the ROP is the world seen from the robot: where
// the world's geometry puts an obstacle within the max range, the ROP reads
// it (away from the obstacles' silhouettes, which the camera sees slanted).
TEST(RopTest, TruthMasksGiveTheWorldsProfile) {
  const testing::TempDir dir("pirouette_rop_test");
  const RopRequest request = TruthRequest(dir, 0.0);
  const RopResult result = MakeRop(request);
  ASSERT_TRUE(fs::exists(request.out_path));
  ASSERT_EQ(result.rop.bins.size(), 360u);
  ASSERT_EQ(result.low_pass.size(), 360u);
  ASSERT_EQ(result.truth.size(), 360u);
  std::vector<double> differences;
  for (std::size_t b = 0; b < 360; ++b) {
    EXPECT_GT(result.rop.bins[b].readings, 0) << b;
    differences.push_back(std::abs(result.rop.bins[b].range_m - result.truth[b]));
  }
  EXPECT_LT(Median(differences), 0.002);
}

// The same place, the pirouette started 90° further round: the ROP, in the
// odometry frame (the world's at the start), is the same.
TEST(RopTest, RotatedPirouetteGivesTheSameWorldProfile) {
  const testing::TempDir dir("pirouette_rop_test");
  const RopResult a = MakeRop(TruthRequest(dir, 0.0));
  const RopResult b = MakeRop(TruthRequest(dir, 90.0));
  std::vector<double> differences;
  int same_kind = 0;
  for (std::size_t i = 0; i < 360; ++i) {
    differences.push_back(std::abs(a.rop.bins[i].range_m - b.rop.bins[i].range_m));
    if (a.rop.bins[i].kind == b.rop.bins[i].kind) ++same_kind;
  }
  EXPECT_LT(Median(differences), 0.001);
  EXPECT_GT(same_kind, 340);
}

TEST(RopTest, PoseWhereTheRobotDoesNotFitIsRefused) {
  const testing::TempDir dir("pirouette_rop_test");
  RopRequest request = TruthRequest(dir, 0.0);
  request.world_T_robot = core::Pose2(0.75, 0.45, 0.0);  // inside the yellow box
  EXPECT_THROW(MakeRop(request), core::InputError);
  request.world_T_robot = core::Pose2(5.0, 0.45, 0.0);  // off the floor
  EXPECT_THROW(MakeRop(request), core::InputError);
}

TEST(RopTest, PlotIsSquare) {
  mapping::RadialProfile rop;
  rop.max_range_m = 0.4;
  rop.bins.assign(360, {0.3, core::ReadingKind::kHit, 1});
  const cv::Mat3b image =
      draw::PlotRadialProfile(rop, std::vector<double>(360, 0.3), {}, "test", 400);
  EXPECT_EQ(image.rows, 400);
  EXPECT_EQ(image.cols, 400);
}

}  // namespace
}  // namespace pirouette::tools
