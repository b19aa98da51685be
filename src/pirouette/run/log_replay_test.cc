#include "pirouette/run/log_replay.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pirouette/core/input_error.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/run_log.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::run {
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

class LogReplayTest : public ::testing::Test {
 protected:
  testing::TempDir temp_{"pirouette_log_replay"};

  void WriteCsv(const std::string& text) { std::ofstream(dir_ / "frames.csv") << text; }

  fs::path dir_ = temp_.path() / "log";  // not there until a test makes it
};

TEST_F(LogReplayTest, MapRefusesACellOutOfRange) {
  const camera::CameraModel camera = TestCamera();
  io::RunLogInfo info;
  info.radius_m = 0.04;
  info.cell_m = 1e-9;
  {
    io::RunLogWriter writer(dir_.string(), camera, info);
    writer.AddFrame(GreyFrame(camera, core::Pose2(0.2, 0.3, 0.0), 0.0), {});
  }
  run::MapLogRequest request;
  request.log_dir = dir_.string();
  request.out_dir = (dir_ / "out").string();
  request.quiet = true;
  try {
    run::RunMapLog(request);
    FAIL() << "a 1e-9 m cell was accepted";
  } catch (const core::InputError& e) {
    EXPECT_EQ(e.field(), "map.cell");
  }
  request.cell_m = -1.0;
  EXPECT_THROW(run::RunMapLog(request), core::InputError);
}

}  // namespace
}  // namespace pirouette::run
