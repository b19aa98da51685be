// `pirouette explore` as a user runs it: its outputs (SPEC.md) and its
// answers to bad input.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "pirouette/io/colour_map_file.h"
#include "pirouette/io/map_file.h"
#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace pirouette::testing {
namespace {

namespace fs = std::filesystem;

std::string World(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml";
}

std::string Slurp(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(ExploreCliTest, WritesTheMapFilesRunJsonAndVideo) {
  const TempDir dir("pirouette_explore_cli");
  const fs::path out = dir.path() / "out";
  const RunResult run = RunPirouette("explore --world " + World("soccer_field") + " --out " +
                                     out.string() + " --max-steps 4 --video --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output();
  EXPECT_TRUE(run.stdout_only.empty()) << run.stdout_only;
  for (const char* name : {"map.yaml", "map.pgm", "map.png", "map_colours.png", "run.json",
                           "explore.mp4", "graph.g2o"}) {
    EXPECT_TRUE(fs::exists(out / name)) << name;
  }
  EXPECT_FALSE(fs::exists(out / "explore.mp4.partial.mp4"));
  const nlohmann::json json = nlohmann::json::parse(Slurp(out / "run.json"));
  EXPECT_EQ(json["format"], "pirouette-run/1");
  EXPECT_EQ(json["status"], "step-limit");
  EXPECT_EQ(json["moves"], 4);
  EXPECT_EQ(json["seed"], 1);
  // The pose graph is on by default.
  EXPECT_EQ(json["localization"]["method"], "graph");
  EXPECT_TRUE(json.contains("pose_error"));
  // In the simulator the loop closures are checked against the truth.
  const nlohmann::json& loops = json["localization"]["loop_closures"];
  for (const char* field :
       {"accepted", "rejected", "correct", "worst_m", "worst_deg", "opportunities", "closed"}) {
    EXPECT_TRUE(loops.contains(field)) << field;
  }
  EXPECT_LE(loops["correct"].get<int>(), loops["accepted"].get<int>());
  EXPECT_LE(loops["closed"].get<int>(), loops["opportunities"].get<int>());
  EXPECT_GE(json["pirouettes"].get<int>(), 1);
  EXPECT_GE(json["frames"].get<int>(), 12);
  for (const char* field : {"turns", "path_length_m", "rotation_deg", "wall_time_s"}) {
    EXPECT_TRUE(json.contains(field)) << field;
  }
  for (const char* field : {"coverage", "false_free", "false_occupied", "wall_error_m", "cells"}) {
    EXPECT_TRUE(json["eval"].contains(field)) << field;
  }
  EXPECT_EQ(Slurp(out / "map.pgm").substr(0, 2), "P5");
  // The colour layer lies on the map's cells, and the walls and blocks seen
  // have colours there.
  const mapping::TrinaryMap map = io::ReadRosMap((out / "map.yaml").string());
  const localize::ColourMap colours =
      io::ReadColourMap((out / "map_colours.png").string(), map.geometry);
  int coloured_walls = 0;
  for (std::size_t i = 0; i < map.cells.size(); ++i) {
    coloured_walls += map.cells[i] == mapping::CellState::kOccupied &&
                      colours.cells()[i] != core::ColourClass::kNone;
  }
  EXPECT_GT(coloured_walls, 10);
  // The map it wrote evaluates to what run.json says.
  const RunResult eval = RunPirouette("eval --world " + World("soccer_field") + " --map " +
                                      (out / "map.yaml").string());
  ASSERT_EQ(eval.exit_code, 0) << eval.output();
  const nlohmann::json evaluated = nlohmann::json::parse(eval.stdout_only);
  EXPECT_EQ(evaluated["cells"], json["eval"]["cells"]);
}

// A run that ends complete gives up the goals it could not reach or see,
// and says so: run.json's given_up lists each with where the robot stood
// and why, so that unknown floor left behind is a reading job. On the
// soccer field the unknown cells round a stop past the field's edge are
// given up after the robot stepped away to look back at them.
TEST(ExploreCliTest, RunJsonListsTheGoalsGivenUpAndWhy) {
  const TempDir dir("pirouette_explore_cli_given_up");
  const fs::path out = dir.path() / "out";
  const RunResult run = RunPirouette("explore --world " + World("soccer_field") + " --out " +
                                     out.string() + " --quiet");
  ASSERT_EQ(run.exit_code, 0) << run.output();
  const nlohmann::json json = nlohmann::json::parse(Slurp(out / "run.json"));
  EXPECT_EQ(json["status"], "complete");
  const nlohmann::json& given_up = json["given_up"];
  ASSERT_TRUE(given_up.is_array());
  ASSERT_FALSE(given_up.empty());
  bool nearby = false;
  for (const nlohmann::json& g : given_up) {
    ASSERT_EQ(g["goal"].size(), 2U) << g;
    ASSERT_EQ(g["robot"].size(), 2U) << g;
    EXPECT_FALSE(g["why"].get<std::string>().empty()) << g;
    if (g.contains("cells")) {
      EXPECT_GT(g["cells"].get<int>(), 0) << g;
      nearby = nearby || g["why"].get<std::string>().starts_with("unknown near a stop");
    }
  }
  EXPECT_TRUE(nearby) << given_up;
}

TEST(ExploreCliTest, BadInputIsRefusedWithExitTwo) {
  const TempDir dir("pirouette_explore_cli");
  const fs::path out = dir.path() / "out";
  EXPECT_EQ(RunPirouette("explore --world /nonexistent.yaml --out " + out.string()).exit_code, 2);
  const RunResult steps = RunPirouette("explore --world " + World("soccer_field") + " --out " +
                                       out.string() + " --max-steps 0");
  EXPECT_EQ(steps.exit_code, 2);
  EXPECT_NE(steps.stderr_only.find("--max-steps"), std::string::npos) << steps.stderr_only;
  EXPECT_EQ(RunPirouette("explore --world " + World("soccer_field") + " --planner astar").exit_code,
            2);
  const RunResult model = RunPirouette("explore --world " + World("soccer_field") + " --out " +
                                       out.string() + " --odometry-model 0.05,-1");
  EXPECT_EQ(model.exit_code, 2);
  EXPECT_NE(model.stderr_only.find("--odometry-model"), std::string::npos) << model.stderr_only;
  EXPECT_FALSE(fs::exists(out));
}

}  // namespace
}  // namespace pirouette::testing
