// Run logs: a run explored with --record and mapped again from its
// log with `map --log` gives the same map, byte for byte.

#include <gtest/gtest.h>

#include <array>
#include <filesystem>
#include <string>

#include "pirouette/io/run_log.h"
#include "pirouette/run/explore_job.h"
#include "pirouette/run/log_replay.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::run {
namespace {

namespace fs = std::filesystem;

class RunLogRoundTripTest : public ::testing::Test {
 protected:
  std::string Path(const std::string& name) const { return dir_ / name; }
  // The bytes of DIR/folder/file.
  std::string Read(const std::string& folder, const std::string& file) const {
    return dir_.Read(folder + "/" + file);
  }

  testing::TempDir dir_{"pirouette_run_log"};
};

// The maze makes the explorer find a move blocked and back up to see, so the
// log's contact and blocked columns are exercised as well as its frames.
TEST_F(RunLogRoundTripTest, MapFromTheLogIsTheMapTheRunMade) {
  run::ExploreRequest explore;
  explore.world_path = std::string(PIROUETTE_WORLDS_DIR) + "/maze.yaml";
  explore.out_dir = Path("explore");
  explore.record_dir = Path("log");
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
  map.out_dir = Path("map");
  map.quiet = true;
  const MapLogReport mapped = RunMapLog(map);
  EXPECT_EQ(mapped.result.frames, explored.result.frames);
  EXPECT_EQ(Read("map", "map.pgm"), Read("explore", "map.pgm"));
  EXPECT_EQ(Read("map", "map.yaml"), Read("explore", "map.yaml"));
  EXPECT_EQ(mapped.run["eval"], explored.run["eval"]);
  EXPECT_EQ(Read("map", "map_colours.png"), Read("explore", "map_colours.png"));
  EXPECT_TRUE(fs::exists(dir_.path() / "map" / "map.png"));
  EXPECT_TRUE(fs::exists(dir_.path() / "map" / "run.json"));
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
  explore.out_dir = Path("explore");
  explore.record_dir = Path("log");
  explore.quiet = true;
  explore.options.localize = LocalizeKind::kScan;
  explore.odometry_noise = std::array<double, 2>{0.05, 0.05};
  const ExploreReport explored = RunExplore(explore);
  EXPECT_EQ(explored.run["localize"], "scan");
  EXPECT_EQ(io::ReadRunLog(explore.record_dir).info.localize, "scan");

  run::MapLogRequest map;
  map.log_dir = explore.record_dir;
  map.out_dir = Path("map");
  map.quiet = true;
  run::RunMapLog(map);
  EXPECT_EQ(Read("map", "map.pgm"), Read("explore", "map.pgm"));
  EXPECT_EQ(Read("map", "map.yaml"), Read("explore", "map.yaml"));
  EXPECT_EQ(Read("map", "map_colours.png"), Read("explore", "map_colours.png"));

  // Mapped again without tracking, the same frames make another map.
  map.out_dir = Path("untracked");
  map.localize = "none";
  RunMapLog(map);
  EXPECT_NE(Read("untracked", "map.pgm"), Read("explore", "map.pgm"));
}

// With the pose graph the log records `localize: graph` and the odometry
// model, and mapping it again builds the same graph and the same map.
TEST_F(RunLogRoundTripTest, AGraphRunMapsAgainTheSame) {
  run::ExploreRequest explore;
  explore.world_path = std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml";
  explore.out_dir = Path("explore");
  explore.record_dir = Path("log");
  explore.quiet = true;
  explore.options.localize = LocalizeKind::kGraph;
  explore.odometry_noise = std::array<double, 2>{0.05, 0.05};
  const ExploreReport explored = RunExplore(explore);
  EXPECT_EQ(explored.run["localize"], "graph");
  EXPECT_EQ(explored.run["localization"]["method"], "graph");
  const io::RunLog log = io::ReadRunLog(explore.record_dir);
  EXPECT_EQ(log.info.localize, "graph");
  ASSERT_TRUE(log.info.odometry_model.has_value());
  EXPECT_DOUBLE_EQ((*log.info.odometry_model)[0], 0.05);

  run::MapLogRequest map;
  map.log_dir = explore.record_dir;
  map.out_dir = Path("map");
  map.quiet = true;
  run::RunMapLog(map);
  EXPECT_EQ(Read("map", "graph.g2o"), Read("explore", "graph.g2o"));
  EXPECT_EQ(Read("map", "map.pgm"), Read("explore", "map.pgm"));
  EXPECT_EQ(Read("map", "map_colours.png"), Read("explore", "map_colours.png"));
  EXPECT_NE(Read("explore", "graph.g2o").find("VERTEX_SE2 0 "), std::string::npos);
}

// A log recorded without noise mapped under drift (`map --log
// --odometry-noise`): the log's poses are the truth, so run.json gives the
// pose error and the loop closures against it; the graph takes out most of
// what the drift puts in; a seed gives the same map again, and a drift of
// nothing the map the run made.
TEST_F(RunLogRoundTripTest, ANoiseFreeLogMapsAgainUnderDriftAgainstItsOwnPoses) {
  run::ExploreRequest explore;
  explore.world_path = std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml";
  explore.out_dir = Path("explore");
  explore.record_dir = Path("log");
  explore.quiet = true;
  const ExploreReport explored = RunExplore(explore);
  ASSERT_EQ(explored.result.status, "complete");

  run::MapLogRequest map;
  map.log_dir = explore.record_dir;
  map.quiet = true;
  map.localize = "graph";
  map.odometry_noise = core::OdometryNoise{0.05, 0.05, 0.02, 0.01};
  map.seed = 3;
  map.out_dir = Path("graph");
  const MapLogReport graph = RunMapLog(map);
  map.out_dir = Path("again");
  RunMapLog(map);
  map.out_dir = Path("none");
  map.localize = "none";
  const MapLogReport none = RunMapLog(map);

  ASSERT_TRUE(graph.run.contains("pose_error"));
  ASSERT_TRUE(none.run.contains("pose_error"));
  EXPECT_EQ(graph.run["odometry_noise"]["seed"], 3);
  const double graph_ate = graph.run["pose_error"]["ate_rms_m"];
  const double none_ate = none.run["pose_error"]["ate_rms_m"];
  EXPECT_GT(none_ate, 0.05);  // 5% noise and a bias drift far over a run
  EXPECT_LT(graph_ate, 0.5 * none_ate);
  EXPECT_TRUE(graph.run["localization"]["loop_closures"].contains("correct"));
  EXPECT_EQ(Read("again", "map.pgm"), Read("graph", "map.pgm"));
  EXPECT_NE(Read("none", "map.pgm"), Read("graph", "map.pgm"));

  map.out_dir = Path("still");
  map.localize = "";
  map.odometry_noise = core::OdometryNoise{};
  const MapLogReport still = RunMapLog(map);
  EXPECT_EQ(Read("still", "map.pgm"), Read("explore", "map.pgm"));
  EXPECT_LT(static_cast<double>(still.run["pose_error"]["ate_rms_m"]), 0.005);
}

}  // namespace
}  // namespace pirouette::run
