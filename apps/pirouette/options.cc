#include "apps/pirouette/options.h"

#include <cstdio>
#include <limits>
#include <map>
#include <stdexcept>

#include "pirouette/core/input_error.h"
#include "pirouette/robot/ros2/dds_participant.h"

namespace pirouette::cli {
namespace {

std::string WithRole(std::string help, std::string_view role) {
  if (!role.empty()) help += "; " + std::string(role);
  return help;
}

// The help text ended by "(default: NOTE)" where there is a note.
std::string WithDefault(std::string help, std::string_view default_note) {
  if (!default_note.empty()) help += " (default: " + std::string(default_note) + ")";
  return help;
}

// Shows the variable's value as the default where no note says otherwise.
CLI::Option* ShowDefault(CLI::Option* option, std::string_view default_note) {
  return default_note.empty() ? option->capture_default_str() : option;
}

std::string MethodHelp(const std::vector<std::string>& choices) {
  static const std::map<std::string, std::string, std::less<>> kMeaning = {
      {"default", "the floor's colour and texture, learnt online, with edges"},
      {"paper", "Taylor, Geva & Boles 2005: low-pass, Canny, flood fill from the bottom"},
      {"truth", "the simulator's true floor mask"},
  };
  std::string help = "floor segmentation: ";
  for (std::size_t i = 0; i < choices.size(); ++i) {
    const char* separator = i == 0 ? "" : i + 1 == choices.size() ? " or " : ", ";
    help += separator + choices[i] + " (" + kMeaning.at(choices[i]) + ")";
  }
  return help;
}

constexpr const char* kPlannerHelp =
    "dt: the paper's distance transform to the nearest unknown space; frontier: the "
    "explore_lite baseline";

}  // namespace

CLI::Option* AddMethodOption(CLI::App* app, std::string& method,
                             const std::vector<std::string>& choices,
                             std::string_view default_note) {
  CLI::Option* option =
      app->add_option("--method", method, WithDefault(MethodHelp(choices), default_note))
          ->check(CLI::IsMember(choices));
  return ShowDefault(option, default_note);
}

CLI::Option* AddSeedOption(CLI::App* app, std::uint64_t& seed, std::string_view seeds) {
  return app->add_option("--seed", seed, "seed of " + std::string(seeds))->capture_default_str();
}

CLI::Option* AddQuietOption(CLI::App* app, bool& quiet) {
  return app->add_flag("--quiet", quiet, "no progress on standard error");
}

CLI::Option* AddOutFolderOption(CLI::App* app, std::string& dir) {
  return app->add_option("--out", dir, "output folder")->capture_default_str();
}

CLI::Option* AddOutPngOption(CLI::App* app, std::string& path, std::string_view what) {
  return app->add_option("--out", path, "the PNG to write: " + std::string(what));
}

CLI::Option* AddReportOption(CLI::App* app, std::string& path) {
  return app->add_option("--out", path, "write the JSON report here (atomically)");
}

CLI::Option* AddWorldOption(CLI::App* app, std::string& path, std::string_view role) {
  return app->add_option("--world", path, WithRole("world file (pirouette-world/1 YAML)", role));
}

CLI::Option* AddWorldsOption(CLI::App* app, std::vector<std::string>& paths) {
  return app->add_option("--world", paths,
                         "world files (pirouette-world/1 YAML): repeat the option for each");
}

CLI::Option* AddCameraOption(CLI::App* app, std::string& path, std::string_view role) {
  return app->add_option("--camera", path,
                         WithRole("camera file (ROS camera_info YAML + mount)", role));
}

CLI::Option* AddImageOption(CLI::App* app, std::string& path, std::string_view what) {
  return app->add_option("--image", path, WithRole("the photo (any format OpenCV reads)", what));
}

CLI::Option* AddCellOption(CLI::App* app, double& cell_m, std::string_view default_note) {
  CLI::Option* option = app->add_option(
      "--cell", cell_m,
      WithDefault("map cell, metres, for which the paper's rule gives the maximum range",
                  default_note));
  return ShowDefault(option, default_note);
}

namespace {

std::string MaxRangeHelp(std::string_view default_note) {
  return WithDefault("read the obstacle profiles out to this range, metres", default_note);
}

}  // namespace

CLI::Option* AddMaxRangeOption(CLI::App* app, double& max_range_m, std::string_view default_note) {
  return app->add_option("--max-range", max_range_m, MaxRangeHelp(default_note));
}

CLI::Option* AddMaxRangeOption(CLI::App* app, std::optional<double>& max_range_m,
                               std::string_view default_note) {
  return app->add_option_function<double>(
      "--max-range", [&max_range_m](const double& value) { max_range_m = value; },
      MaxRangeHelp(default_note));
}

CLI::Option* AddMaxMapOption(CLI::App* app, double& max_map_m, std::string_view ending) {
  return app
      ->add_option("--max-map-m", max_map_m,
                   "the longest side the map may grow to, metres (default: 4096 cells, 41 m at "
                   "1 cm, 82 m at 2 cm); a frame that would make it larger (odometry that "
                   "jumped, a floor larger than this) " +
                       std::string(ending) + ", with the map so far")
      ->check(CLI::PositiveNumber);
}

CLI::Option* AddRadiusOption(CLI::App* app, double& radius_m, std::string_view default_note) {
  return app->add_option("--radius", radius_m,
                         WithDefault("the robot's radius, metres", default_note));
}

CLI::Option* AddPoseOption(CLI::App* app, std::string& text, std::string_view role) {
  return app->add_option(
      "--pose", text,
      WithRole("X,Y,HEADING: metres, metres, degrees counter-clockwise from +x", role));
}

CLI::Option* AddLocalizeOption(CLI::App* app, std::string& kind, std::string_view default_note) {
  CLI::Option* option =
      app->add_option(
             "--localize", kind,
             WithDefault(
                 "pose tracking. graph: a pose graph over the stops (each stop scan-matched "
                 "against the earlier stops its view overlaps, loops closed when the robot comes "
                 "back, optimised after every stop, the map made again from every frame at its "
                 "stop's new pose; DIR/graph.g2o); none: trust the odometry; scan: correct each "
                 "frame's heading by "
                 "matching what the camera sees against the earlier frames of the stop and the "
                 "map made before it, turning in steps of a pirouette's with a look after each, "
                 "and each whole pirouette's position and heading by scan matching its hits "
                 "against those of the stops before (cuts pose error and false free cells under "
                 "wheel slip, costs a little without it: docs/measurements.md, \"Pose tracking\")",
                 default_note))
          ->check(CLI::IsMember({"graph", "scan", "none"}));
  return ShowDefault(option, default_note);
}

CLI::Option* AddPlannerOption(CLI::App* app, std::string& planner) {
  return app->add_option("--planner", planner, kPlannerHelp)
      ->check(CLI::IsMember({"dt", "frontier"}))
      ->capture_default_str();
}

CLI::Option* AddPlannersOption(CLI::App* app, std::vector<std::string>& planners) {
  return app
      ->add_option("--planner", planners,
                   "planners, comma separated (" + std::string(kPlannerHelp) + ")")
      ->delimiter(',')
      ->check(CLI::IsMember({"dt", "frontier"}))
      ->capture_default_str();
}

CLI::Option* AddMaxStepsOption(CLI::App* app, int& max_steps) {
  return app
      ->add_option(
          "--max-steps", max_steps,
          "straight moves a run may make; then it stops (status step-limit). Default: "
          "in the simulator 4 for each robot disc's area of floor, at least 2000; on a robot "
          "2000")
      ->check(CLI::Range(1, std::numeric_limits<int>::max()).description(">= 1"));
}

void AddOdometryOptions(CLI::App* app, std::vector<double>& noise, std::vector<double>& bias) {
  app->add_option("--odometry-noise", noise,
                  "T,R: the simulated robot's motion error, standard deviations as fractions of "
                  "each straight move's length and each turn's angle (default: the world file's "
                  "odometry_noise)")
      ->delimiter(',')
      ->expected(2);
  app->add_option("--odometry-bias", bias,
                  "T,R: a constant error added to those fractions (wheels that drift one way), "
                  "e.g. 0.02,-0.01 (default: the world file's odometry_noise)")
      ->delimiter(',')
      ->expected(2);
}

void AddOdometryModelOption(CLI::App* app, std::vector<double>& model) {
  app->add_option("--odometry-model", model,
                  "T,R: what the pose graph (--localize graph) believes of the odometry: the "
                  "standard deviations of a straight move's error as a fraction of its length "
                  "and of a turn's as a fraction of its angle, e.g. 0.05,0.03 for a robot whose "
                  "wheels slip little (default: 0.08,0.08 for a real robot; in the simulator "
                  "the world's odometry_noise with --odometry-noise and --odometry-bias)")
      ->delimiter(',')
      ->expected(2);
}

CLI::Option* AddRangeFactorOption(CLI::App* app, double& range_factor) {
  return app
      ->add_option("--range-factor", range_factor,
                   "read the pirouettes (and the map's views) out to this many times the map's "
                   "range, but no farther than every image column sees the floor")
      ->capture_default_str();
}

CLI::Option* AddPlaceTableOption(CLI::App* app, std::string& path, std::string_view role) {
  return app->add_option("--table", path,
                         WithRole("place table file (pirouette-places/1 YAML)", role));
}

}  // namespace pirouette::cli

namespace pirouette::cli {

void AddRos2PublishOptions(CLI::App* app, Ros2Choices& choices) {
  app->add_flag("--ros2-publish", choices.publish,
                "publish the run to ROS 2 over DDS as it goes, in the domain ROS_DOMAIN_ID names "
                "(default 0): map, tf (map->odom), pirouette/path, pirouette/plan, "
                "pirouette/floor, pirouette/status, for RViz2 or `ros2 topic echo` "
                "(docs/ros2.md). Only on the loopback interface unless --ros-network");
  app->add_option("--ros-namespace", choices.ros_namespace,
                  "the ROS 2 namespace of the topics, e.g. robot1 (default: none)");
  app->add_option("--ros-network", choices.network,
                  "let DDS leave this machine: an interface (eth0, wlan0 or its IPv4 address), "
                  "or auto for Cyclone DDS's own choice and CYCLONEDDS_URI (default: loopback "
                  "only, 127.0.0.1, no multicast)");
}

std::optional<run::Ros2PublishOptions> Ros2PublishOf(const Ros2Choices& choices) {
  if (!choices.publish) {
    if (!choices.ros_namespace.empty() || !choices.network.empty()) {
      throw core::InputError("--ros-namespace", 0, "", "needs --ros2-publish");
    }
    return std::nullopt;
  }
  run::Ros2PublishOptions options;
  try {
    options.domain_id = robot::ros2::RosDomainIdFromEnvironment();
  } catch (const std::invalid_argument& e) {
    throw core::InputError("ROS_DOMAIN_ID", 0, "", e.what());
  }
  try {
    robot::ros2::RosTopicName(choices.ros_namespace, "map");
  } catch (const std::invalid_argument& e) {
    throw core::InputError("--ros-namespace", 0, "", e.what());
  }
  options.ros_namespace = choices.ros_namespace;
  options.network.interface = choices.network;
  try {
    robot::ros2::CycloneConfigFor(options.network);
  } catch (const std::invalid_argument& e) {
    throw core::InputError("--ros-network", 0, "", e.what());
  }
  return options;
}

void AddViewOptions(CLI::App* app, ViewChoices& choices, bool with_control) {
  app->add_option("--view", choices.endpoint,
                  "serve a live view of the run on [HOST:]PORT: a web page at http://HOST:PORT/ "
                  "(the map growing, the robot, its path and plan, the camera's last frame with "
                  "its floor, progress) and the Foxglove WebSocket protocol at ws://HOST:PORT/ "
                  "for Foxglove (docs/live_view.md). HOST defaults to 127.0.0.1, this machine "
                  "only; 0.0.0.0 opens it to every network the machine is on: anyone who "
                  "reaches the port sees the run")
      ->type_name("[HOST:]PORT");
  if (with_control) {
    app->add_flag("--view-control", choices.control,
                  "let the live view pause, resume and stop the run and send the robot home "
                  "(default: it only watches and refuses every such request)");
  }
  app->add_option("--view-linger", choices.linger_s,
                  "seconds to keep serving the live view after the run ends, so a page opened "
                  "late still sees the end (ends sooner once every client has left; Ctrl-C ends "
                  "it)")
      ->capture_default_str()
      ->check(CLI::NonNegativeNumber);
}

std::optional<run::LiveViewOptions> LiveViewOf(const ViewChoices& choices,
                                               const std::string& ros_namespace) {
  if (choices.endpoint.empty()) {
    if (choices.control) throw core::InputError("--view-control", 0, "", "needs --view");
    return std::nullopt;
  }
  run::LiveViewOptions options;
  options.endpoint = view::ParseEndpoint(choices.endpoint, "--view");
  options.control = choices.control;
  options.linger_s = choices.linger_s;
  options.ros_namespace = ros_namespace;
  return options;
}

std::function<void(const view::Endpoint&)> AnnounceView(const char* command, bool quiet) {
  return [command, quiet](const view::Endpoint& endpoint) {
    if (quiet) return;
    const std::string url = view::HttpUrl(endpoint);
    std::fprintf(stderr, "%s: live view at %s (Foxglove: ws%s)\n", command, url.c_str(),
                 url.substr(4).c_str());
  };
}

}  // namespace pirouette::cli
