#include "pirouette/tools/explore_eval.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "pirouette/core/input_error.h"
#include "pirouette/io/world_file.h"
#include "pirouette/testing/input_error.h"
#include "pirouette/testing/same_world.h"
#include "pirouette/testing/temp_dir.h"
#include "pirouette/tools/world_generate.h"

// Its own namespace: the unit tests compile together (unity batches).
namespace pirouette::tools::explore_eval_test {
namespace {

using sim::WorldKind;
using testing::ExpectInputError;

std::vector<std::uint64_t> SeedsOf(const std::vector<GeneratedWorldRequest>& worlds) {
  std::vector<std::uint64_t> seeds;
  seeds.reserve(worlds.size());
  for (const GeneratedWorldRequest& world : worlds) seeds.push_back(world.seed);
  return seeds;
}

TEST(ParseGenerateSpecTest, ReadsRangesListsAndBoth) {
  EXPECT_EQ(ParseGenerateSpec("maze:1-10"),
            (std::vector<GeneratedWorldRequest>{{WorldKind::kMaze, 1},
                                                {WorldKind::kMaze, 2},
                                                {WorldKind::kMaze, 3},
                                                {WorldKind::kMaze, 4},
                                                {WorldKind::kMaze, 5},
                                                {WorldKind::kMaze, 6},
                                                {WorldKind::kMaze, 7},
                                                {WorldKind::kMaze, 8},
                                                {WorldKind::kMaze, 9},
                                                {WorldKind::kMaze, 10}}));
  EXPECT_EQ(ParseGenerateSpec("rooms:1,4,7"),
            (std::vector<GeneratedWorldRequest>{
                {WorldKind::kRooms, 1}, {WorldKind::kRooms, 4}, {WorldKind::kRooms, 7}}));
  // In the order given; a range of one seed; seed 0 and the largest.
  EXPECT_EQ(SeedsOf(ParseGenerateSpec("clutter:9,1-3,5-5,0")),
            (std::vector<std::uint64_t>{9, 1, 2, 3, 5, 0}));
  EXPECT_EQ(SeedsOf(ParseGenerateSpec("apartment:18446744073709551615")),
            (std::vector<std::uint64_t>{18446744073709551615ULL}));
  EXPECT_EQ(SeedsOf(ParseGenerateSpec("maze:18446744073709551614-18446744073709551615")),
            (std::vector<std::uint64_t>{18446744073709551614ULL, 18446744073709551615ULL}));
  for (const WorldKind kind : sim::kWorldKinds) {
    const std::string name(sim::WorldKindName(kind));
    EXPECT_EQ(ParseGenerateSpec(name + ":3"), (std::vector<GeneratedWorldRequest>{{kind, 3}}));
  }
  EXPECT_EQ(ParseGenerateSpec("maze:1-1000").size(), kMaxGeneratedWorlds);
}

TEST(ParseGenerateSpecTest, RefusesBadValuesNamingTheOptionAndTheValue) {
  struct Case {
    const char* text;
    const char* problem;
  };
  const std::vector<Case> cases = {
      {"maze", "expected KIND:SEEDS"},
      {"maze-1", "expected KIND:SEEDS"},
      {"", "expected KIND:SEEDS"},
      {"house:1", "unknown kind 'house' (expected rooms, maze, clutter or apartment)"},
      {"Maze:1", "unknown kind 'Maze'"},
      {":1", "unknown kind ''"},
      {"maze:", "'' is not a seed"},
      {"maze:1,,2", "'' is not a seed"},
      {"maze:1,", "'' is not a seed"},
      {"maze:x", "'x' is not a seed"},
      {"maze:-3", "'' is not a seed"},
      {"maze:3-", "'' is not a seed"},
      {"maze:1-2-3", "'2-3' is not a seed"},
      {"maze:+1", "'+1' is not a seed"},
      {"maze: 1", "' 1' is not a seed"},
      {"maze:1.5", "'1.5' is not a seed"},
      {"maze:18446744073709551616", "'18446744073709551616' is not a seed"},
      {"maze:5-3", "the range 5-3 runs backwards"},
      {"maze:1-3,2", "seed 2 is given twice"},
      {"maze:1-1001", "more than 1000 worlds"},
      {"maze:0-18446744073709551615", "more than 1000 worlds"},
      {"maze:1-600,601-1200", "more than 1000 worlds"},
  };
  for (const Case& c : cases) {
    const core::InputError e = ExpectInputError([&] { (void)ParseGenerateSpec(c.text); });
    const std::string message = e.what();
    EXPECT_EQ(message.rfind("--generate: '" + std::string(c.text) + "': ", 0), 0u)
        << c.text << ": " << message;
    EXPECT_NE(message.find(c.problem), std::string::npos) << c.text << ": " << message;
  }
}

// The world made in memory is the one its file holds, and explores the same.
TEST(ExploreEvalTest, AGeneratedWorldExploresAsTheFileWorldGenerateWrites) {
  const testing::TempDir dir;
  const std::string path = dir / "clutter1.yaml";
  (void)RunWorldGenerate({WorldKind::kClutter, 1, std::nullopt, path});
  const GeneratedWorldRequest generated{WorldKind::kClutter, 1};
  EXPECT_TRUE(testing::SameWorld(LoadGeneratedWorld(generated), io::LoadWorldFile(path)));

  ExploreEvalRequest from_file;
  from_file.world_paths = {path};
  from_file.seeds = {2};
  from_file.planners = {run::PlannerKind::kDistanceTransform};
  from_file.options.max_steps = 2;
  ExploreEvalRequest in_memory = from_file;
  in_memory.world_paths.clear();
  in_memory.generated = {generated};
  const std::vector<ExploreEvalRun> a = EvaluateExploration(from_file);
  const std::vector<ExploreEvalRun> b = EvaluateExploration(in_memory);
  ASSERT_EQ(a.size(), 1u);
  ASSERT_EQ(b.size(), 1u);
  EXPECT_EQ(b[0].world_name, "clutter-1");
  EXPECT_EQ(b[0].world_name, a[0].world_name);
  EXPECT_EQ(b[0].seed, 2u);
  EXPECT_EQ(b[0].status, a[0].status);
  EXPECT_EQ(b[0].eval.coverage, a[0].eval.coverage);
  EXPECT_EQ(b[0].eval.false_free, a[0].eval.false_free);
  EXPECT_EQ(b[0].eval.false_occupied, a[0].eval.false_occupied);
  EXPECT_EQ(b[0].eval.wall_error_m, a[0].eval.wall_error_m);
  EXPECT_EQ(b[0].path_length_m, a[0].path_length_m);
  EXPECT_EQ(b[0].stops, a[0].stops);
  EXPECT_EQ(b[0].moves, a[0].moves);
  EXPECT_GT(b[0].stops, 0);
}

ExploreEvalRun FakeRun(run::PlannerKind planner, const std::string& status, double path_m) {
  ExploreEvalRun run;
  run.world_name = "maze-7";
  run.planner = planner;
  run.status = status;
  run.eval.coverage = 0.9;
  run.cell_m = 0.01;
  run.path_length_m = path_m;
  run.stops = 4;
  run.wall_time_s = 2.0;
  return run;
}

TEST(ExploreEvalTableTest, SaysHowTheRunsThatDidNotCompleteEnded) {
  const std::string table = ExploreEvalTable({
      FakeRun(run::PlannerKind::kDistanceTransform, "complete", 1.0),
      FakeRun(run::PlannerKind::kDistanceTransform, "step-limit", 2.0),
      FakeRun(run::PlannerKind::kDistanceTransform, "stuck", 3.0),
      FakeRun(run::PlannerKind::kDistanceTransform, "step-limit", 2.0),
      FakeRun(run::PlannerKind::kFrontier, "complete", 4.0),
  });
  EXPECT_NE(table.find("| maze-7 | dt | 1/4 (step-limit 2, stuck 1) | 0.900 |"), std::string::npos)
      << table;
  EXPECT_NE(table.find("| 2.00 | 4.0 | 2.0 | 0.50× |"), std::string::npos) << table;
  EXPECT_NE(table.find("| maze-7 | frontier | 1/1 | 0.900 |"), std::string::npos) << table;
}

TEST(ExploreEvalTableTest, NoRatioAgainstABaselineThatDidNotMove) {
  const std::string table = ExploreEvalTable({
      FakeRun(run::PlannerKind::kDistanceTransform, "complete", 1.0),
      FakeRun(run::PlannerKind::kFrontier, "step-limit", 0.0),
  });
  EXPECT_EQ(table.find("×"), std::string::npos) << table;
  EXPECT_EQ(table.find("inf"), std::string::npos) << table;
}

}  // namespace
}  // namespace pirouette::tools::explore_eval_test
