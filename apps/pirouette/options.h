#pragma once

#include <CLI/CLI.hpp>
#include <cstdint>
#include <functional>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "pirouette/run/live_view_publisher.h"
#include "pirouette/run/ros2_run_publisher.h"

namespace pirouette::cli {

// The options several subcommands share, each declared here once: its name,
// its one help text and how it is read. Where the commands differ in what an
// option is for or what its default is, the caller passes that as a phrase.
//
// `default_note`: empty where the option's variable holds its default (shown
// as "=VALUE" in --help); else the help ends "(default: NOTE)" and no value
// is shown, for defaults decided later (the camera's, the log's).

// The choices of --method: a floor segmenter (vision::SegmentationMethod), or
// a segmenter or the simulator's truth (vision::MaskSource).
inline const std::vector<std::string> kSegmentationMethods = {"default", "paper"};
inline const std::vector<std::string> kMaskSources = {"default", "paper", "truth"};

// --method: the floor segmentation, one of `choices` (refused otherwise).
CLI::Option* AddMethodOption(CLI::App* app, std::string& method,
                             const std::vector<std::string>& choices,
                             std::string_view default_note = {});

// --seed: `seeds` says what it seeds ("the simulator's noise (camera and
// odometry)").
CLI::Option* AddSeedOption(CLI::App* app, std::uint64_t& seed, std::string_view seeds);

// --quiet: no progress on standard error.
CLI::Option* AddQuietOption(CLI::App* app, bool& quiet);

// --out, the folder a run writes its outputs to.
CLI::Option* AddOutFolderOption(CLI::App* app, std::string& dir);
// --out, a PNG to write; `what` says what it shows.
CLI::Option* AddOutPngOption(CLI::App* app, std::string& path, std::string_view what);
// --out, a file for the JSON report, written atomically.
CLI::Option* AddReportOption(CLI::App* app, std::string& path);

// --world, one world file; `role` (may be empty) says what it is for here.
CLI::Option* AddWorldOption(CLI::App* app, std::string& path, std::string_view role = {});
// --world, repeated: one or more world files.
CLI::Option* AddWorldsOption(CLI::App* app, std::vector<std::string>& paths);

// --camera, a camera file; `role` (may be empty) says what it is for here.
CLI::Option* AddCameraOption(CLI::App* app, std::string& path, std::string_view role = {});

// --image, a photo to read; `what` (may be empty) says what it must show.
CLI::Option* AddImageOption(CLI::App* app, std::string& path, std::string_view what = {});

// --cell: the map's cell, metres, from which the default maximum range follows.
CLI::Option* AddCellOption(CLI::App* app, double& cell_m, std::string_view default_note = {});

// --max-range: how far the obstacle profiles are read, metres. Either a
// value whose 0 means the default, or an optional left empty unless given.
CLI::Option* AddMaxRangeOption(CLI::App* app, double& max_range_m, std::string_view default_note);
// --max-map-m: the longest side the map may grow to.
CLI::Option* AddMaxMapOption(CLI::App* app, double& max_map_m, std::string_view ending);
CLI::Option* AddMaxRangeOption(CLI::App* app, std::optional<double>& max_range_m,
                               std::string_view default_note);

// --radius: the robot's radius, metres (0: the default).
CLI::Option* AddRadiusOption(CLI::App* app, double& radius_m, std::string_view default_note);

// --pose X,Y,HEADING as given (cli::ParsePose reads it once the command
// runs); `role` (may be empty) says whose pose it is.
CLI::Option* AddPoseOption(CLI::App* app, std::string& text, std::string_view role = {});

// --localize: pose tracking, scan or none.
CLI::Option* AddLocalizeOption(CLI::App* app, std::string& kind,
                               std::string_view default_note = {});

// --planner: one planner, or several (comma separated).
CLI::Option* AddPlannerOption(CLI::App* app, std::string& planner);
CLI::Option* AddPlannersOption(CLI::App* app, std::vector<std::string>& planners);

// --max-steps: the straight moves a run may make.
CLI::Option* AddMaxStepsOption(CLI::App* app, int& max_steps);

// --odometry-noise and --odometry-bias of the simulated robot: T,R each, or
// left empty for the world file's.
void AddOdometryOptions(CLI::App* app, std::vector<double>& noise, std::vector<double>& bias);
// --odometry-model T,R: the pose graph's odometry model (run::ExploreRequest::odometry_model).
void AddOdometryModelOption(CLI::App* app, std::vector<double>& model);

// --range-factor: how far a pirouette and the map's views are read, in
// times the map's range.
CLI::Option* AddRangeFactorOption(CLI::App* app, double& range_factor);

// --table: a place table file; `role` says when it is loaded or written.
CLI::Option* AddPlaceTableOption(CLI::App* app, std::string& path, std::string_view role);

// --ros2-publish, --ros-namespace and --ros-network: publish the run to ROS 2
// over DDS (docs/ros2.md).
struct Ros2Choices {
  bool publish = false;
  std::string ros_namespace;
  std::string network;
};
void AddRos2PublishOptions(CLI::App* app, Ros2Choices& choices);

// The publishing the choices ask for (none without --ros2-publish), in the
// domain ROS_DOMAIN_ID names. Throws core::InputError naming ROS_DOMAIN_ID,
// --ros-namespace or --ros-network for a value ROS 2 or Cyclone would refuse.
std::optional<run::Ros2PublishOptions> Ros2PublishOf(const Ros2Choices& choices);

// --view [HOST:]PORT, --view-control, --view-linger (SPEC.md, "Live view").
struct ViewChoices {
  std::string endpoint;
  bool control = false;
  double linger_s = 0.0;
};
// `with_control`: also --view-control (explore's only: a replay and the
// simulator's server have no run to pause or send home).
void AddViewOptions(CLI::App* app, ViewChoices& choices, bool with_control);

// The live view the choices ask for (none without --view), its topics under
// `ros_namespace`. Throws core::InputError naming the option at fault.
std::optional<run::LiveViewOptions> LiveViewOf(const ViewChoices& choices,
                                               const std::string& ros_namespace);

// Says on standard error where the view listens (unless quiet).
std::function<void(const view::Endpoint&)> AnnounceView(const char* command, bool quiet);

}  // namespace pirouette::cli
