// `pirouette places` as a user runs it: the table it writes and loads, the
// report, and its answers to bad input.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
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

TEST(PlacesCliTest, BuildsSavesAndLoadsTheTableAndWritesTheReport) {
  const TempDir temp("pirouette_places_cli");
  const fs::path& dir = temp.path();
  const std::string common = "places --world " + World("soccer_field") +
                             " --queries 3 --spacing 0.3 --seed 2 --quiet --table " +
                             (dir / "table.yaml").string();
  const RunResult built = RunPirouette(common + " --out " + (dir / "report.json").string());
  ASSERT_EQ(built.exit_code, 0) << built.output();
  EXPECT_TRUE(fs::exists(dir / "table.yaml"));
  EXPECT_NE(built.stdout_only.find("fourier"), std::string::npos) << built.stdout_only;
  const nlohmann::json report = nlohmann::json::parse(Slurp(dir / "report.json"));
  EXPECT_EQ(report["format"], "pirouette-places-report/1");
  EXPECT_EQ(report["queries"], 3);
  EXPECT_FALSE(report["table"]["loaded"].get<bool>());
  const int places = report["table"]["places"].get<int>();
  EXPECT_GT(places, 5);
  for (const char* kind : {"dct", "hu", "fourier", "colour"}) {
    ASSERT_TRUE(report["signatures"].contains(kind)) << kind;
    const double rate = report["signatures"][kind]["place_rate"].get<double>();
    EXPECT_GE(rate, 0.0);
    EXPECT_LE(rate, 1.0);
  }
  EXPECT_TRUE(report["signatures"]["dct"]["heading_rate"].is_null());
  EXPECT_FALSE(report["signatures"]["colour"]["heading_rate"].is_null());

  // The second run loads the table; a third gives the same answers.
  const RunResult loaded = RunPirouette(common + " --out " + (dir / "again.json").string());
  ASSERT_EQ(loaded.exit_code, 0) << loaded.output();
  const nlohmann::json again = nlohmann::json::parse(Slurp(dir / "again.json"));
  EXPECT_TRUE(again["table"]["loaded"].get<bool>());
  EXPECT_EQ(again["table"]["places"], places);
  const RunResult third = RunPirouette(common + " --out " + (dir / "third.json").string());
  ASSERT_EQ(third.exit_code, 0) << third.output();
  const nlohmann::json same = nlohmann::json::parse(Slurp(dir / "third.json"));
  EXPECT_EQ(same["signatures"], again["signatures"]);
  EXPECT_EQ(same["query_log"], again["query_log"]);
}

TEST(PlacesCliTest, BadInputIsRefusedWithExitTwo) {
  const TempDir temp("pirouette_places_cli");
  EXPECT_EQ(RunPirouette("places --world /nonexistent.yaml").exit_code, 2);
  const RunResult queries =
      RunPirouette("places --world " + World("soccer_field") + " --queries 0");
  EXPECT_EQ(queries.exit_code, 2);
  EXPECT_NE(queries.stderr_only.find("--queries"), std::string::npos) << queries.stderr_only;
  const std::string broken = temp.Write(
      "broken.yaml",
      "format: pirouette-places/1\nworld: soccer_field\nmax_range_m: nope\nplaces: []\n");
  const RunResult table =
      RunPirouette("places --world " + World("soccer_field") + " --queries 1 --table " + broken);
  EXPECT_EQ(table.exit_code, 2);
  EXPECT_NE(table.stderr_only.find("max_range_m"), std::string::npos) << table.stderr_only;
}

}  // namespace
}  // namespace pirouette::testing
