// `pirouette capture` as a user meets it: a short video made from frames the
// simulator renders, the overlays and profiles it writes, exit code 2 with a
// message naming the source for bad input, and the real robot video of
// ../shared/realdata/visar when it is there.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <memory>
#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>
#include <opencv2/imgcodecs.hpp>
#include <opencv2/videoio.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace {

namespace fs = std::filesystem;

using pirouette::testing::RunPirouette;
using pirouette::testing::TempDir;
using Result = pirouette::testing::RunResult;

std::string World(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name;
}

std::vector<nlohmann::json> ReadJsonLines(const fs::path& path) {
  std::ifstream in(path);
  std::vector<nlohmann::json> lines;
  for (std::string line; std::getline(in, line);) {
    if (!line.empty()) lines.push_back(nlohmann::json::parse(line));
  }
  return lines;
}

std::string Slurp(const std::string& path) {
  std::ifstream in(path);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

std::vector<std::string> PngNames(const fs::path& dir) {
  std::vector<std::string> names;
  for (const fs::directory_entry& entry : fs::directory_iterator(dir)) {
    if (entry.path().extension() == ".png") names.push_back(entry.path().filename().string());
  }
  std::sort(names.begin(), names.end());
  return names;
}

class CaptureCliTest : public ::testing::Test {
 protected:
  static constexpr int kFrames = 6;

  // The video all tests share: the robot turning on the spot in the soccer
  // field, rendered through yujin.yaml (320×240), as MJPG in an AVI.
  static void SetUpTestSuite() {
    shared_ = std::make_unique<TempDir>("pirouette_capture_cli_test");
    cv::VideoWriter writer(*shared_ / "turn.avi", cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 5.0,
                           cv::Size(320, 240));
    ASSERT_TRUE(writer.isOpened());
    for (int i = 0; i < kFrames; ++i) {
      const std::string frame = *shared_ / "frame.png";
      const Result r =
          RunPirouette("render --world " + World("soccer_field.yaml") + " --pose 0.6,0.6," +
                       std::to_string(30 * i) + " --out " + frame);
      ASSERT_EQ(r.exit_code, 0) << r.output();
      const cv::Mat image = cv::imread(frame);
      ASSERT_EQ(image.size(), cv::Size(320, 240));
      writer.write(image);
    }
    writer.release();
  }
  static void TearDownTestSuite() { shared_.reset(); }

  static std::string Video() { return *shared_ / "turn.avi"; }
  std::string Path(const std::string& name) const { return dir_ / name; }

  static std::unique_ptr<TempDir> shared_;  // the video, for the whole suite
  TempDir dir_{"pirouette_capture_cli_test"};
};

std::unique_ptr<TempDir> CaptureCliTest::shared_;

TEST_F(CaptureCliTest, WritesAnOverlayAndAProfileLineForEveryFrame) {
  const fs::path out = dir_.path() / "capture";
  const Result r = RunPirouette("capture --source " + Video() + " --camera " + World("yujin.yaml") +
                                " --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output();
  const nlohmann::json summary = nlohmann::json::parse(r.stdout_only);
  EXPECT_EQ(summary.at("format"), "pirouette-capture/1");
  EXPECT_EQ(summary.at("frames"), kFrames);
  EXPECT_EQ(summary.at("frames_read"), kFrames);
  EXPECT_EQ(summary.at("stopped"), "end");
  EXPECT_EQ(summary.at("method"), "default");
  EXPECT_EQ(summary.at("frame_size"), nlohmann::json::array({320, 240}));
  EXPECT_GT(summary.at("mean_floor_fraction").get<double>(), 0.2);
  EXPECT_GT(summary.at("max_range_m").get<double>(), 0.0);

  std::vector<std::string> expected;
  expected.reserve(kFrames);
  for (int i = 0; i < kFrames; ++i) expected.push_back("00000" + std::to_string(i) + ".png");
  EXPECT_EQ(PngNames(out), expected);
  const cv::Mat overlay = cv::imread((out / "000000.png").string());
  EXPECT_EQ(overlay.cols, 320);
  EXPECT_GT(overlay.rows, 240);  // the range strip and caption below the frame

  const std::vector<nlohmann::json> lines = ReadJsonLines(out / "profiles.jsonl");
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(kFrames));
  const double max_range = summary.at("max_range_m").get<double>();
  int frames_with_hits = 0;
  for (int i = 0; i < kFrames; ++i) {
    SCOPED_TRACE(i);
    const nlohmann::json& line = lines[static_cast<std::size_t>(i)];
    EXPECT_EQ(line.at("frame"), i);
    EXPECT_EQ(line.at("image"), expected[static_cast<std::size_t>(i)]);
    // One reading a column.
    EXPECT_EQ(line.at("hit").get<int>() + line.at("clear").get<int>() + line.at("blind").get<int>(),
              320);
    // The robot stands on open floor: the bottom centre is floor, and no
    // column is blind.
    EXPECT_GT(line.at("reference_fraction").get<double>(), 0.9);
    EXPECT_EQ(line.at("blind"), 0);
    if (line.at("hit").get<int>() + line.at("feet").get<int>() > 0) {
      ++frames_with_hits;
      const double nearest = line.at("nearest_hit_m").get<double>();
      EXPECT_GT(nearest, 0.05);  // beyond the robot's own radius (4 cm)
      EXPECT_LE(nearest, max_range);
    } else {
      EXPECT_TRUE(line.at("nearest_hit_m").is_null());
    }
  }
  // Turning on the spot among the field's blocks, most views end the floor
  // within range somewhere (the 30° and 60° views see open floor only).
  EXPECT_GE(frames_with_hits, kFrames / 2);
}

TEST_F(CaptureCliTest, EveryAndFramesPickTheFramesUsed) {
  const fs::path out = dir_.path() / "capture";
  const Result r = RunPirouette("capture --source " + Video() + " --method paper --every 3 " +
                                "--frames 2 --quiet --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output();
  EXPECT_TRUE(r.stderr_only.empty()) << r.stderr_only;
  const nlohmann::json summary = nlohmann::json::parse(r.stdout_only);
  EXPECT_EQ(summary.at("frames"), 2);
  EXPECT_EQ(summary.at("stopped"), "frames");
  EXPECT_EQ(summary.at("method"), "paper");
  EXPECT_TRUE(summary.at("camera").is_null());
  EXPECT_FALSE(summary.contains("max_range_m"));
  EXPECT_EQ(PngNames(out), (std::vector<std::string>{"000000.png", "000003.png"}));
  const std::vector<nlohmann::json> lines = ReadJsonLines(out / "profiles.jsonl");
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_FALSE(lines[0].contains("hit"));  // no camera, no profile
  // Without a camera, a 320-wide frame is drawn as is, with a caption below.
  const cv::Mat overlay = cv::imread((out / "000003.png").string());
  EXPECT_EQ(overlay.cols, 320);
}

// Ctrl-C (SIGINT, sent once the first frame is out) stops after the current frame: exit 0,
// and every overlay written is listed in profiles.jsonl and the summary.
TEST_F(CaptureCliTest, InterruptStopsCleanlyKeepingWhatWasWritten) {
  constexpr int kLongFrames = 2400;
  const std::string video = Path("long.avi");
  {
    cv::VideoWriter writer(video, cv::VideoWriter::fourcc('M', 'J', 'P', 'G'), 25.0,
                           cv::Size(320, 240));
    ASSERT_TRUE(writer.isOpened());
    cv::VideoCapture reader(Video());
    std::vector<cv::Mat> frames;
    for (cv::Mat frame; reader.read(frame);) frames.push_back(frame.clone());
    ASSERT_FALSE(frames.empty());
    // Long enough that the signal comes well before the end.
    for (int i = 0; i < kLongFrames; ++i) {
      writer.write(frames[static_cast<std::size_t>(i) % frames.size()]);
    }
  }
  const fs::path out = dir_.path() / "capture";
  // SIGINT once the first overlay is written (so that the handler is surely
  // installed, however loaded the machine), at most 120 s after the start.
  const std::string run = std::string(PIROUETTE_BINARY) + " capture --source " + video +
                          " --camera " + World("yujin.yaml") + " --quiet --out " + out.string() +
                          " >" + Path("summary.json") + " 2>" + Path("err.txt");
  const std::string first = (out / "000000.png").string();
  const std::string script = run + " & pid=$!; for i in $(seq 1200); do [ -e '" + first +
                             "' ] && break; sleep 0.1; done; kill -INT $pid; wait $pid";
  const int status = std::system(script.c_str());
  ASSERT_TRUE(WIFEXITED(status));
  ASSERT_EQ(WEXITSTATUS(status), 0) << Slurp(Path("err.txt"));
  const nlohmann::json summary = nlohmann::json::parse(Slurp(Path("summary.json")));
  EXPECT_EQ(summary.at("stopped"), "interrupted");
  const int frames = summary.at("frames").get<int>();
  EXPECT_LT(frames, kLongFrames);
  EXPECT_EQ(ReadJsonLines(out / "profiles.jsonl").size(), static_cast<std::size_t>(frames));
  EXPECT_EQ(PngNames(out).size(), static_cast<std::size_t>(frames));
  for (const fs::directory_entry& entry : fs::directory_iterator(out)) {
    const std::string name = entry.path().filename().string();
    EXPECT_TRUE(entry.path().extension() == ".png" || name == "profiles.jsonl") << name;
  }
}

TEST_F(CaptureCliTest, MissingFileIsBadInput) {
  const std::string missing = Path("no_such_video.avi");
  const Result r = RunPirouette("capture --source " + missing + " --out " + Path("out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find(missing), std::string::npos) << r.stderr_only;
  EXPECT_NE(r.stderr_only.find("no such file"), std::string::npos) << r.stderr_only;
  EXPECT_FALSE(fs::exists(Path("out")));
}

TEST_F(CaptureCliTest, FileThatIsNotAVideoIsBadInput) {
  const std::string junk = Path("junk.avi");
  std::ofstream(junk) << "this is not a video\n";
  const Result r = RunPirouette("capture --source " + junk + " --out " + Path("out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find(junk), std::string::npos) << r.stderr_only;
}

TEST_F(CaptureCliTest, DeviceThatIsNotThereIsBadInput) {
  const Result r = RunPirouette("capture --source 97 --out " + Path("out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find("97"), std::string::npos) << r.stderr_only;
}

TEST_F(CaptureCliTest, FramesOfAnotherSizeThanTheCameraAreRefused) {
  const Result r = RunPirouette("capture --source " + Video() + " --camera " +
                                World("webcam640.yaml") + " --out " + Path("out"));
  EXPECT_EQ(r.exit_code, 2);
  EXPECT_NE(r.stderr_only.find("320×240"), std::string::npos) << r.stderr_only;
  EXPECT_NE(r.stderr_only.find("640×480"), std::string::npos) << r.stderr_only;
  EXPECT_NE(r.stderr_only.find("webcam640.yaml"), std::string::npos) << r.stderr_only;
  EXPECT_FALSE(fs::exists(Path("out")));
}

TEST_F(CaptureCliTest, BadOptionsAreBadUsage) {
  EXPECT_EQ(RunPirouette("capture --source " + Video() + " --method magic").exit_code, 2);
  EXPECT_EQ(RunPirouette("capture --source " + Video() + " --every 0 --out " + Path("o")).exit_code,
            2);
  EXPECT_EQ(RunPirouette("capture").exit_code, 2);  // --source is required
}

// The real robot video (160×120, 25 fps, about 100 s among static obstacles),
// every 10th frame. No camera file fits it (the shipped ones are 320×240 and
// 640×480), so it is captured without a profile; the robot drives on floor,
// so the bottom centre of most frames must be found to be floor.
TEST(CaptureRealVideoTest, FindsTheFloorInFrontOfTheRobot) {
  const fs::path video = fs::path(PIROUETTE_SHARED_DIR) / "realdata/visar/eng_stat_obst.avi";
  if (!fs::exists(video)) GTEST_SKIP() << video << " is absent";
  cv::VideoCapture reader(video.string());
  ASSERT_TRUE(reader.isOpened());
  int frames = 0;
  for (cv::Mat frame; reader.grab();) ++frames;
  ASSERT_GT(frames, 0);
  const int used = (frames + 9) / 10;

  const TempDir dir("pirouette_capture_real");
  const fs::path out = dir.path() / "capture";
  const Result r = RunPirouette("capture --source " + video.string() +
                                " --every 10 --quiet --out " + out.string());
  ASSERT_EQ(r.exit_code, 0) << r.output();
  const nlohmann::json summary = nlohmann::json::parse(r.stdout_only);
  EXPECT_EQ(summary.at("frames"), used);
  EXPECT_EQ(summary.at("frames_read"), frames);
  EXPECT_EQ(summary.at("frame_size"), nlohmann::json::array({160, 120}));
  EXPECT_EQ(PngNames(out).size(), static_cast<std::size_t>(used));
  const std::vector<nlohmann::json> lines = ReadJsonLines(out / "profiles.jsonl");
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(used));
  int floor_in_front = 0;
  int floor_ends = 0;
  for (const nlohmann::json& line : lines) {
    if (line.at("reference_fraction").get<double>() > 0.8) ++floor_in_front;
    if (line.at("floor_fraction").get<double>() < 0.95) ++floor_ends;
  }
  EXPECT_GT(floor_in_front, used * 9 / 10);
  // Not everything is floor: walls and obstacles are found in most frames
  // (close up, the video's white walls look like its white floor).
  EXPECT_GT(floor_ends, used * 9 / 10);
  // A 160-wide frame is drawn twice as large.
  EXPECT_EQ(cv::imread((out / "000000.png").string()).cols, 320);
}

}  // namespace
