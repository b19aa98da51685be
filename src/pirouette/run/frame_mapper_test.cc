#include "pirouette/run/frame_mapper.h"

#include <gtest/gtest.h>

#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/testing/test_camera.h"

namespace pirouette::run {
namespace {

MapperSetup PaperRobotSetup() {
  return MapperSetup{testing::PaperCamera(), 0.04, 0.01, 0.40, {}, std::nullopt, std::nullopt, 0.0};
}

// The k-th frame of a pirouette at the origin; its first pixel's red is k.
robot::Frame FrameNumber(int k) {
  robot::Frame frame;
  frame.image = core::ImageRgb8(320, 240);
  frame.image.data()[0] = static_cast<std::uint8_t>(k);
  frame.odometry = core::Pose2(0.0, 0.0, core::DegToRad(30.0 * k));
  frame.time_s = k;
  return frame;
}

int NumberOf(const cv::Mat3b& bgr) { return bgr(0, 0)[2]; }

TEST(FrameMapperTest, TheSettlingFramesAreMaskedAgainAndMappedOnceAllAreSeen) {
  constexpr int kSettling = 3;
  std::vector<int> calls;
  // A segmenter that sees no floor while it learns, then floor everywhere.
  const MaskFunction learning = [&](const cv::Mat3b& bgr) {
    calls.push_back(NumberOf(bgr));
    const bool settled = calls.size() > static_cast<std::size_t>(kSettling);
    return cv::Mat1b(bgr.size(), settled ? std::uint8_t{255} : std::uint8_t{0});
  };
  FrameMapper mapper(PaperRobotSetup(), {learning, kSettling, {}}, core::Pose2());
  for (int k = 0; k < kSettling - 1; ++k) {
    const FrameMapper::Seen seen = mapper.AddFrame(FrameNumber(k));
    EXPECT_EQ(mapper.grid().KnownCellCount(), 0U) << "frame " << k << " is not mapped yet";
    EXPECT_EQ(seen.pose.heading(), core::DegToRad(30.0 * k));
  }
  mapper.AddFrame(FrameNumber(kSettling - 1));
  mapper.AddFrame(FrameNumber(kSettling));
  EXPECT_EQ(calls, (std::vector<int>{0, 1, 2, 0, 1, 2, 3}));

  // The map is that of the second pass's masks, frame by frame.
  FrameMapper settled(
      PaperRobotSetup(),
      {[](const cv::Mat3b& bgr) { return cv::Mat1b(bgr.size(), std::uint8_t{255}); }, 0, {}},
      core::Pose2());
  for (int k = 0; k <= kSettling; ++k) settled.AddFrame(FrameNumber(k));
  EXPECT_GT(settled.grid().KnownCellCount(), 0U);
  EXPECT_EQ(mapper.grid().geometry().origin(), settled.grid().geometry().origin());
  EXPECT_EQ(mapper.grid().ToTrinary().cells, settled.grid().ToTrinary().cells);
  EXPECT_EQ(mapper.FramePoses().size(), 4U);
}

TEST(FrameMapperTest, ARunEndedWhileSettlingMapsWhatItSaw) {
  int calls = 0;
  FrameMapper mapper(PaperRobotSetup(),
                     {[&](const cv::Mat3b& bgr) {
                        ++calls;
                        return cv::Mat1b(bgr.size(), std::uint8_t{255});
                      },
                      12,
                      {}},
                     core::Pose2());
  mapper.AddFrame(FrameNumber(0));
  mapper.AddFrame(FrameNumber(1));
  EXPECT_EQ(mapper.grid().KnownCellCount(), 0U);
  mapper.Finish();
  EXPECT_EQ(calls, 4);
  EXPECT_GT(mapper.grid().KnownCellCount(), 0U);
  EXPECT_EQ(mapper.FramePoses().size(), 2U);
}

}  // namespace
}  // namespace pirouette::run
