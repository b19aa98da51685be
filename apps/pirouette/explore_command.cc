#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "apps/pirouette/command.h"
#include "apps/pirouette/interrupt.h"
#include "apps/pirouette/options.h"
#include "pirouette/run/explore_job.h"

namespace pirouette::cli {
namespace {

constexpr const char* kExploreHelp =
    "Drop the robot (simulated, or a real one with --robot) into a world knowing nothing and let "
    "it map the floor by itself: it pirouettes (12 frames, 30 degrees apart), maps the floor's "
    "edges, plans the shortest safe path to the nearest unknown space, looks before every move, "
    "and stops when no reachable unknown space is left. Writes OUT/map.yaml + map.pgm (ROS "
    "map_server), map.png, map_colours.png (the colours seen on the map's walls, for locate), "
    "run.json (with the map's evaluation against the world) and, with --video, explore.mp4. "
    "Ctrl-C stops and still writes the map so far.\n"
    "Exit: 0 complete or step limit, 1 stuck or interrupted (outputs still written), 2 bad "
    "input.\n  example: pirouette explore --world worlds/soccer_field.yaml --out out --video\n"
    "  a real robot: pirouette explore --robot tcp://192.168.1.20:5555 --camera cam.yaml "
    "--radius 0.15 --record run1";

// The options given as text, read into the request when the command runs.
struct ExploreChoices {
  std::string planner = "dt";
  std::string method = "default";
  std::string localize = "graph";
  std::vector<double> odometry_noise;  // {} or {translation, rotation}
  std::vector<double> odometry_bias;   // {} or {translation, rotation}
  std::vector<double> odometry_model;  // {} or {translation, rotation}
  Ros2Choices ros2;
  ViewChoices view;
};

// The world, where the outputs go, the seed and the step limit.
void AddRunOptions(CLI::App* cmd, run::ExploreRequest& request) {
  AddWorldOption(cmd, request.world_path,
                 "with --robot only for the camera, the radius and the evaluation");
  AddOutFolderOption(cmd, request.out_dir);
  AddSeedOption(cmd, request.options.seed, "the simulator's noise (camera and odometry)");
  AddMaxStepsOption(cmd, request.options.max_steps);
}

// How the robot sees, maps and explores.
void AddExplorationOptions(CLI::App* cmd, run::ExploreRequest& request, ExploreChoices& choices) {
  AddPlannerOption(cmd, choices.planner);
  AddMethodOption(cmd, choices.method, kSegmentationMethods);
  AddLocalizeOption(cmd, choices.localize);
  AddCellOption(cmd, request.options.cell_m, "0.01 for a robot under 0.1 m radius, else 0.02");
  AddMaxRangeOption(cmd, request.options.max_range_m, "the paper's rule for the camera and --cell");
  AddMaxMapOption(cmd, request.options.max_map_m, "ends the run (status stuck)");
  cmd->add_flag("--return-home", request.options.return_home,
                "drive back to the start when the map is complete");
  AddOdometryOptions(cmd, choices.odometry_noise, choices.odometry_bias);
  AddOdometryModelOption(cmd, choices.odometry_model);
}

// A real robot instead of the simulated one, and what else is written.
void AddRobotAndOutputOptions(CLI::App* cmd, run::ExploreRequest& request,
                              ExploreChoices& choices) {
  cmd->add_flag("--video", request.video, "also write OUT/explore.mp4");
  cmd->add_option("--robot", request.robot_url,
                  "explore with a real robot instead of in the simulator: tcp://HOST:PORT, one "
                  "that speaks the line protocol (docs/robot-protocol.md), or ros2, a ROS 2 "
                  "robot over DDS that publishes image_raw and odom and obeys cmd_vel, in the "
                  "domain ROS_DOMAIN_ID names, under --ros-namespace (docs/ros2.md; the run is "
                  "published as with --ros2-publish). `pirouette sim-serve [--ros2]` serves the "
                  "simulator either way");
  AddCameraOption(cmd, request.camera_path,
                  "the robot's camera (default: the world's); with --robot ros2 it may hold only "
                  "the mount, the intrinsics then coming from camera_info");
  AddRadiusOption(cmd, request.radius_m, "the world's robot");
  cmd->add_option("--robot-timeout", request.robot_timeout_s,
                  "seconds to wait for the robot's reply before giving up (the map so far is "
                  "written)")
      ->capture_default_str();
  cmd->add_option("--record", request.record_dir,
                  "also write a run log (pirouette-log/1: camera.yaml, frames/, frames.csv) in "
                  "this new folder; `pirouette map --log DIR` maps it again");
  AddRos2PublishOptions(cmd, choices.ros2);
  AddViewOptions(cmd, choices.view, true);
  AddQuietOption(cmd, request.quiet);
}

// Explores; a run that ends stuck or interrupted, or whose run log is
// incomplete, is a failed run (exit 1) after its outputs are written.
void Explore(run::ExploreRequest& request, const ExploreChoices& choices) {
  request.options.localize = *run::ParseLocalizeKind(choices.localize);
  if (!choices.odometry_noise.empty()) {
    request.odometry_noise = {choices.odometry_noise[0], choices.odometry_noise[1]};
  }
  if (!choices.odometry_bias.empty()) {
    request.odometry_bias = {choices.odometry_bias[0], choices.odometry_bias[1]};
  }
  if (!choices.odometry_model.empty()) {
    request.options.odometry_model = {choices.odometry_model[0], choices.odometry_model[1]};
  }
  request.options.planner = *run::ParsePlannerKind(choices.planner);
  request.options.method = *vision::ParseMaskSource(choices.method);
  Ros2Choices ros2 = choices.ros2;
  if (request.robot_url == run::kRos2Robot) ros2.publish = true;  // its topics are NS's too
  request.ros2_publish = Ros2PublishOf(ros2);
  request.live_view = LiveViewOf(choices.view, ros2.ros_namespace);
  request.on_view = AnnounceView("explore", request.quiet);
  request.options.stop_requested = StopOnInterrupt();
  const run::ExploreReport report = run::RunExplore(request);
  const std::string& status = report.result.status;
  if (!request.quiet) {
    std::fprintf(stderr, "explore: %s; map in %s/map.yaml\n", status.c_str(),
                 request.out_dir.c_str());
  }
  if (status == "stuck") throw std::runtime_error("stuck: " + report.result.reason);
  if (!report.record_error.empty()) {
    throw std::runtime_error("the run log in " + request.record_dir +
                             " is incomplete: " + report.record_error);
  }
  if (status == "interrupted") {
    throw std::runtime_error("interrupted; the map so far is in " + request.out_dir);
  }
}

}  // namespace

Command AddExploreCommand(CLI::App& parent) {
  auto request = std::make_shared<run::ExploreRequest>();
  auto choices = std::make_shared<ExploreChoices>();
  CLI::App* cmd = parent.add_subcommand("explore", kExploreHelp);
  AddRunOptions(cmd, *request);
  AddExplorationOptions(cmd, *request, *choices);
  AddRobotAndOutputOptions(cmd, *request, *choices);
  return {cmd, [request, choices] { Explore(*request, *choices); }};
}

}  // namespace pirouette::cli
