// `pirouette explore-eval --generate` as a user runs it: generated worlds
// explored and named as their files name them, the table on standard output
// and progress on standard error; a bad KIND:SEEDS value, or no worlds at
// all, refused with exit code 2 and a message naming the option.

#include <gtest/gtest.h>

#include <string>

#include "run_pirouette.h"

namespace pirouette::testing {
namespace {

TEST(ExploreEvalCliTest, ExploresAGeneratedWorldByItsName) {
  const RunResult r =
      RunPirouette("explore-eval --generate clutter:1 --seeds 3 --planner dt --max-steps 1");
  ASSERT_EQ(r.exit_code, 0) << r.output();
  EXPECT_EQ(r.stdout_only.rfind("| world | planner | complete | coverage (worst) |", 0), 0u)
      << r.stdout_only;
  EXPECT_NE(r.stdout_only.find("\n| clutter-1 | dt | "), std::string::npos) << r.stdout_only;
  EXPECT_EQ(r.stdout_only.find("| frontier |"), std::string::npos)
      << "one planner asked for, one row: " << r.stdout_only;
  EXPECT_NE(r.stdout_only.find(" (step-limit 1) | "), std::string::npos)
      << "one straight move, then the step limit: " << r.stdout_only;
  EXPECT_NE(r.stderr_only.find("explore-eval: clutter-1 dt seed 3: "), std::string::npos)
      << r.stderr_only;
}

TEST(ExploreEvalCliTest, ABadGenerateValueExitsTwoNamingTheOptionAndTheValue) {
  for (const std::string value : {"house:1", "maze", "maze:5-3", "maze:1,x", "rooms:"}) {
    const RunResult r = RunPirouette("explore-eval --generate " + value + " --max-steps 1");
    EXPECT_EQ(r.exit_code, 2) << value << ": " << r.output();
    EXPECT_NE(r.stderr_only.find("--generate: '" + value + "'"), std::string::npos)
        << value << ": " << r.stderr_only;
    EXPECT_TRUE(r.stdout_only.empty()) << value << ": " << r.stdout_only;
  }
  // A good value beside a bad one: refused before anything is explored.
  const RunResult r = RunPirouette("explore-eval --generate clutter:1 --generate clutter:2-1");
  EXPECT_EQ(r.exit_code, 2) << r.output();
  EXPECT_EQ(r.stderr_only.find("explore-eval: clutter-1"), std::string::npos) << r.stderr_only;
}

TEST(ExploreEvalCliTest, NoWorldsExitsTwo) {
  const RunResult r = RunPirouette("explore-eval --seeds 1");
  EXPECT_EQ(r.exit_code, 2) << r.output();
  EXPECT_NE(r.stderr_only.find("--world FILE or --generate KIND:SEEDS"), std::string::npos)
      << r.stderr_only;
}

TEST(ExploreEvalCliTest, HelpTellsTheWorldSeedsFromTheRunSeeds) {
  const RunResult r = RunPirouette("explore-eval --help");
  EXPECT_EQ(r.exit_code, 0);
  for (const char* words : {"--generate", "KIND:SEEDS", "maze:1-10", "rooms:1,4,7", "--world",
                            "explore-eval --generate", "simulator's noise", "maze-7"}) {
    EXPECT_NE(r.output().find(words), std::string::npos) << words;
  }
}

}  // namespace
}  // namespace pirouette::testing
