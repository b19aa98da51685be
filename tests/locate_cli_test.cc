// `pirouette locate` as a user runs it: global localization (the kidnapped
// robot; Taylor, Geva & Boles 2005, §5.3) on a map that `pirouette explore`
// made, the place table it writes beside the map and reuses, the report, and
// its answers to bad input.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>

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

// One exploration of the soccer field for the whole suite (about 5 s).
class LocateCliTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    temp_ = std::make_unique<TempDir>("pirouette_locate_cli");
    dir_ = temp_->path();
    const RunResult explored = RunPirouette("explore --world " + World("soccer_field") +
                                            " --quiet --out " + (dir_ / "soccer").string());
    ASSERT_EQ(explored.exit_code, 0) << explored.output();
  }
  static void TearDownTestSuite() { temp_.reset(); }

  static std::string Map() { return (dir_ / "soccer" / "map.yaml").string(); }

  static std::unique_ptr<TempDir> temp_;  // the exploration, for the whole suite
  static fs::path dir_;                   // temp_'s path
};

std::unique_ptr<TempDir> LocateCliTest::temp_;
fs::path LocateCliTest::dir_;

// Found within one coarse cell and 10 degrees of the truth, or "cannot
// tell"; never wrong.
void ExpectFoundOrCannotTell(const nlohmann::json& report) {
  ASSERT_EQ(report["trials"].size(), 1U);
  const nlohmann::json& t = report["trials"][0];
  if (t["found"].get<bool>()) {
    EXPECT_LE(t["position_error_m"].get<double>(), report["coarse_cell_m"].get<double>()) << t;
    EXPECT_LE(t["heading_error_deg"].get<double>(), 10.0) << t;
    EXPECT_TRUE(t["right"].get<bool>()) << t;
  } else {
    EXPECT_TRUE(t.contains("reason")) << t;
  }
}

TEST_F(LocateCliTest, FindsTheRobotOrSaysItCannotAndReusesTheTable) {
  const fs::path table = dir_ / "places.yaml";
  int found = 0;
  int run = 0;
  for (const char* pose : {"0.75,0.65,30", "0.40,1.10,-120", "1.25,0.30,170"}) {
    const fs::path out = dir_ / ("report" + std::to_string(run) + ".json");
    const RunResult r =
        RunPirouette("locate --map " + Map() + " --world " + World("soccer_field") + " --pose " +
                     pose + " --quiet --table " + table.string() + " --out " + out.string());
    ASSERT_EQ(r.exit_code, 0) << r.output();
    EXPECT_TRUE(r.stdout_only.rfind("found ", 0) == 0 ||
                r.stdout_only.rfind("cannot tell: ", 0) == 0)
        << r.stdout_only;
    const nlohmann::json report = nlohmann::json::parse(Slurp(out));
    EXPECT_EQ(report["format"], "pirouette-locate-report/1");
    // The first run builds the table beside the map; the others load it.
    EXPECT_EQ(report["table_loaded"].get<bool>(), run > 0) << pose;
    EXPECT_GT(report["table_places"].get<int>(), 10);
    ExpectFoundOrCannotTell(report);
    found += report["trials"][0]["found"].get<bool>() ? 1 : 0;
    ++run;
  }
  EXPECT_TRUE(fs::exists(table));
  // explore wrote the map's colour layer, and locate used it.
  const nlohmann::json report = nlohmann::json::parse(Slurp(dir_ / "report0.json"));
  EXPECT_EQ(report["colours"], (dir_ / "soccer" / "map_colours.png").string());
  // A pose near a corner can look like another corner (the walls are all
  // grey): "cannot tell" is a right answer there, but at least one of these
  // is found.
  EXPECT_GE(found, 1);
}

TEST_F(LocateCliTest, TheSameRunGivesTheSameAnswer) {
  const std::string command = "locate --map " + Map() + " --world " + World("soccer_field") +
                              " --pose 0.75,0.65,30 --quiet --seed 3 --table " +
                              (dir_ / "same.yaml").string();
  const RunResult a = RunPirouette(command);
  const RunResult b = RunPirouette(command);
  ASSERT_EQ(a.exit_code, 0) << a.output();
  EXPECT_EQ(a.stdout_only, b.stdout_only);
}

TEST_F(LocateCliTest, NoColoursComparesRangesOnly) {
  const fs::path out = dir_ / "plain.json";
  const RunResult r = RunPirouette("locate --map " + Map() + " --world " + World("soccer_field") +
                                   " --pose 0.75,0.65,30 --quiet --no-colours --table " +
                                   (dir_ / "plain.yaml").string() + " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output();
  const nlohmann::json report = nlohmann::json::parse(Slurp(out));
  EXPECT_TRUE(report["colours"].is_null());
  ExpectFoundOrCannotTell(report);
}

TEST_F(LocateCliTest, DefaultTableGoesBesideTheMap) {
  const RunResult r = RunPirouette("locate --map " + Map() + " --world " + World("soccer_field") +
                                   " --pose 0.75,0.65,30 --quiet");
  ASSERT_EQ(r.exit_code, 0) << r.output();
  EXPECT_TRUE(fs::exists(dir_ / "soccer" / "places.yaml"));
}

TEST_F(LocateCliTest, APictureShowsTheMapAndTheAnswer) {
  const fs::path picture = dir_ / "where.png";
  const RunResult r = RunPirouette("locate --map " + Map() + " --world " + World("soccer_field") +
                                   " --pose 0.75,0.65,30 --quiet --picture " + picture.string());
  ASSERT_EQ(r.exit_code, 0) << r.output();
  EXPECT_NE(r.stderr_only.find("wrote " + picture.string()), std::string::npos) << r.stderr_only;
  const std::string png = Slurp(picture);
  ASSERT_GT(png.size(), 1000U);
  EXPECT_EQ(png.substr(0, 8), std::string("\x89PNG\r\n\x1a\n", 8));
}

TEST_F(LocateCliTest, BadInputIsRefusedWithExitTwo) {
  const std::string world = " --world " + World("soccer_field");
  const RunResult missing = RunPirouette("locate --map " + (dir_ / "nope" / "map.yaml").string() +
                                         world + " --pose 0.75,0.65,0");
  EXPECT_EQ(missing.exit_code, 2) << missing.output();
  EXPECT_NE(missing.stderr_only.find("nope"), std::string::npos) << missing.stderr_only;

  // Inside the green post at (1.10, 0.35).
  const RunResult wall = RunPirouette("locate --map " + Map() + world + " --pose 1.10,0.35,0");
  EXPECT_EQ(wall.exit_code, 2) << wall.output();
  EXPECT_NE(wall.stderr_only.find("--pose"), std::string::npos) << wall.stderr_only;

  const RunResult outside = RunPirouette("locate --map " + Map() + world + " --pose 9,9,0");
  EXPECT_EQ(outside.exit_code, 2) << outside.output();

  const RunResult neither = RunPirouette("locate --map " + Map() + world);
  EXPECT_EQ(neither.exit_code, 2) << neither.output();

  const RunResult bad_pose = RunPirouette("locate --map " + Map() + world + " --pose 1,2");
  EXPECT_EQ(bad_pose.exit_code, 2) << bad_pose.output();

  const RunResult no_colours =
      RunPirouette("locate --map " + Map() + world + " --pose 0.75,0.65,0 --colours " +
                   (dir_ / "none.png").string());
  EXPECT_EQ(no_colours.exit_code, 2) << no_colours.output();
  EXPECT_NE(no_colours.stderr_only.find("none.png"), std::string::npos) << no_colours.stderr_only;

  const RunResult short_range =
      RunPirouette("locate --map " + Map() + world + " --pose 0.75,0.65,0 --range-factor 0.5");
  EXPECT_EQ(short_range.exit_code, 2) << short_range.output();
  EXPECT_NE(short_range.stderr_only.find("--range-factor"), std::string::npos)
      << short_range.stderr_only;
}

TEST_F(LocateCliTest, HelpTeachesWithAnExample) {
  const RunResult r = RunPirouette("locate --help");
  EXPECT_EQ(r.exit_code, 0);
  EXPECT_NE(r.output().find("example: pirouette"), std::string::npos) << r.output();
}

}  // namespace
}  // namespace pirouette::testing
