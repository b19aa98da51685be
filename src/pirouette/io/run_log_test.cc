#include "pirouette/io/run_log.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pirouette/core/input_error.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::io {
namespace {

namespace fs = std::filesystem;

camera::CameraModel TestCamera() {
  return io::LoadCameraFile(std::string(PIROUETTE_WORLDS_DIR) + "/yujin.yaml");
}

robot::Frame GreyFrame(const camera::CameraModel& camera, const core::Pose2& pose, double t) {
  robot::Frame frame;
  frame.image = core::ImageRgb8(camera.width(), camera.height());
  for (std::uint8_t* p = frame.image.data();
       p != frame.image.data() + 3 * camera.width() * camera.height(); ++p) {
    *p = 128;
  }
  frame.odometry = pose;
  frame.time_s = t;
  return frame;
}

class RunLogTest : public ::testing::Test {
 protected:
  testing::TempDir temp_{"pirouette_run_log"};

  void WriteCsv(const std::string& text) { std::ofstream(dir_ / "frames.csv") << text; }

  fs::path dir_ = temp_.path() / "log";  // not there until a test makes it
};

TEST_F(RunLogTest, WrittenLogReadsBackWithOdometryMotionsAndBlockedLegs) {
  const camera::CameraModel camera = TestCamera();
  RunLogInfo info;
  info.radius_m = 0.04;
  info.cell_m = 0.01;
  info.method = "default";
  {
    RunLogWriter writer(dir_.string(), camera, info);
    writer.AddFrame(GreyFrame(camera, core::Pose2(0.2, 0.3, 0.5236), 0.0), {});
    core::MoveOutcome turn{core::Move::Turn(0.1), 0.1, false, core::Pose2(0.2, 0.3, 0.6236)};
    core::MoveOutcome drive{core::Move::Straight(0.2), 0.05, true, core::Pose2(0.25, 0.3, 0.6236)};
    writer.AddFrame(GreyFrame(camera, core::Pose2(0.25, 0.3, 0.6236), 1.5), {turn, drive});
    writer.MarkBlocked(0.12);
  }
  const RunLog log = ReadRunLog(dir_.string());
  ASSERT_EQ(log.rows.size(), 2U);
  EXPECT_DOUBLE_EQ(log.info.radius_m, 0.04);
  EXPECT_EQ(log.info.method, "default");
  EXPECT_EQ(log.camera.width(), camera.width());
  EXPECT_DOUBLE_EQ(log.rows[0].odometry.x(), 0.2);
  EXPECT_NEAR(log.rows[0].odometry.heading(), 0.5236, 1e-15);
  EXPECT_FALSE(log.rows[0].contact);
  EXPECT_FALSE(log.rows[0].blocked_leg_m);
  EXPECT_TRUE(log.rows[1].contact);
  ASSERT_TRUE(log.rows[1].blocked_leg_m);
  EXPECT_DOUBLE_EQ(*log.rows[1].blocked_leg_m, 0.12);
  EXPECT_DOUBLE_EQ(log.rows[1].time_s, 1.5);
  const robot::Frame frame = ReadLogFrame(log, log.rows[1]);
  EXPECT_EQ(frame.image.width(), camera.width());
  EXPECT_EQ(frame.image.data()[0], 128);
}

TEST_F(RunLogTest, WriterRefusesAFolderThatHoldsALog) {
  const camera::CameraModel camera = TestCamera();
  { RunLogWriter writer(dir_.string(), camera, RunLogInfo{}); }
  EXPECT_THROW(RunLogWriter(dir_.string(), camera, RunLogInfo{}), core::InputError);
}

TEST_F(RunLogTest, BadLogsAreRefusedNamingFileLineAndField) {
  EXPECT_THROW(ReadRunLog((dir_ / "missing").string()), core::InputError);
  fs::create_directories(dir_ / "frames");
  std::ofstream(dir_ / "camera.yaml") << io::CameraFileText(TestCamera());
  WriteCsv("index,time_s,x,y,heading_deg,motion,blocked_leg_m\n0,0,0.2,zero,45,,\n");
  try {
    ReadRunLog(dir_.string());
    FAIL() << "a bad number was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.field(), "y");
  }
  WriteCsv("index,time_s,x,y,heading_deg,motion,blocked_leg_m\n");
  EXPECT_THROW(ReadRunLog(dir_.string()), core::InputError);  // no frames
  WriteCsv("frame,t\n0,0\n");
  EXPECT_THROW(ReadRunLog(dir_.string()), core::InputError);  // header
  WriteCsv("index,time_s,x,y,heading_deg\n0,0,0,0,0\n");
  const RunLog log = ReadRunLog(dir_.string());  // the short form of a real robot's script
  EXPECT_THROW(ReadLogFrame(log, log.rows[0]), core::InputError);  // no image
  std::ofstream(dir_ / "log.yaml") << "format: something-else\n";
  EXPECT_THROW(ReadRunLog(dir_.string()), core::InputError);
  // A section that is not a map (fuzz/regressions/run_log), a number that is not finite.
  for (const char* body :
       {"robot: 0.04\n", "map: 0.01\n", "source: worlds/maze.yaml\n", "robot:\n  radius: .nan\n"}) {
    std::ofstream(dir_ / "log.yaml") << "format: pirouette-log/1\n" << body;
    EXPECT_THROW(ReadRunLog(dir_.string()), core::InputError) << body;
  }
  std::ofstream(dir_ / "log.yaml") << "format: pirouette-log/1\nmap: 7\n";
  try {
    ReadRunLog(dir_.string());
    FAIL() << "a scalar map section was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.line(), 2);
    EXPECT_EQ(e.field(), "map");
  }
}

}  // namespace
}  // namespace pirouette::io
