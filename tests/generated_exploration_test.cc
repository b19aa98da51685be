// Generated worlds explored (issue 20, docs/worlds.md): one world of each
// kind, made by `world generate`, explored with the defaults and no odometry
// noise, ends complete within the noise-free bounds. The seeds are ones the
// explorer maps within the bounds today (docs/measurements.md, "Generated
// worlds", gives the rate over worlds chosen before looking); this guards them.

#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace {

struct Generated {
  const char* kind;
  int seed;
  const char* size;  // --size X,Y, or "" for the kind's own draw
  // The least coverage: the bound (0.98), or what the explorer reaches today
  // where it falls short of it, said why.
  double coverage = 0.98;
};

// Generates the world `g` names and explores it with the defaults (and
// `options`); the run's run.json (null, with a test failure, when either
// command failed).
nlohmann::json GenerateAndExplore(const Generated& g, const pirouette::testing::TempDir& dir,
                                  const std::string& options = "") {
  const std::string world = dir / "world.yaml";
  std::string generate = std::string("world generate --kind ") + g.kind + " --seed " +
                         std::to_string(g.seed) + " --out " + world;
  if (*g.size != '\0') generate += std::string(" --size ") + g.size;
  const auto made = pirouette::testing::RunPirouette(generate);
  EXPECT_EQ(made.exit_code, 0) << made.output();
  if (made.exit_code != 0) return nullptr;
  const auto run = pirouette::testing::RunPirouette("explore --quiet --world " + world + " --out " +
                                                    (dir / "out") + options);
  EXPECT_EQ(run.exit_code, 0) << run.output();
  if (run.exit_code != 0) return nullptr;
  std::ifstream in(dir / "out/run.json");
  return nlohmann::json::parse(in);
}

class GeneratedExplorationTest : public ::testing::TestWithParam<Generated> {};

TEST_P(GeneratedExplorationTest, IsMappedWithinTheBounds) {
  const Generated& g = GetParam();
  const pirouette::testing::TempDir dir("pirouette_generated_exploration_test");
  const nlohmann::json j = GenerateAndExplore(g, dir);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j.at("status"), "complete");
  const nlohmann::json& e = j.at("eval");
  EXPECT_GE(e.at("coverage").get<double>(), g.coverage);
  EXPECT_LE(e.at("false_free").get<double>(), 0.005);
  EXPECT_LE(e.at("false_occupied").get<double>(), 0.02);
  // One cell: 1 cm for the Yujin robot's map, 2 cm for the apartment robot's.
  EXPECT_LE(e.at("wall_error_m").get<double>(), std::string(g.kind) == "apartment" ? 0.02 : 0.01);
}

INSTANTIATE_TEST_SUITE_P(
    Kinds, GeneratedExplorationTest,
    // The maze falls short of the coverage bound since the map of
    // record calls free only floor seen free from two places: the
    // dead ends the robot saw whole from their mouths stay unknown
    // there (0.945; 0.98 or more before, docs/worlds.md, fix 7).
    ::testing::Values(Generated{"rooms", 1, ""}, Generated{"maze", 7, "", 0.93},
                      Generated{"clutter", 1, ""}, Generated{"apartment", 2, "6,5"}),
    [](const ::testing::TestParamInfo<Generated>& info) { return std::string(info.param.kind); });

// Maze 108's corridors are 0.12-0.20 m wide, narrower than twice the camera's
// near range: at its start the views across one are filled by walls, whose
// blind areas, grown by the radius, close every way out of the robot's
// coarse cell. Once the first pirouette ended the run there ("complete" at
// coverage 0.002); the robot now probes across the blind ring along the
// corridor it saw (Explorer::ProbeAcrossTheBlindRing) and goes on mapping.
// Later its exploring runs out of plans with much of the maze unseen, and
// the second looks (trips to see again from a second place the floor one
// place saw free) carry it on: their budget, a quarter of the pirouettes,
// once fixed when exploring first ran out, stopped them at coverage 0.40;
// reckoned on the whole run, they take it to 0.54 (docs/worlds.md, fix 17).
// It still falls far short of the bounds (docs/worlds.md, "Still open", 1),
// so this checks that it gets out and goes on, and maps no false free floor.
TEST(BoxedInMazeTest, ProbesOutOfItsStartAndSecondLooksCarryItOn) {
  const pirouette::testing::TempDir dir("pirouette_boxed_in_maze_test");
  const nlohmann::json j = GenerateAndExplore(Generated{"maze", 108, ""}, dir);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j.at("status"), "complete");
  EXPECT_GE(j.at("probes").get<int>(), 1);
  EXPECT_GE(j.at("pirouettes").get<int>(), 5);
  const nlohmann::json& e = j.at("eval");
  EXPECT_GE(e.at("coverage").get<double>(), 0.5);
  EXPECT_LE(e.at("false_free").get<double>(), 0.005);
}

// Maze 103 starts in a dead end: its first view and four more are a wall a
// few centimetres off, taller than the camera, and in two of them the floor
// shows beside it. Those views once voted, with the wall learnt first, for
// the wall's appearance as the floor's, and the run ended at its first stop
// (coverage 0.001). A view whose appearance runs from the bottom of the view
// to its top shows no end of it and no longer votes
// (vision::AppearanceSegmenter, docs/worlds.md fix 13).
//
// Later the robot ends its exploring in a pocket whose only way out, past a
// wall's end, a phantom speck and the wall's end drawn a cell long close on
// the map: no plan for the robot's disc passes there, and the run ended
// `complete` at coverage 0.45 with half the maze beyond. The last plan is
// now one for a robot a cell narrower (docs/worlds.md fix 19), which goes
// through. Further on, the robot's disc came to rest on a wall's end with
// a wall less than the camera's near range behind it, and every move that
// way stopped at once, 40 in a row (`stuck`): a contact now backs off as
// far as the known-free floor allows, down to a radius. Checks the whole
// story: off the first stop, through the pocket's closed way out, to the
// end without getting stuck (coverage 0.92 today; still short of 0.98).
TEST(DeadEndMazeTest, TheFirstPirouettesVoteFindsTheFloor) {
  const pirouette::testing::TempDir dir("pirouette_dead_end_maze_test");
  const nlohmann::json j = GenerateAndExplore(Generated{"maze", 103, ""}, dir);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j.at("status"), "complete");
  EXPECT_GE(j.at("pirouettes").get<int>(), 10);
  const nlohmann::json& e = j.at("eval");
  EXPECT_GE(e.at("coverage").get<double>(), 0.8);
  EXPECT_LE(e.at("false_free").get<double>(), 0.005);
}

// Maze 101: the robot comes down a corridor 0.12 m wide to where its wall
// ends and a side corridor turns back beside it. The goals at the side
// corridor's mouth lie within the camera's near range of every point of the
// way down, or behind the wall's end: the plans once ended 0.13-0.16 m from
// them (the view distance alone), the pirouettes there never saw them, and
// the run ended `complete` at coverage 0.10 with the rest of the maze
// beyond. A plan now ends only where its goal is in view (past the near
// range, within the view distance, no wall across the line of sight), else
// at its path's end (Explorer::StopWhereTheGoalIsInView), and a look that
// sees only a wall near lets a move go where the map knows the look's own
// corridor free. Still short of the bounds (docs/worlds.md, fix 16): this
// checks that the robot gets round the wall's end and on through the maze.
TEST(SideCorridorMazeTest, APlanEndsWhereItsGoalIsInView) {
  const pirouette::testing::TempDir dir("pirouette_side_corridor_maze_test");
  const nlohmann::json j = GenerateAndExplore(Generated{"maze", 101, ""}, dir);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j.at("status"), "complete");
  const nlohmann::json& e = j.at("eval");
  EXPECT_GE(e.at("coverage").get<double>(), 0.4);
  EXPECT_LE(e.at("false_free").get<double>(), 0.005);
}

// Rooms 104: the robot ends its exploring in a room it entered through a
// doorway the coarse grid closes (0.13-0.14 m for a 0.08 m robot), with
// floor elsewhere seen free from one place only. The second looks at that
// floor (Explorer::CorroborationMap) were planned on the coarse grid alone,
// found no way out of the room, and the map of record kept the floor
// unknown (coverage 0.960). They fall back on the map's own cells as
// exploring does.
TEST(CorroborationTest, SecondLooksPassADoorwayTheCoarseGridCloses) {
  const pirouette::testing::TempDir dir("pirouette_corroboration_doorway_test");
  const nlohmann::json j = GenerateAndExplore(Generated{"rooms", 104, ""}, dir);
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j.at("status"), "complete");
  const nlohmann::json& e = j.at("eval");
  EXPECT_GE(e.at("coverage").get<double>(), 0.98);
  EXPECT_LE(e.at("false_free").get<double>(), 0.005);
}

// Maze 109: a plan's end left the robot at a corridor's corner with its disc
// 12 mm clear of a wall's true face, which the map drew 1.2 cm thicker; its
// own cell lay inside the wall as the configuration space grows it, no
// planner could start there, and the run ended `complete` after 27 stops
// (207 moves) at coverage 0.09 with most of the maze beyond. The planning
// map now clears the cells under the robot's disc
// (explore::ClearFootprint, docs/worlds.md fix 18), and the robot goes on
// (coverage 0.71 in the whole run). The first 250 moves check it: the run
// is still going when they are spent.
TEST(FootprintMazeTest, APlanStartsWhereTheRobotStands) {
  const pirouette::testing::TempDir dir("pirouette_footprint_maze_test");
  const nlohmann::json j = GenerateAndExplore(Generated{"maze", 109, ""}, dir, " --max-steps 250");
  ASSERT_FALSE(j.is_null());
  EXPECT_EQ(j.at("status"), "step-limit");
  EXPECT_GE(j.at("pirouettes").get<int>(), 40);
  const nlohmann::json& e = j.at("eval");
  EXPECT_GE(e.at("coverage").get<double>(), 0.15);
  EXPECT_LE(e.at("false_free").get<double>(), 0.005);
}

}  // namespace
