// Run logs (issue 5): a run explored with --record and mapped again from its
// log with `map --log` gives the same map, byte for byte.

#include <gtest/gtest.h>
#include <unistd.h>

#include <array>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <string>

#include "pirouette/io/run_log.h"
#include "pirouette/run/explore_job.h"
#include "pirouette/run/log_replay.h"

namespace pirouette::run {
namespace {

namespace fs = std::filesystem;

std::string ReadAll(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

class RunLogRoundTripTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("pirouette_run_log_" + std::to_string(getpid()));
    fs::remove_all(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  fs::path dir_;
};

// The maze makes the explorer find a move blocked and back up to see, so the
// log's contact and blocked columns are exercised as well as its frames.
TEST_F(RunLogRoundTripTest, MapFromTheLogIsTheMapTheRunMade) {
  run::ExploreRequest explore;
  explore.world_path = std::string(PIROUETTE_WORLDS_DIR) + "/maze.yaml";
  explore.out_dir = (dir_ / "explore").string();
  explore.record_dir = (dir_ / "log").string();
  explore.quiet = true;
  const ExploreReport explored = RunExplore(explore);
  ASSERT_EQ(explored.result.status, "complete") << explored.result.reason;

  const io::RunLog log = io::ReadRunLog(explore.record_dir);
  EXPECT_EQ(static_cast<int>(log.rows.size()), explored.result.frames);
  EXPECT_EQ(log.info.world, explore.world_path);
  EXPECT_DOUBLE_EQ(log.info.radius_m, 0.04);
  int blocked = 0;
  for (const io::RunLogRow& row : log.rows) blocked += row.blocked_leg_m ? 1 : 0;
  EXPECT_LE(blocked, explored.result.blocked_looks);

  run::MapLogRequest map;
  map.log_dir = explore.record_dir;
  map.out_dir = (dir_ / "map").string();
  map.quiet = true;
  const MapLogReport mapped = RunMapLog(map);
  EXPECT_EQ(mapped.result.frames, explored.result.frames);
  EXPECT_EQ(ReadAll(dir_ / "map" / "map.pgm"), ReadAll(dir_ / "explore" / "map.pgm"));
  EXPECT_EQ(ReadAll(dir_ / "map" / "map.yaml"), ReadAll(dir_ / "explore" / "map.yaml"));
  EXPECT_EQ(mapped.run["eval"], explored.run["eval"]);
  EXPECT_EQ(ReadAll(dir_ / "map" / "map_colours.png"),
            ReadAll(dir_ / "explore" / "map_colours.png"));
  EXPECT_TRUE(fs::exists(dir_ / "map" / "map.png"));
  EXPECT_TRUE(fs::exists(dir_ / "map" / "run.json"));
}

}  // namespace
}  // namespace pirouette::run

namespace pirouette::run {
namespace {

// With pose tracking and odometry noise the log records `localize: scan`,
// and mapping it again tracks the same way: the same map.
TEST_F(RunLogRoundTripTest, ATrackedRunMapsAgainTheSame) {
  run::ExploreRequest explore;
  explore.world_path = std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml";
  explore.out_dir = (dir_ / "explore").string();
  explore.record_dir = (dir_ / "log").string();
  explore.quiet = true;
  explore.options.localize = LocalizeKind::kScan;
  explore.odometry_noise = std::array<double, 2>{0.05, 0.05};
  const ExploreReport explored = RunExplore(explore);
  EXPECT_EQ(explored.run["localize"], "scan");
  EXPECT_EQ(io::ReadRunLog(explore.record_dir).info.localize, "scan");

  run::MapLogRequest map;
  map.log_dir = explore.record_dir;
  map.out_dir = (dir_ / "map").string();
  map.quiet = true;
  run::RunMapLog(map);
  EXPECT_EQ(ReadAll(dir_ / "map" / "map.pgm"), ReadAll(dir_ / "explore" / "map.pgm"));
  EXPECT_EQ(ReadAll(dir_ / "map" / "map.yaml"), ReadAll(dir_ / "explore" / "map.yaml"));
  EXPECT_EQ(ReadAll(dir_ / "map" / "map_colours.png"),
            ReadAll(dir_ / "explore" / "map_colours.png"));

  // Mapped again without tracking, the same frames make another map.
  map.out_dir = (dir_ / "untracked").string();
  map.localize = "none";
  RunMapLog(map);
  EXPECT_NE(ReadAll(dir_ / "untracked" / "map.pgm"), ReadAll(dir_ / "explore" / "map.pgm"));
}

}  // namespace
}  // namespace pirouette::run
