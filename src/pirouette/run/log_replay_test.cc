#include "pirouette/run/log_replay.h"

#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "pirouette/core/input_error.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/run_log.h"

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

class LogMappingTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pirouette_log_mapping_unit_" + std::to_string(getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void WriteCsv(const std::string& text) { std::ofstream(dir_ / "frames.csv") << text; }

  fs::path dir_;
};

TEST_F(LogMappingTest, MapRefusesACellOutOfRange) {
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
