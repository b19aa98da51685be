#include "pirouette/run/log_replay.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <utility>
#include <vector>

#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/input_error.h"
#include "pirouette/eval/loop_closure_check.h"
#include "pirouette/eval/map_evaluation.h"
#include "pirouette/eval/pose_error.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/run_log.h"
#include "pirouette/io/world_file.h"
#include "pirouette/run/explore_job.h"
#include "pirouette/run/frame_mapper.h"
#include "pirouette/run/progress_line.h"
#include "pirouette/run/run_watchers.h"
#include "pirouette/sim/drifted_odometry.h"
#include "pirouette/vision/floor_segmenter.h"

namespace pirouette::run {
namespace {

namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

double Round(double v, double unit) { return std::round(v / unit) * unit; }

// The bounds of a log's robot and map, as explore's own options have them.
constexpr double kMinRadiusM = 0.005;
constexpr double kMaxRadiusM = 5.0;
constexpr double kMaxRangeM = 100.0;
// Frames whose map poses lie nearer than this are taken at one place (a
// pirouette's): the path does not move between them.
constexpr double kSamePlaceM = 1e-9;

vision::SegmentationMethod MethodOf(const std::string& name, const std::string& source) {
  if (name.empty()) return vision::SegmentationMethod::kDefault;
  const std::optional<vision::SegmentationMethod> method = vision::ParseSegmentationMethod(name);
  if (!method) {
    throw core::InputError(source, 0, "method", "'" + name + "': the method is default or paper");
  }
  return *method;
}

// The bounds explore's options have, named where the value came from: the
// option when asked for (asked > 0), else the log's field.
void CheckBounds(double value, double lo, double hi, double asked, const char* option,
                 const std::string& log_yaml, const char* field) {
  if (!(value >= lo && value <= hi)) {
    throw core::InputError(asked > 0.0 ? option : log_yaml, 0, asked > 0.0 ? "" : field,
                           fmt::format("{} is out of range: between {} and {}", value, lo, hi));
  }
}

// The robot's radius, the map's cell and range, and the tracking: the
// request's, else the log's, else the explorer's defaults.
MapperSetup SetupOf(const MapLogRequest& request, const io::RunLog& log,
                    const std::string& log_yaml) {
  MapperSetup setup{
      log.camera,       0.0, 0.0, 0.0, kExplorationOccupancy, std::nullopt, std::nullopt,
      request.max_map_m};
  setup.radius_m = request.radius_m > 0.0 ? request.radius_m : log.info.radius_m;
  if (!(setup.radius_m > 0.0)) {
    throw core::InputError(log_yaml, 0, "robot.radius",
                           "the log does not give the robot's radius: give --radius");
  }
  setup.cell_m = request.cell_m > 0.0    ? request.cell_m
                 : log.info.cell_m > 0.0 ? log.info.cell_m
                                         : mapping::DefaultCellSize(setup.radius_m);
  setup.max_range_m = request.max_range_m > 0.0    ? request.max_range_m
                      : log.info.max_range_m > 0.0 ? log.info.max_range_m
                                                   : camera::MaxRange(setup.camera, setup.cell_m);
  CheckBounds(setup.radius_m, kMinRadiusM, kMaxRadiusM, request.radius_m, "--radius", log_yaml,
              "robot.radius");
  CheckBounds(setup.cell_m, mapping::kMinCellM, mapping::kMaxCellM, request.cell_m, "--cell",
              log_yaml, "map.cell");
  CheckBounds(setup.max_range_m, setup.cell_m, kMaxRangeM, request.max_range_m, "--max-range",
              log_yaml, "map.max_range");
  return setup;
}

// How to localize: the request's, else the log's, else the pose graph (the
// default, as explore's).
LocalizeKind LocalizeOf(const MapLogRequest& request, const io::RunLog& log,
                        const std::string& log_yaml) {
  const std::string name = !request.localize.empty()    ? request.localize
                           : !log.info.localize.empty() ? log.info.localize
                                                        : "graph";
  const std::optional<LocalizeKind> localize = ParseLocalizeKind(name);
  if (!localize) {
    throw core::InputError(request.localize.empty() ? log_yaml : "--localize", 0,
                           request.localize.empty() ? "map.localize" : "",
                           "'" + name + "' is not a way to localize (graph | scan | none)");
  }
  return *localize;
}

// Maps the log's frames in order, as the run did, each at `odometry` (one
// pose a row: the log's, or drifted from it); the result's grid, path (the
// frames' map poses, where they moved), frames, times and the graph's outcome.
ExplorationResult Replay(const io::RunLog& log, const std::vector<core::Pose2>& odometry,
                         const MapperSetup& setup, vision::SegmentationMethod method, bool quiet,
                         const RunWatchers& watchers, const std::atomic<bool>* stop_requested) {
  const Clock::time_point start = Clock::now();
  std::unique_ptr<vision::FloorSegmenter> segmenter =
      vision::MakeFloorSegmenter(method, setup.camera);
  FrameMapper mapper(setup, MasksOf(*segmenter), odometry.front());
  ExplorationResult result;
  run::ProgressLine progress(quiet);
  for (std::size_t k = 0; k < log.rows.size(); ++k) {
    const io::RunLogRow& row = log.rows[k];
    if (stop_requested != nullptr && stop_requested->load()) {
      result.status = "interrupted";
      break;
    }
    robot::Frame frame;
    try {
      frame = io::ReadLogFrame(log, row);
      frame.odometry = odometry[k];
    } catch (const core::InputError& e) {
      // A frame missing or cut short ends the log there: what came before
      // is mapped (a log with no readable frame is bad input).
      if (result.frames == 0) throw;
      result.status = "truncated";
      result.reason = fmt::format("{}; mapped the {} frames before it", e.what(), result.frames);
      break;
    }
    if (row.contact) mapper.AddContact(odometry[k]);
    std::optional<FrameMapper::Seen> added;
    try {
      added = mapper.AddFrame(frame);
    } catch (const mapping::MapTooLarge& e) {
      // Refused before it changed the map: the frames before it stand.
      result.status = "truncated";
      result.reason = fmt::format("frame {}: {}; mapped the {} frames before it", row.index,
                                  e.what(), result.frames);
      break;
    }
    const FrameMapper::Seen& seen = *added;
    if (row.blocked_leg_m) mapper.ConfirmBlocking(seen.profile, seen.pose, *row.blocked_leg_m);
    ++result.frames;
    result.frame_poses.push_back(seen.pose);
    if (result.path.empty() ||
        (result.path.back().translation() - seen.pose.translation()).norm() > kSamePlaceM) {
      if (!result.path.empty()) {
        result.path_length_m += (result.path.back().translation() - seen.pose.translation()).norm();
      }
      result.path.push_back(seen.pose);
    }
    const double elapsed = std::chrono::duration<double>(Clock::now() - start).count();
    if (!watchers.all.empty()) {
      static const std::vector<core::Pose2> kNoStops;
      static const std::vector<Eigen::Vector2d> kNoPlan;
      const mapping::OccupancyGrid& grid = mapper.grid();
      ExplorationProgress at;
      at.known_area_m2 = static_cast<double>(grid.KnownCellCount()) * grid.geometry().resolution() *
                         grid.geometry().resolution();
      at.elapsed_s = elapsed;
      const RunSnapshot snapshot{grid,     result.path, kNoStops,
                                 kNoPlan,  seen.pose,   seen.pose * odometry[k].Inverse(),
                                 seen.bgr, seen.mask,   result.frames,
                                 at};
      for (const auto& watcher : watchers.all) watcher->Publish(snapshot);
    }
    progress.Show(elapsed, [&] {
      return fmt::format("map: frame {} of {}, {:.1f} s", result.frames, log.rows.size(), elapsed);
    });
  }
  mapper.Finish();
  if (const auto& graph = mapper.graph()) result.path = graph->graph().poses();
  TakeGraphOutcome(mapper, result);
  result.final_frame_poses = mapper.FramePoses();
  if (result.status.empty() && !log.cut.empty()) {
    result.status = "truncated";
    result.reason = fmt::format("{}; mapped the {} frames before it", log.cut, result.frames);
  }
  if (result.status.empty()) result.status = "complete";
  result.wall_time_s = std::chrono::duration<double>(Clock::now() - start).count();
  result.times.perceive_s = mapper.perceive_s();
  result.times.update_s = mapper.update_s();
  result.colour_map = mapper.MakeColourMap();
  result.grid = mapper.TakeGrid();
  return result;
}

}  // namespace

MapLogReport RunMapLog(const MapLogRequest& request) {
  for (const auto& [value, option] :
       {std::pair{request.radius_m, "--radius"}, std::pair{request.cell_m, "--cell"},
        std::pair{request.max_range_m, "--max-range"},
        std::pair{request.max_map_m, "--max-map-m"}}) {
    if (value < 0.0 || !std::isfinite(value)) {
      throw core::InputError(option, 0, "", "must be a number > 0 (metres)");
    }
  }
  const io::RunLog log = io::ReadRunLog(request.log_dir);
  const std::string log_yaml = (fs::path(request.log_dir) / "log.yaml").string();
  MapperSetup setup = SetupOf(request, log, log_yaml);
  const std::string method_name = request.method.empty() ? log.info.method : request.method;
  const vision::SegmentationMethod method =
      MethodOf(method_name, request.method.empty() ? log_yaml : "--method");
  const LocalizeKind localize = LocalizeOf(request, log, log_yaml);
  if (localize == LocalizeKind::kScan) setup.tracking = ExplorationOptions{}.tracker;
  if (localize == LocalizeKind::kGraph) {
    // The graph as the run kept it: its odometry model from the log.
    setup.graph = ExplorationOptions{}.graph;
    if (log.info.odometry_model) {
      setup.graph->odometry.translation_fraction = (*log.info.odometry_model)[0];
      setup.graph->odometry.rotation_fraction = (*log.info.odometry_model)[1];
    }
  }

  // The world for the evaluation: the one asked for, else the log's when it
  // is still where it was.
  std::optional<sim::World> world;
  std::string world_path = request.world_path;
  if (!world_path.empty()) {
    world = io::LoadWorldFile(world_path);
  } else if (!log.info.world.empty() && fs::exists(log.info.world)) {
    world_path = log.info.world;
    world = io::LoadWorldFile(world_path);
  }

  std::error_code error;
  fs::create_directories(request.out_dir, error);
  if (error) {
    throw core::InputError(request.out_dir, 0, "--out",
                           "cannot create the output folder: " + error.message());
  }

  // The odometry the frames are mapped at: the log's, or with
  // --odometry-noise one drifted from it, the log's then the truth.
  std::vector<core::Pose2> truth;
  for (const io::RunLogRow& row : log.rows) truth.push_back(row.odometry);
  std::vector<core::Pose2> odometry = truth;
  if (request.odometry_noise) {
    core::CheckOdometryNoise(*request.odometry_noise);
    odometry = sim::DriftedOdometry(truth, *request.odometry_noise, request.seed);
    if (setup.graph) {
      ExplorationOptions options;
      options.odometry_noise = request.odometry_noise;
      setup.graph->odometry = GraphOdometryModel(options, &*request.odometry_noise);
    }
  }

  const RunWatchers watchers(request.ros2_publish, request.live_view);
  if (watchers.view != nullptr && request.on_view) request.on_view(watchers.view->endpoint());
  MapLogReport report{
      Replay(log, odometry, setup, method, request.quiet, watchers, request.stop_requested), {}};
  ExplorationResult& result = report.result;
  if (request.odometry_noise) {
    // The frames mapped, against the log's poses.
    truth.resize(std::min(truth.size(), result.final_frame_poses.size()));
    result.pose_error = eval::PoseErrorOf(result.final_frame_poses, truth);
    if (result.graph) {
      result.loop_closure_check = eval::CheckLoopClosures(*result.graph, result.frame_stops, truth);
      result.loop_closure_recall = eval::CheckLoopClosureRecall(
          *result.graph, result.frame_stops, truth, result.loop_reach_m, setup.graph->loop_path_m);
    }
  }
  const mapping::TrinaryMap map = WriteMapOutputs(request.out_dir, result);
  nlohmann::json& run = report.run;
  run["format"] = "pirouette-run/1";
  run["source"] = "log";
  run["log"] = request.log_dir;
  if (world) run["world"] = world_path;
  run["status"] = result.status;
  if (!result.reason.empty()) run["reason"] = result.reason;
  run["method"] = vision::SegmentationMethodName(method);
  run["frames"] = result.frames;
  run["path_length_m"] = Round(result.path_length_m, 1e-4);
  run["wall_time_s"] = Round(result.wall_time_s, 1e-3);
  run["time_per_frame_s"] = Round(result.wall_time_s / result.frames, 1e-5);
  run["stage_time_s"] = {{"perceive", Round(result.times.perceive_s, 1e-4)},
                         {"update", Round(result.times.update_s, 1e-4)}};
  run["localize"] = LocalizeKindName(localize);
  if (nlohmann::json localization = LocalizationJson(localize, result); !localization.is_null()) {
    run["localization"] = std::move(localization);
  }
  if (request.odometry_noise) {
    run["odometry_noise"] = OdometryNoiseJson(*request.odometry_noise);
    run["odometry_noise"]["seed"] = request.seed;
  }
  if (result.pose_error) run["pose_error"] = PoseErrorJson(*result.pose_error);
  if (world) run["eval"] = eval::MapEvaluationToJson(eval::EvaluateMap(map, *world));
  io::WriteFileAtomically((fs::path(request.out_dir) / "run.json").string(), run.dump(2) + "\n");
  watchers.Finish(map, result, request.stop_requested);
  return report;
}

}  // namespace pirouette::run
