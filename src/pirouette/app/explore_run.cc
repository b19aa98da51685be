#include "pirouette/app/explore_run.h"

#include <fmt/format.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>

#include "pirouette/app/atomic_file.h"
#include "pirouette/app/exploration_video.h"
#include "pirouette/app/image_io.h"
#include "pirouette/app/map_evaluation.h"
#include "pirouette/app/map_file.h"
#include "pirouette/app/map_picture.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/sim/world_file.h"

namespace pirouette::app {
namespace {

// The live progress line: rewritten in place on a terminal, a line every few
// seconds otherwise (a log file).
class ProgressLine {
 public:
  explicit ProgressLine(bool quiet) : quiet_(quiet), tty_(isatty(STDERR_FILENO) != 0) {}
  ~ProgressLine() {
    if (!quiet_ && tty_ && shown_) std::fputc('\n', stderr);
  }
  ProgressLine(const ProgressLine&) = delete;
  ProgressLine& operator=(const ProgressLine&) = delete;

  void Show(const ExplorationProgress& p) {
    if (quiet_) return;
    const double interval = tty_ ? 0.1 : 5.0;
    if (shown_ && p.elapsed_s - last_s_ < interval) return;
    last_s_ = p.elapsed_s;
    shown_ = true;
    const std::string line =
        fmt::format("explore: {} moves, {} pirouettes, {:.2f} m² known, {:.1f} s", p.moves,
                    p.pirouettes, p.known_area_m2, p.elapsed_s);
    if (tty_) {
      std::fprintf(stderr, "\r%s\033[K", line.c_str());
    } else {
      std::fprintf(stderr, "%s\n", line.c_str());
    }
    std::fflush(stderr);
  }

 private:
  bool quiet_;
  bool tty_;
  bool shown_ = false;
  double last_s_ = 0.0;
};

constexpr int kMapMarginCells = 5;

double Round(double v, double unit) { return std::round(v / unit) * unit; }

}  // namespace

nlohmann::json RunJson(const ExploreRequest& request, const ExplorationResult& result,
                       const nlohmann::json& eval) {
  nlohmann::json run;
  run["format"] = "pirouette-run/1";
  run["world"] = request.world_path;
  run["seed"] = request.options.seed;
  run["status"] = result.status;
  if (!result.reason.empty()) run["reason"] = result.reason;
  run["planner"] = PlannerKindName(request.options.planner);
  run["method"] = MaskSourceName(request.options.method);
  run["moves"] = result.moves;
  run["turns"] = result.turns;
  run["pirouettes"] = result.pirouettes;
  run["frames"] = result.frames;
  run["path_length_m"] = Round(result.path_length_m, 1e-4);
  run["rotation_deg"] = Round(result.rotation_deg, 0.1);
  run["wall_time_s"] = Round(result.wall_time_s, 1e-3);
  run["stage_time_s"] = {{"render", Round(result.times.render_s, 1e-4)},
                         {"perceive", Round(result.times.perceive_s, 1e-4)},
                         {"update", Round(result.times.update_s, 1e-4)},
                         {"plan", Round(result.times.plan_s, 1e-4)}};
  const auto pose_json = [](const core::Pose2& p) {
    return nlohmann::json::array(
        {Round(p.x(), 1e-4), Round(p.y(), 1e-4), Round(core::RadToDeg(p.heading()), 0.01)});
  };
  if (!result.path.empty()) run["final_pose"] = pose_json(result.path.back());
  run["final_true_pose"] = pose_json(result.final_true_pose);
  run["blocked_looks"] = result.blocked_looks;
  run["backups"] = result.backups;
  run["eval"] = eval;
  return run;
}

ExploreReport RunExplore(const ExploreRequest& request) {
  const sim::World world = sim::LoadWorldFile(request.world_path);
  CheckExplorationOptions(request.options);
  std::error_code error;
  std::filesystem::create_directories(request.out_dir, error);
  if (error) {
    throw core::InputError(request.out_dir, 0, "--out",
                           "cannot create the output folder: " + error.message());
  }
  const std::filesystem::path out(request.out_dir);
  std::optional<ExplorationVideo> video;
  if (request.video) video.emplace((out / "explore.mp4").string());

  ProgressLine progress(request.quiet);
  ExplorationObserver observer;
  observer.on_progress = [&progress](const ExplorationProgress& p) { progress.Show(p); };
  if (video) observer.on_frame = [&video](const FrameEvent& event) { video->AddFrame(event); };

  ExploreReport report{Explore(world, request.options, observer), {}};
  const ExplorationResult& result = report.result;

  // The map written is the part the robot saw, with a margin.
  const mapping::OccupancyGrid seen = result.grid.CroppedToKnown(kMapMarginCells);
  const mapping::TrinaryMap map = seen.ToTrinary();
  WriteRosMap(map, (out / "map.yaml").string());
  WritePng((out / "map.png").string(), DrawMapPicture(seen, result.path, result.stops));
  report.run = RunJson(request, result, MapEvaluationToJson(EvaluateMap(map, world)));
  WriteFileAtomically((out / "run.json").string(), report.run.dump(2) + "\n");
  if (video) video->Finish();
  return report;
}

}  // namespace pirouette::app
