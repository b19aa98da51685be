#include "pirouette/run/checkpoint_writer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <vector>

#include "pirouette/io/map_file.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::run {
namespace checkpoint_test {

// A grid with one wall cell and one free cell, seen `frames` times.
mapping::OccupancyGrid SeenGrid(int frames) {
  mapping::OccupancyGrid grid(core::GridGeometry(0.05, Eigen::Vector2d(-1.0, -1.0), 40, 40));
  for (int i = 0; i < frames; ++i) {
    grid.BeginFrame();
    grid.Apply({10, 5}, mapping::CellUpdate::kHit);
    grid.Apply({10, 30}, mapping::CellUpdate::kMiss);
  }
  return grid;
}

struct FakeRun {
  mapping::OccupancyGrid grid = SeenGrid(10);
  std::vector<core::Pose2> path = {core::Pose2(0, 0, 0), core::Pose2(0.3, 0.4, 0)};
  std::vector<core::Pose2> stops = {core::Pose2(0, 0, 0)};
  std::vector<Eigen::Vector2d> plan;
  cv::Mat3b bgr;
  cv::Mat1b mask;

  RunSnapshot At(int frames) const {
    ExplorationProgress progress;
    progress.moves = 1;
    progress.pirouettes = 1;
    progress.known_area_m2 = 0.005;
    progress.elapsed_s = 1.5;
    return RunSnapshot{grid,          path, stops, plan,   core::Pose2(0.3, 0.4, 0),
                       core::Pose2(), bgr,  mask,  frames, progress};
  }
};

// The map and run.json of the last stop are on disk, whole: the map reads
// back as map_server reads it, run.json says the run is running.
TEST(CheckpointWriter, WritesTheMapAndARunningRunJson) {
  const testing::TempDir dir("checkpoint");
  CheckpointWriter writer(dir.path().string(), {{"format", "pirouette-run/1"}, {"seed", 7}});
  const FakeRun fake;
  writer.Publish(fake.At(13));
  EXPECT_EQ(writer.Finish(), "");

  const mapping::TrinaryMap map = io::ReadRosMap(dir / "map.yaml");
  EXPECT_EQ(map.geometry.width(), 11);  // the seen part with its 5-cell margin
  const nlohmann::json json = nlohmann::json::parse(dir.Read("run.json"));
  EXPECT_EQ(json["status"], "running");
  EXPECT_EQ(json["format"], "pirouette-run/1");
  EXPECT_EQ(json["seed"], 7);
  EXPECT_EQ(json["frames"], 13);
  EXPECT_EQ(json["stops"], 1);
  EXPECT_DOUBLE_EQ(json["path_length_m"].get<double>(), 0.5);
  EXPECT_EQ(writer.cost().taken, 1);
  EXPECT_EQ(writer.cost().written, 1);
  // Nothing is left aside: every temporary file was renamed.
  int files = 0;
  for (const auto& entry : std::filesystem::directory_iterator(dir.path())) {
    EXPECT_EQ(entry.path().string().find(".tmp-"), std::string::npos) << entry.path();
    ++files;
  }
  EXPECT_EQ(files, 3);
}

// A snapshot without new frames (after a plan) takes no checkpoint; the
// last one taken is the one on disk at the end.
TEST(CheckpointWriter, TakesOnlyNewFramesAndWritesTheLast) {
  const testing::TempDir dir("checkpoint");
  CheckpointWriter writer(dir.path().string(), nlohmann::json::object());
  const FakeRun fake;
  writer.Publish(fake.At(12));
  writer.Publish(fake.At(12));
  writer.Publish(fake.At(13));
  EXPECT_EQ(writer.Finish(), "");
  EXPECT_EQ(writer.cost().taken, 2);
  EXPECT_GE(writer.cost().written, 1);
  EXPECT_EQ(nlohmann::json::parse(dir.Read("run.json"))["frames"], 13);
  writer.Publish(fake.At(14));  // after Finish: nothing
  EXPECT_EQ(nlohmann::json::parse(dir.Read("run.json"))["frames"], 13);
}

// A folder that cannot be written stops the checkpoints; Finish says why.
TEST(CheckpointWriter, SaysWhyWhenTheFolderIsGone) {
  CheckpointWriter writer("/nonexistent/pirouette-checkpoint", nlohmann::json::object());
  const FakeRun fake;
  writer.Publish(fake.At(1));
  EXPECT_NE(writer.Finish().find("/nonexistent/pirouette-checkpoint"), std::string::npos);
}

}  // namespace checkpoint_test
}  // namespace pirouette::run
