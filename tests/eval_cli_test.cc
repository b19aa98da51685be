// `pirouette eval` as a user meets it: the evaluation as JSON on standard
// output and nothing else, exit code 2 with a message naming the file and
// field for a bad world or map (SPEC.md, "Commands" and "eval").

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <string>

#include "pirouette/io/map_file.h"
#include "pirouette/io/world_file.h"
#include "pirouette/mapping/trinary_map.h"
#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace {

using pirouette::mapping::CellState;
using pirouette::testing::RunPirouette;
using Result = pirouette::testing::RunResult;

class EvalCliTest : public ::testing::Test {
 protected:
  std::string Path(const std::string& name) const { return dir_ / name; }
  std::string Write(const std::string& name, const std::string& text) const {
    return dir_.Write(name, text);
  }
  static std::string World(const std::string& name) {
    return std::string(PIROUETTE_WORLDS_DIR) + "/" + name;
  }

  // Writes the soccer field's true map, on a 2 cm grid a cell larger than the
  // floor on every side, to DIR/map.yaml.
  std::string WritePerfectMap() const {
    const pirouette::sim::World world = pirouette::io::LoadWorldFile(World("soccer_field.yaml"));
    pirouette::mapping::TrinaryMap map{
        pirouette::core::GridGeometry::Covering(0.02, {-0.02, -0.02},
                                                world.floor().size + Eigen::Vector2d(0.04, 0.04)),
        {}};
    for (std::size_t i = 0; i < map.geometry.CellCount(); ++i) {
      const Eigen::Vector2d c = map.geometry.CellCentre(map.geometry.Unflat(i));
      map.cells.push_back(world.IsOccupied(c) ? CellState::kOccupied : CellState::kFree);
    }
    pirouette::io::WriteRosMap(map, Path("map.yaml"));
    return Path("map.yaml");
  }

  pirouette::testing::TempDir dir_{"pirouette_eval_cli_test"};
};

TEST_F(EvalCliTest, PrintsTheEvaluationAsJsonOnly) {
  const std::string map = WritePerfectMap();
  const Result r = RunPirouette("eval --world " + World("soccer_field.yaml") + " --map " + map);
  ASSERT_EQ(r.exit_code, 0) << r.output();
  // The whole of standard output is one JSON value.
  const nlohmann::json j = nlohmann::json::parse(r.stdout_only);
  ASSERT_TRUE(j.is_object()) << r.stdout_only;
  EXPECT_EQ(j.at("coverage").get<double>(), 1.0);
  EXPECT_EQ(j.at("false_free").get<double>(), 0.0);
  EXPECT_EQ(j.at("false_occupied").get<double>(), 0.0);
  EXPECT_EQ(j.at("wall_error_m").get<double>(), 0.0);
  const nlohmann::json& cells = j.at("cells");
  const auto total = cells.at("free").get<std::size_t>() + cells.at("occupied").get<std::size_t>() +
                     cells.at("unknown").get<std::size_t>();
  EXPECT_EQ(total, 77u * 67u);  // (1.50 + 0.04) / 0.02 × (1.30 + 0.04) / 0.02
  EXPECT_EQ(cells.at("unknown").get<int>(), 0);
  EXPECT_GT(j.at("reachable_cells").get<int>(), 0);
}

TEST_F(EvalCliTest, AMapOfAnotherWorldIsJudgedWrong) {
  // The maze's floor is 2 × 2 m with walls where the soccer field is free.
  const std::string map = WritePerfectMap();
  const Result r = RunPirouette("eval --world " + World("maze.yaml") + " --map " + map);
  ASSERT_EQ(r.exit_code, 0) << r.output();
  const nlohmann::json j = nlohmann::json::parse(r.stdout_only);
  EXPECT_LT(j.at("coverage").get<double>(), 1.0);
  EXPECT_GT(j.at("false_free").get<double>(), 0.0);
}

TEST_F(EvalCliTest, MissingMapIsBadInput) {
  const Result r =
      RunPirouette("eval --world " + World("soccer_field.yaml") + " --map " + Path("none.yaml"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.stdout_only.empty()) << r.stdout_only;
  EXPECT_NE(r.stderr_only.find(Path("none.yaml")), std::string::npos) << r.stderr_only;
}

TEST_F(EvalCliTest, MalformedMapNamesTheField) {
  WritePerfectMap();
  const std::string yaml = Write("bad.yaml",
                                 "image: map.pgm\nmode: trinary\nresolution: -0.02\n"
                                 "origin: [0, 0, 0]\nnegate: 0\noccupied_thresh: 0.65\n"
                                 "free_thresh: 0.196\n");
  const Result r = RunPirouette("eval --world " + World("soccer_field.yaml") + " --map " + yaml);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.stdout_only.empty()) << r.stdout_only;
  EXPECT_NE(r.stderr_only.find(yaml + ":3"), std::string::npos) << r.stderr_only;
  EXPECT_NE(r.stderr_only.find("'resolution'"), std::string::npos) << r.stderr_only;
}

TEST_F(EvalCliTest, MalformedYamlIsBadInput) {
  const std::string yaml = Write("broken.yaml", "image: map.pgm\norigin: [0, 0\n");
  const Result r = RunPirouette("eval --world " + World("soccer_field.yaml") + " --map " + yaml);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find(yaml), std::string::npos) << r.stderr_only;
}

TEST_F(EvalCliTest, BadWorldIsBadInput) {
  const std::string map = WritePerfectMap();
  const std::string world = Write("world.yaml", "format: pirouette-world/1\nname: t\n");
  const Result r = RunPirouette("eval --world " + world + " --map " + map);
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_TRUE(r.stdout_only.empty()) << r.stdout_only;
  EXPECT_NE(r.stderr_only.find(world), std::string::npos) << r.stderr_only;
}

TEST_F(EvalCliTest, MissingOptionIsBadUsage) {
  EXPECT_EQ(RunPirouette("eval --world " + World("soccer_field.yaml")).exit_code, 2);
}

TEST_F(EvalCliTest, HelpTeachesWithAnExample) {
  const Result r = RunPirouette("eval --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output().find("example: pirouette eval --world"), std::string::npos) << r.output();
  EXPECT_NE(r.output().find("--map"), std::string::npos) << r.output();
}

}  // namespace
