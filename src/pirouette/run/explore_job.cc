#include "pirouette/run/explore_job.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/draw/exploration_video.h"
#include "pirouette/draw/map_picture.h"
#include "pirouette/eval/map_evaluation.h"
#include "pirouette/io/atomic_file.h"
#include "pirouette/io/camera_file.h"
#include "pirouette/io/colour_map_file.h"
#include "pirouette/io/graph_file.h"
#include "pirouette/io/image_io.h"
#include "pirouette/io/map_file.h"
#include "pirouette/io/run_log.h"
#include "pirouette/io/world_file.h"
#include "pirouette/robot/remote_robot.h"
#include "pirouette/robot/robot_watchdog.h"
#include "pirouette/robot/ros2/ros2_robot.h"
#include "pirouette/run/checkpoint_writer.h"
#include "pirouette/run/progress_line.h"
#include "pirouette/run/ros2_camera.h"
#include "pirouette/run/run_watchers.h"
#include "pirouette/run/simulated_exploration.h"
#include "pirouette/sim/simulated_robot.h"
#include "pirouette/vision/floor_segmenter.h"

namespace pirouette::run {
namespace {

// The longest wait for a robot's reply one may ask for (--robot-timeout).
constexpr double kMaxRobotTimeoutS = 3600.0;
// A whole request over TCP (a frame's bytes too) may take this many times
// --robot-timeout: the first bounds each wait, this the request.
constexpr int kRequestTimeoutFactor = 2;

double Round(double v, double unit) { return std::round(v / unit) * unit; }

}  // namespace

nlohmann::json RunJsonBase(const ExploreRequest& request) {
  nlohmann::json run;
  run["format"] = "pirouette-run/1";
  if (!request.world_path.empty()) run["world"] = request.world_path;
  run["seed"] = request.options.seed;
  run["planner"] = PlannerKindName(request.options.planner);
  run["method"] = vision::MaskSourceName(request.options.method);
  run["localize"] = LocalizeKindName(request.options.localize);
  if (!request.robot_url.empty()) run["robot"] = request.robot_url;
  return run;
}

nlohmann::json LocalizationJson(LocalizeKind localize, const ExplorationResult& result) {
  if (localize == LocalizeKind::kGraph && result.graph) {
    double mean = 0.0;
    double most = 0.0;
    for (const double t : result.per_stop_s) {
      mean += t;
      most = std::max(most, t);
    }
    if (!result.per_stop_s.empty()) mean /= static_cast<double>(result.per_stop_s.size());
    nlohmann::json loops = {{"accepted", result.loop_closures_accepted},
                            {"rejected", result.loop_closures_rejected}};
    if (const auto& check = result.loop_closure_check) {
      // In the simulator: how many accepted closures were within 2 cm and
      // 1° of the truth, and the worst one's error.
      loops["correct"] = check->correct;
      loops["worst_m"] = Round(check->worst_m, 1e-4);
      loops["worst_deg"] = Round(check->worst_deg, 1e-2);
    }
    if (const auto& recall = result.loop_closure_recall) {
      // In the simulator: the stops that had a loop to close by the graph's
      // own rule at the true poses, and how many it closed.
      loops["opportunities"] = recall->opportunities;
      loops["closed"] = recall->closed;
    }
    return {{"method", "graph"},
            {"stops", result.graph->NodeCount()},
            {"edges", result.graph->edges().size()},
            {"scan_matches", result.scan_matches},
            {"loop_closures", loops},
            {"optimise_s", Round(result.optimise_s, 1e-4)},
            {"per_stop_s", {{"mean", Round(mean, 1e-5)}, {"max", Round(most, 1e-5)}}},
            {"rebuilds", result.rebuilds},
            {"rebuild_s", Round(result.rebuild_s, 1e-4)}};
  } else if (localize == LocalizeKind::kScan) {
    return {{"method", "scan"},
            {"frames_matched", result.matches},
            {"frames_corrected", result.corrections},
            {"stops_scan_matched", result.scan_matches},
            {"time_per_matched_frame_s",
             result.matches > 0 ? Round(result.times.localize_s / result.matches, 1e-6) : 0.0}};
  }
  return nullptr;
}

nlohmann::json OdometryNoiseJson(const core::OdometryNoise& noise) {
  return {{"translation", noise.translation},
          {"rotation", noise.rotation},
          {"translation_bias", noise.translation_bias},
          {"rotation_bias", noise.rotation_bias}};
}

nlohmann::json PoseErrorJson(const eval::PoseError& e) {
  return {
      {"ate_rms_m", Round(e.ate_rms_m, 1e-4)}, {"heading_rms_deg", Round(e.heading_rms_deg, 0.01)},
      {"final_m", Round(e.final_m, 1e-4)},     {"final_deg", Round(e.final_deg, 0.01)},
      {"mean_m", Round(e.mean_m, 1e-4)},       {"mean_deg", Round(e.mean_deg, 0.01)},
      {"max_m", Round(e.max_m, 1e-4)}};
}

nlohmann::json RunJson(const ExploreRequest& request, const ExplorationResult& result,
                       const nlohmann::json& eval) {
  nlohmann::json run = RunJsonBase(request);
  run["status"] = result.status;
  if (!result.reason.empty()) run["reason"] = result.reason;
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
                         {"plan", Round(result.times.plan_s, 1e-4)},
                         {"localize", Round(result.times.localize_s, 1e-4)}};
  if (nlohmann::json localization = LocalizationJson(request.options.localize, result);
      !localization.is_null()) {
    run["localization"] = std::move(localization);
  }
  const auto pose_json = [](const core::Pose2& p) {
    return nlohmann::json::array(
        {Round(p.x(), 1e-4), Round(p.y(), 1e-4), Round(core::RadToDeg(p.heading()), 0.01)});
  };
  if (result.final_pose) {
    run["final_pose"] = pose_json(*result.final_pose);
  } else if (!result.path.empty()) {
    run["final_pose"] = pose_json(result.path.back());
  }
  if (result.final_true_pose) run["final_true_pose"] = pose_json(*result.final_true_pose);
  if (result.pose_error) run["pose_error"] = PoseErrorJson(*result.pose_error);
  run["blocked_looks"] = result.blocked_looks;
  run["backups"] = result.backups;
  run["probes"] = result.probes;
  run["contacts"] = result.contacts;
  const auto point_json = [](const Eigen::Vector2d& p) {
    return nlohmann::json::array({Round(p.x(), 1e-3), Round(p.y(), 1e-3)});
  };
  run["given_up"] = nlohmann::json::array();
  for (const GivenUpGoal& g : result.given_up) {
    nlohmann::json entry = {
        {"goal", point_json(g.goal_world)}, {"robot", point_json(g.robot_world)}, {"why", g.why}};
    if (g.cells > 0) entry["cells"] = g.cells;
    run["given_up"].push_back(std::move(entry));
  }
  if (!eval.is_null()) run["eval"] = eval;
  return run;
}

// map.png's width, about (whole pixels a cell).
constexpr int kMapPictureWidthPx = 800;

mapping::OccupancyGrid SeenPart(const mapping::OccupancyGrid& grid) {
  constexpr int kMapMarginCells = 5;
  return grid.CroppedToKnown(kMapMarginCells);
}

mapping::TrinaryMap WriteMapOutputs(const std::string& out_dir, const ExplorationResult& result) {
  const std::filesystem::path out(out_dir);
  const mapping::OccupancyGrid seen = SeenPart(result.grid);
  mapping::TrinaryMap map = seen.ToMapOfRecord();
  io::WriteRosMap(map, (out / "map.yaml").string());
  io::WriteColourMap(result.colour_map.On(map.geometry),
                     io::ColourMapPathFor((out / "map.yaml").string()));
  io::WritePng((out / "map.png").string(),
               draw::DrawMapPicture(seen, result.path, result.stops, kMapPictureWidthPx,
                                    result.graph ? &*result.graph : nullptr));
  if (result.graph) {
    io::WriteFileAtomically((out / "graph.g2o").string(), io::G2oText(*result.graph));
  }
  return map;
}

namespace {

// How long a run whose camera file has intrinsics listens for camera_info,
// only to warn when its size is another: a driver sends it with every frame.
constexpr std::chrono::milliseconds kCameraInfoPeek{1000};

// The robot's radius: the options', else the world's.
double RobotRadius(const ExploreRequest& request, const sim::World* world) {
  const double radius =
      request.radius_m > 0.0 ? request.radius_m : (world ? world->robot().radius : 0.0);
  if (!(radius > 0.0)) {
    throw core::InputError("--radius", 0, "", "a robot without a world needs its radius (metres)");
  }
  return radius;
}

// The robot's camera and size: the options', else the world's.
RobotDescription DescribeRobot(const ExploreRequest& request, const sim::World* world) {
  if (request.camera_path.empty() && world == nullptr) {
    throw core::InputError("--camera", 0, "", "a robot without a world needs its camera file");
  }
  const double radius = RobotRadius(request, world);
  return RobotDescription{
      request.camera_path.empty() ? world->robot().camera : io::LoadCameraFile(request.camera_path),
      radius};
}

void CheckRobotMethod(const ExploreRequest& request) {
  if (request.options.method == vision::MaskSource::kTruth) {
    throw core::InputError("--method", 0, "", "the truth is only known in the simulator");
  }
}

std::chrono::milliseconds RobotTimeout(const ExploreRequest& request) {
  return std::chrono::milliseconds(std::llround(request.robot_timeout_s * 1000.0));
}

// The ROS 2 robot of --robot ros2, its frames `width` × `height` (0: any).
std::unique_ptr<robot::ros2::Ros2Robot> MakeRos2Robot(const ExploreRequest& request, int width,
                                                      int height) {
  robot::ros2::Ros2RobotOptions ros2;
  const Ros2PublishOptions dds = request.ros2_publish.value_or(Ros2PublishOptions{});
  ros2.domain_id = dds.domain_id;
  ros2.network = dds.network;
  ros2.ros_namespace = dds.ros_namespace;
  ros2.frame_width = width;
  ros2.frame_height = height;
  ros2.stop_requested = request.options.stop_requested;
  ros2.connect_timeout = std::min(ros2.connect_timeout, RobotTimeout(request));
  return std::make_unique<robot::ros2::Ros2Robot>(ros2);
}

// Connects to the ROS 2 robot with a camera file that may leave the
// intrinsics to its camera_info (the mount is always the file's), and
// describes it; tells the user where the intrinsics came from.
RobotDescription ConnectRos2Robot(const ExploreRequest& request, const sim::World* world,
                                  std::unique_ptr<robot::Robot>& connected) {
  const io::CameraMountFile file = io::LoadCameraMount(request.camera_path);
  const double radius = RobotRadius(request, world);
  CheckRobotMethod(request);
  std::unique_ptr<robot::ros2::Ros2Robot> robot = MakeRos2Robot(
      request, file.camera ? file.camera->width() : 0, file.camera ? file.camera->height() : 0);
  std::vector<std::string> notes;
  camera::CameraModel camera = CameraOfRos2Robot(*robot, file, request.camera_path,
                                                 RobotTimeout(request), kCameraInfoPeek, notes);
  if (!request.quiet) {
    for (const std::string& note : notes) fmt::print(stderr, "explore: {}\n", note);
  }
  connected = std::move(robot);
  return RobotDescription{std::move(camera), radius};
}

// Connects to the robot at request.robot_url (before any output is made,
// so that a robot that is not there leaves nothing behind).
std::unique_ptr<robot::Robot> ConnectRobot(const ExploreRequest& request,
                                           const RobotDescription& robot_info) {
  CheckRobotMethod(request);
  if (request.robot_url == kRos2Robot) {
    return MakeRos2Robot(request, robot_info.camera.width(), robot_info.camera.height());
  }
  robot::RemoteRobotOptions remote;
  remote.reply_timeout = RobotTimeout(request);
  remote.request_timeout = kRequestTimeoutFactor * RobotTimeout(request);
  remote.frame_width = robot_info.camera.width();
  remote.frame_height = robot_info.camera.height();
  return std::make_unique<robot::RemoteRobot>(request.robot_url, remote);
}

// How a connected robot names itself in reasons: "the robot at HOST:PORT",
// "the ROS 2 robot (DDS domain N)".
std::string RobotName(const robot::Robot& robot) {
  if (const auto* tcp = dynamic_cast<const robot::RemoteRobot*>(&robot)) {
    return "the robot at " + tcp->address().ToString();
  }
  if (const auto* dds = dynamic_cast<const robot::ros2::Ros2Robot*>(&robot)) {
    return "the ROS 2 robot (" + dds->Describe() + ")";
  }
  return "the robot";
}

// Explores through a connected robot, watched for what no working robot does
// (robot::RobotWatchdog: odometry that jumps, a clock that goes backwards, a
// frozen camera, a robot that does not move).
ExplorationResult ExploreRemote(robot::Robot& connected, const ExploreRequest& request,
                                const ExplorationOptions& options,
                                const RobotDescription& robot_info,
                                const ExplorationObserver& observer) {
  robot::RobotWatchdog robot(connected, RobotName(connected));
  std::unique_ptr<vision::FloorSegmenter> segmenter = vision::MakeFloorSegmenter(
      request.options.method == vision::MaskSource::kPaper ? vision::SegmentationMethod::kPaper
                                                           : vision::SegmentationMethod::kDefault,
      robot_info.camera);
  return ExploreWithRobot(robot, robot_info, options, MasksOf(*segmenter), observer);
}

// The request's own checks (the options are checked with their noise).
void CheckRequest(const ExploreRequest& request, bool has_world) {
  if (request.robot_url.empty() && !has_world) {
    throw core::InputError("--world", 0, "",
                           "give a world to explore in the simulator, or --robot");
  }
  if (!(request.robot_timeout_s > 0.0) || request.robot_timeout_s > kMaxRobotTimeoutS) {
    throw core::InputError("--robot-timeout", 0, "", "must be a number of seconds in (0, 3600]");
  }
  if (request.radius_m < 0.0 || !std::isfinite(request.radius_m)) {
    throw core::InputError("--radius", 0, "", "must be a number > 0 (metres)");
  }
}

void CreateOutDir(const std::string& out_dir) {
  std::error_code error;
  std::filesystem::create_directories(out_dir, error);
  if (error) {
    throw core::InputError(out_dir, 0, "--out",
                           "cannot create the output folder: " + error.message());
  }
}

// Records the run's log (--record) from the observer's captures. A log that
// cannot be written (a full disk) stops recording, not the run: the map is
// worth more than the log; error() says why it stopped.
class Recorder {
 public:
  Recorder(const ExploreRequest& request, const RobotDescription& robot_info,
           const localize::OdometryModel& odometry) {
    io::RunLogInfo info;
    info.odometry_model = {odometry.translation_fraction, odometry.rotation_fraction};
    info.radius_m = robot_info.radius_m;
    info.cell_m = request.options.cell_m > 0.0 ? request.options.cell_m
                                               : mapping::DefaultCellSize(robot_info.radius_m);
    info.max_range_m = request.options.max_range_m > 0.0
                           ? request.options.max_range_m
                           : camera::MaxRange(robot_info.camera, info.cell_m);
    info.method = vision::MaskSourceName(request.options.method);
    info.localize = LocalizeKindName(request.options.localize);
    if (request.robot_url.empty()) {
      info.world = request.world_path;
      info.seed = request.options.seed;
    }
    log_.emplace(request.record_dir, robot_info.camera, info);
  }

  void Watch(ExplorationObserver& observer) {
    observer.on_capture = [this](const robot::Frame& frame,
                                 const std::vector<core::MoveOutcome>& motions) {
      if (!error_.empty()) return;
      try {
        log_->AddFrame(frame, motions);
      } catch (const std::exception& e) {
        error_ = e.what();
      }
    };
    observer.on_blocked = [this](double leg_m) { log_->MarkBlocked(leg_m); };
  }

  void Close() {
    if (!error_.empty()) return;
    try {
      log_->Close();
    } catch (const std::exception& e) {
      error_ = e.what();
    }
  }
  const std::string& error() const { return error_; }

 private:
  std::optional<io::RunLogWriter> log_;
  std::string error_;
};

// The run's checkpoints (CheckpointWriter) from the observer's snapshots. A
// checkpoint that cannot be written (a full disk) stops checkpointing, not
// the run, as the recorder does; run.json says why.
class Checkpoints {
 public:
  Checkpoints(const std::string& out_dir, const nlohmann::json& run_base)
      : writer_(out_dir, run_base) {}

  void Watch(ExplorationObserver& observer) {
    auto before = observer.on_snapshot;
    observer.on_snapshot = [this, before](const RunSnapshot& snapshot) {
      if (before) before(snapshot);
      writer_.Publish(snapshot);
    };
  }

  // Waits for the last checkpoint to be written (before the final outputs
  // replace it).
  void Finish() { error_ = writer_.Finish(); }

  // Their count and cost (and error) in the final run.json.
  void Report(nlohmann::json& run) const {
    const CheckpointCost& cost = writer_.cost();
    const auto per = [](double total_s, int n) {
      return n > 0 ? Round(1e3 * total_s / n, 1e-3) : 0.0;
    };
    run["checkpoints"] = {{"taken", cost.taken},
                          {"written", cost.written},
                          {"prepare_ms", per(cost.prepare_s, cost.taken)},
                          {"write_ms", per(cost.write_s, cost.written)},
                          {"max_write_ms", Round(1e3 * cost.max_write_s, 1e-3)}};
    if (!error_.empty()) run["checkpoint_error"] = error_;
  }

 private:
  CheckpointWriter writer_;
  std::string error_;
};

}  // namespace

ExploreReport RunExplore(const ExploreRequest& request) {
  std::optional<sim::World> world;
  if (!request.world_path.empty()) world = io::LoadWorldFile(request.world_path);
  CheckRequest(request, world.has_value());
  ExplorationOptions options = request.options;
  if (world && (request.odometry_noise || request.odometry_bias)) {
    options.odometry_noise = core::OdometryNoiseWith(world->robot().odometry_noise,
                                                     request.odometry_noise, request.odometry_bias);
  }
  CheckExplorationOptions(options);
  // What the run log records; the simulated Explore derives the same.
  options.graph.odometry =
      GraphOdometryModel(options, world ? &world->robot().odometry_noise : nullptr);
  const RunWatchers watchers(request.ros2_publish, request.live_view);
  if (watchers.view != nullptr) {
    if (request.on_view) request.on_view(watchers.view->endpoint());
    options.control = &watchers.view->control();
  }
  std::unique_ptr<robot::Robot> remote;
  const RobotDescription robot_info = [&] {
    const sim::World* w = world ? &*world : nullptr;
    if (request.robot_url == kRos2Robot && !request.camera_path.empty()) {
      return ConnectRos2Robot(request, w, remote);
    }
    RobotDescription description = DescribeRobot(request, w);
    if (!request.robot_url.empty()) remote = ConnectRobot(request, description);
    return description;
  }();
  CreateOutDir(request.out_dir);
  const std::filesystem::path out(request.out_dir);
  std::optional<draw::ExplorationVideo> video;
  if (request.video) video.emplace((out / "explore.mp4").string());

  run::ProgressLine progress(request.quiet);
  ExplorationObserver observer;
  observer.on_progress = [&progress](const ExplorationProgress& p) {
    progress.Show(p.elapsed_s, [&] {
      return fmt::format("explore: {} moves, {} pirouettes, {:.2f} m² known, {:.1f} s", p.moves,
                         p.pirouettes, p.known_area_m2, p.elapsed_s);
    });
  };
  if (video) {
    observer.on_frame = [&video](const FrameEvent& event) {
      video->AddFrame(event.bgr, event.floor_mask, event.odom_T_robot, event.grid);
    };
  }
  watchers.Watch(observer);
  nlohmann::json run_base = RunJsonBase(request);
  if (request.robot_url.empty()) {
    run_base["odometry_noise"] =
        OdometryNoiseJson(options.odometry_noise.value_or(world->robot().odometry_noise));
  }
  Checkpoints checkpoints(out.string(), run_base);
  checkpoints.Watch(observer);
  std::optional<Recorder> recorder;
  if (!request.record_dir.empty()) {
    recorder.emplace(request, robot_info, options.graph.odometry).Watch(observer);
  }

  ExploreReport report{request.robot_url.empty()
                           ? Explore(*world, options, observer)
                           : ExploreRemote(*remote, request, options, robot_info, observer),
                       {},
                       {}};
  checkpoints.Finish();
  if (recorder) {
    recorder->Close();
    report.record_error = recorder->error();
  }
  const mapping::TrinaryMap map = WriteMapOutputs(out.string(), report.result);
  report.run =
      RunJson(request, report.result,
              world ? eval::MapEvaluationToJson(eval::EvaluateMap(map, *world)) : nlohmann::json());
  if (!report.record_error.empty()) report.run["record_error"] = report.record_error;
  if (run_base.contains("odometry_noise")) {
    report.run["odometry_noise"] = run_base["odometry_noise"];
  }
  checkpoints.Report(report.run);
  io::WriteFileAtomically((out / "run.json").string(), report.run.dump(2) + "\n");
  if (video) video->Finish();
  watchers.Finish(map, report.result, request.options.stop_requested);
  return report;
}

}  // namespace pirouette::run
