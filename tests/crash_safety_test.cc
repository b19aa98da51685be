// Crash-safe runs (issue 24): an explore killed with SIGKILL at random
// moments leaves its map up to its last stop, whole, and a run log that
// `map --log` maps up to where it was cut; a log cut at any byte of
// frames.csv or of a frame maps every whole frame before the cut.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <random>
#include <string>
#include <thread>
#include <vector>

#include "pirouette/io/image_io.h"
#include "pirouette/io/map_file.h"
#include "pirouette/io/run_log.h"
#include "pirouette/run/explore_job.h"
#include "pirouette/run/log_replay.h"
#include "pirouette/testing/temp_dir.h"

namespace pirouette::run {
namespace crash_safety_test {

namespace fs = std::filesystem;

const std::string kWorld = std::string(PIROUETTE_WORLDS_DIR) + "/maze.yaml";

// Starts `pirouette explore` on the maze into `out`, recording to `log`,
// kills it with SIGKILL `after` its start (or, with `after_first_checkpoint`,
// `after` the first checkpoint appeared: a moment in the middle of the run
// whatever the machine's speed), and waits for it. Returns whether it was
// still running when killed (false: it had ended by itself).
bool ExploreKilledAfter(const std::string& out, const std::string& log,
                        std::chrono::milliseconds after, bool after_first_checkpoint) {
  const pid_t pid = ::fork();
  if (pid == 0) {
    const int null = ::open("/dev/null", O_WRONLY);
    ::dup2(null, STDERR_FILENO);
    ::execl(PIROUETTE_BINARY, PIROUETTE_BINARY, "explore", "--world", kWorld.c_str(), "--out",
            out.c_str(), "--record", log.c_str(), "--quiet", static_cast<char*>(nullptr));
    ::_exit(127);
  }
  int status = 0;
  const auto ended = [&] { return ::waitpid(pid, &status, WNOHANG) == pid; };
  const auto poll = std::chrono::milliseconds(2);
  if (after_first_checkpoint) {
    while (!std::filesystem::exists(std::filesystem::path(out) / "run.json")) {
      if (ended()) return false;
      std::this_thread::sleep_for(poll);
    }
  }
  const auto deadline = std::chrono::steady_clock::now() + after;
  while (std::chrono::steady_clock::now() < deadline) {
    if (ended()) return false;
    std::this_thread::sleep_for(poll);
  }
  ::kill(pid, SIGKILL);
  ::waitpid(pid, &status, 0);
  return WIFSIGNALED(status);
}

std::string ReadFile(const fs::path& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

// How many rows of frames.csv are whole (end in a line end), header excluded.
int WholeRows(const std::string& csv) {
  int lines = 0;
  for (const char c : csv) lines += c == '\n' ? 1 : 0;
  return std::max(0, lines - 1);
}

// Kills runs at seeded random moments: half of them at any moment from the
// start, half in the middle of the run (after its first checkpoint); after
// each, what the output folder holds is whole, and the log maps.
TEST(CrashSafety, ARunKilledAtAnyMomentKeepsItsMapAndItsLog) {
  std::mt19937 random(24);
  std::uniform_int_distribution<int> after_ms(0, 2500);
  constexpr int kRuns = 6;
  int killed = 0;
  int checkpoints = 0;
  int logs_mapped = 0;
  for (int i = 0; i < kRuns; ++i) {
    const testing::TempDir dir("crash_safety");
    const std::string out = dir / "out";
    const std::string log = dir / "log";
    const auto after = std::chrono::milliseconds(after_ms(random));
    const bool mid_run = i % 2 == 1;
    SCOPED_TRACE("run " + std::to_string(i) + " killed " + std::to_string(after.count()) +
                 " ms after " + (mid_run ? "its first checkpoint" : "its start"));
    killed += ExploreKilledAfter(out, log, after, mid_run) ? 1 : 0;

    // The output folder: nothing, or a whole map and a run.json that parses.
    int checkpoint_frames = 0;
    if (fs::exists(fs::path(out) / "run.json")) {
      const nlohmann::json run = nlohmann::json::parse(ReadFile(fs::path(out) / "run.json"));
      checkpoint_frames = run.at("frames").get<int>();
      ASSERT_TRUE(fs::exists(fs::path(out) / "map.yaml"));
      const mapping::TrinaryMap map = io::ReadRosMap((fs::path(out) / "map.yaml").string());
      EXPECT_GT(map.geometry.CellCount(), 0U);
      ++checkpoints;
    }

    // The log: every whole row maps; its frames cover the checkpoint's but
    // the last (a row is written when the next frame comes).
    const fs::path csv = fs::path(log) / "frames.csv";
    if (!fs::exists(csv) || WholeRows(ReadFile(csv)) == 0) continue;
    const int rows = WholeRows(ReadFile(csv));
    MapLogRequest request;
    request.log_dir = log;
    request.out_dir = dir / "mapped";
    request.quiet = true;
    const MapLogReport mapped = RunMapLog(request);
    EXPECT_TRUE(mapped.result.status == "complete" || mapped.result.status == "truncated")
        << mapped.result.status;
    EXPECT_EQ(mapped.result.frames, rows);
    EXPECT_GE(mapped.result.frames, checkpoint_frames - 1);
    ++logs_mapped;
  }
  // The runs killed mid-run had checkpointed and recorded before.
  EXPECT_GE(checkpoints, kRuns / 2);
  EXPECT_GE(logs_mapped, kRuns / 2);
  std::printf("crash safety: %d runs, %d killed, %d checkpoints found whole, %d logs mapped\n",
              kRuns, killed, checkpoints, logs_mapped);
}

class CutLogTest : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new testing::TempDir("cut_log");
    ExploreRequest explore;
    explore.world_path = kWorld;
    explore.out_dir = *dir_ / "explore";
    explore.record_dir = *dir_ / "log";
    explore.quiet = true;
    explore.options.max_steps = 12;  // a short log is enough
    RunExplore(explore);
  }
  static void TearDownTestSuite() {
    delete dir_;
    dir_ = nullptr;
  }

  // A copy of the log whose frames.csv is `csv` and whose frame `cut_frame`
  // (if >= 0) is its first `png_bytes` bytes; the other frames are links.
  static std::string CopyOfLog(const std::string& name, const std::string& csv, int cut_frame = -1,
                               std::size_t png_bytes = 0) {
    const fs::path from = fs::path(*dir_ / "log");
    const fs::path to = fs::path(*dir_ / name);
    fs::create_directories(to / "frames");
    fs::copy_file(from / "log.yaml", to / "log.yaml");
    fs::copy_file(from / "camera.yaml", to / "camera.yaml");
    std::ofstream(to / "frames.csv", std::ios::binary) << csv;
    for (const auto& entry : fs::directory_iterator(from / "frames")) {
      const fs::path target = to / "frames" / entry.path().filename();
      if (entry.path().filename() == FrameName(cut_frame)) {
        std::ofstream(target, std::ios::binary) << ReadFile(entry.path()).substr(0, png_bytes);
      } else {
        fs::create_symlink(entry.path(), target);
      }
    }
    return to.string();
  }
  static std::string FrameName(int index) {
    char name[32];
    std::snprintf(name, sizeof name, "%06d.png", index);
    return name;
  }
  static MapLogReport Map(const std::string& log) {
    MapLogRequest request;
    request.log_dir = log;
    request.out_dir = log + "-out";
    request.quiet = true;
    return RunMapLog(request);
  }

  static testing::TempDir* dir_;
};
testing::TempDir* CutLogTest::dir_ = nullptr;

// frames.csv cut at seeded random bytes: the whole rows before the cut map,
// the status says the log was cut and where.
TEST_F(CutLogTest, FramesCsvCutAtAnyByteMapsTheWholeRows) {
  const std::string csv = ReadFile(fs::path(*dir_ / "log") / "frames.csv");
  const std::size_t header = csv.find('\n') + 1;
  std::mt19937 random(7);
  std::uniform_int_distribution<std::size_t> byte(header + 1, csv.size() - 1);
  for (int i = 0; i < 8; ++i) {
    const std::size_t cut = byte(random);
    SCOPED_TRACE("cut at byte " + std::to_string(cut) + " of " + std::to_string(csv.size()));
    const std::string part = csv.substr(0, cut);
    const int rows = WholeRows(part);
    if (rows == 0) continue;
    const MapLogReport mapped = Map(CopyOfLog("csv-cut-" + std::to_string(i), part));
    EXPECT_EQ(mapped.result.frames, rows);
    if (part.back() == '\n') {
      EXPECT_EQ(mapped.result.status, "complete");
    } else {
      EXPECT_EQ(mapped.result.status, "truncated");
      EXPECT_NE(mapped.result.reason.find("line " + std::to_string(rows + 2)), std::string::npos)
          << mapped.result.reason;
      EXPECT_EQ(mapped.run.at("status"), "truncated");
    }
  }
}

// A frame cut at a seeded random byte ends the log there: the frames before
// it map, the reason names the frame's file.
TEST_F(CutLogTest, AFrameCutAtAnyByteEndsTheLogThere) {
  const std::string csv = ReadFile(fs::path(*dir_ / "log") / "frames.csv");
  const int rows = WholeRows(csv);
  ASSERT_GT(rows, 4);
  std::mt19937 random(11);
  std::uniform_int_distribution<int> frame(1, rows - 1);
  for (int i = 0; i < 4; ++i) {
    const int k = frame(random);
    const std::string png = ReadFile(fs::path(*dir_ / "log") / "frames" / FrameName(k));
    std::uniform_int_distribution<std::size_t> byte(0, png.size() - 1);
    const std::size_t cut = byte(random);
    SCOPED_TRACE("frame " + std::to_string(k) + " cut at byte " + std::to_string(cut));
    const MapLogReport mapped = Map(CopyOfLog("png-cut-" + std::to_string(i), csv, k, cut));
    EXPECT_EQ(mapped.result.status, "truncated");
    EXPECT_EQ(mapped.result.frames, k);
    EXPECT_NE(mapped.result.reason.find(FrameName(k)), std::string::npos) << mapped.result.reason;
  }
}

// A map that would grow past --max-map-m ends the run (status stuck) with
// the map so far, as a robot whose odometry jumped would.
TEST(MapLimit, AMapThatWouldGrowPastTheLimitEndsTheRunWithItsMap) {
  const testing::TempDir dir("map_limit");
  ExploreRequest explore;
  explore.world_path = kWorld;
  explore.out_dir = dir / "out";
  explore.quiet = true;
  explore.options.max_map_m = 1.0;
  const ExploreReport report = RunExplore(explore);
  EXPECT_EQ(report.result.status, "stuck");
  EXPECT_NE(report.result.reason.find("--max-map-m"), std::string::npos) << report.result.reason;
  EXPECT_GT(report.result.frames, 0);
  const mapping::TrinaryMap map = io::ReadRosMap(dir / "out/map.yaml");
  EXPECT_LE(map.geometry.width() * map.geometry.resolution(), 1.0 + 0.2);
  EXPECT_EQ(nlohmann::json::parse(ReadFile(fs::path(dir / "out/run.json")))["status"], "stuck");
}

}  // namespace crash_safety_test
}  // namespace pirouette::run
