// `pirouette world generate` as a user meets it: a world file that loads from
// wherever it is written and that `eval` takes, the same bytes for the same
// kind, seed and size, exit code 2 with a message naming the option for bad
// usage, 1 when the file cannot be written (SPEC.md, "Worlds nobody drew by hand").

#include <gtest/gtest.h>

#include <filesystem>
#include <nlohmann/json.hpp>
#include <string>

#include "pirouette/io/map_file.h"
#include "pirouette/io/world_file.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/mapping/trinary_map.h"
#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace {

namespace fs = std::filesystem;

using pirouette::mapping::CellState;
using pirouette::testing::RunPirouette;
using Result = pirouette::testing::RunResult;

class WorldGenerateCliTest : public ::testing::Test {
 protected:
  std::string Path(const std::string& name) const { return dir_ / name; }
  std::string Read(const std::string& name) const { return dir_.Read(name); }

  // The world's true map on its robot's default cell, written to DIR/map.yaml.
  std::string WritePerfectMap(const pirouette::sim::World& world) const {
    const double cell = pirouette::mapping::DefaultCellSize(world.robot().radius);
    pirouette::mapping::TrinaryMap map{
        pirouette::core::GridGeometry::Covering(cell, {0.0, 0.0}, world.floor().size), {}};
    for (std::size_t i = 0; i < map.geometry.CellCount(); ++i) {
      const Eigen::Vector2d c = map.geometry.CellCentre(map.geometry.Unflat(i));
      map.cells.push_back(world.IsOccupied(c) ? CellState::kOccupied : CellState::kFree);
    }
    pirouette::io::WriteRosMap(map, Path("map.yaml"));
    return Path("map.yaml");
  }

  pirouette::testing::TempDir dir_{"pirouette_world_generate_cli_test"};
};

TEST_F(WorldGenerateCliTest, WritesAWorldThatLoadsFromItsFolderAndEvalTakes) {
  fs::create_directories(Path("elsewhere/deep"));
  const std::string out = Path("elsewhere/deep/maze.yaml");
  const Result r = RunPirouette("world generate --kind maze --seed 7 --out " + out);
  ASSERT_EQ(r.exit_code, 0) << r.output();
  EXPECT_TRUE(r.stdout_only.empty()) << "generate prints nothing on standard output";
  EXPECT_NE(r.stderr_only.find("wrote " + out), std::string::npos) << r.stderr_only;
  // No camera file beside it: the camera is inline.
  EXPECT_FALSE(fs::exists(Path("elsewhere/deep/yujin.yaml")));
  const pirouette::sim::World world = pirouette::io::LoadWorldFile(out);
  EXPECT_EQ(world.name(), "maze-7");
  EXPECT_EQ(world.robot().camera.name(), "yujin");

  const Result eval = RunPirouette("eval --world " + out + " --map " + WritePerfectMap(world));
  ASSERT_EQ(eval.exit_code, 0) << eval.output();
  const nlohmann::json j = nlohmann::json::parse(eval.stdout_only);
  EXPECT_EQ(j.at("coverage").get<double>(), 1.0);
  EXPECT_EQ(j.at("false_free").get<double>(), 0.0);
  EXPECT_GT(j.at("reachable_cells").get<int>(), 1000);
}

TEST_F(WorldGenerateCliTest, TheSameKindSeedAndSizeGiveTheSameBytes) {
  const std::string args = "world generate --kind apartment --seed 3 --size 9,7.5 --out ";
  ASSERT_EQ(RunPirouette(args + Path("a.yaml")).exit_code, 0);
  ASSERT_EQ(RunPirouette(args + Path("b.yaml")).exit_code, 0);
  ASSERT_FALSE(Read("a.yaml").empty());
  EXPECT_EQ(Read("a.yaml"), Read("b.yaml"));
  EXPECT_EQ(pirouette::io::LoadWorldFile(Path("a.yaml")).floor().size, Eigen::Vector2d(9.0, 7.5));
  ASSERT_EQ(
      RunPirouette("world generate --kind apartment --seed 4 --size 9,7.5 --out " + Path("c.yaml"))
          .exit_code,
      0);
  EXPECT_NE(Read("a.yaml"), Read("c.yaml"));
}

TEST_F(WorldGenerateCliTest, EveryKindIsMade) {
  for (const std::string kind : {"rooms", "maze", "clutter", "apartment"}) {
    const std::string out = Path(kind + ".yaml");
    const Result r = RunPirouette("world generate --kind " + kind + " --seed 1 --out " + out);
    ASSERT_EQ(r.exit_code, 0) << kind << ": " << r.output();
    EXPECT_EQ(pirouette::io::LoadWorldFile(out).name(), kind + "-1");
  }
}

TEST_F(WorldGenerateCliTest, BadUsageExitsTwoNamingTheOption) {
  const std::string out = " --out " + Path("x.yaml");
  const Result kind = RunPirouette("world generate --kind house --seed 1" + out);
  EXPECT_EQ(kind.exit_code, 2);
  EXPECT_NE(kind.stderr_only.find("--kind"), std::string::npos) << kind.output();
  EXPECT_NE(kind.stderr_only.find("rooms, maze, clutter or apartment"), std::string::npos);
  for (const std::string size : {"1,2,3", "2", "a,b", "0.1,2", "2,9", "nan,2"}) {
    const Result r = RunPirouette("world generate --kind rooms --seed 1 --size " + size + out);
    EXPECT_EQ(r.exit_code, 2) << size;
    EXPECT_NE(r.stderr_only.find("--size"), std::string::npos) << size << ": " << r.output();
  }
  const Result big = RunPirouette("world generate --kind apartment --seed 1 --size 50,10" + out);
  EXPECT_EQ(big.exit_code, 2);
  EXPECT_NE(big.stderr_only.find("[4, 30] m"), std::string::npos) << big.output();
  EXPECT_EQ(RunPirouette("world generate --kind rooms --seed 1").exit_code, 2);  // no --out
  EXPECT_EQ(RunPirouette("world generate --seed 1" + out).exit_code, 2);         // no --kind
  EXPECT_EQ(RunPirouette("world generate --kind rooms" + out).exit_code, 2);     // no --seed
  EXPECT_EQ(RunPirouette("world").exit_code, 2);
  EXPECT_FALSE(fs::exists(Path("x.yaml")));
}

TEST_F(WorldGenerateCliTest, AFileThatCannotBeWrittenExitsOne) {
  const Result r =
      RunPirouette("world generate --kind rooms --seed 1 --out " + Path("no/such/folder/x.yaml"));
  EXPECT_EQ(r.exit_code, 1);
  EXPECT_NE(r.stderr_only.find("cannot write"), std::string::npos) << r.output();
}

TEST_F(WorldGenerateCliTest, HelpTeachesTheKinds) {
  const Result world = RunPirouette("world --help");
  EXPECT_EQ(world.exit_code, 0);
  EXPECT_NE(world.output().find("generate"), std::string::npos);
  const Result help = RunPirouette("world generate --help");
  EXPECT_EQ(help.exit_code, 0);
  for (const char* words : {"rooms", "maze", "clutter", "apartment", "--size", "--seed",
                            "as high as the camera", "reachable"}) {
    EXPECT_NE(help.output().find(words), std::string::npos) << words;
  }
  EXPECT_NE(RunPirouette("--help").output().find("world"), std::string::npos);
}

}  // namespace
