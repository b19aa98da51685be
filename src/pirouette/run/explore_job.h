#pragma once

#include <array>
#include <atomic>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>

#include "pirouette/core/odometry_noise.h"
#include "pirouette/run/explorer.h"
#include "pirouette/run/live_view_publisher.h"
#include "pirouette/run/ros2_run_publisher.h"

namespace pirouette::run {

// `--robot ros2`: a ROS 2 robot over DDS (robot::ros2::Ros2Robot).
inline constexpr std::string_view kRos2Robot = "ros2";

// What `pirouette explore` was asked.
struct ExploreRequest {
  std::string world_path;
  std::string out_dir = "out";
  ExplorationOptions options;
  bool video = false;
  bool quiet = false;
  // Non-empty: also write a run log (pirouette-log/1) of the run there.
  std::string record_dir;
  // Non-empty: explore with the robot at this tcp://HOST:PORT (the line
  // protocol, docs/robot-protocol.md), or with the ROS 2 robot on DDS
  // (kRos2Robot: its domain, network and namespace are ros2_publish's),
  // instead of in the simulator; the world, when given, is then only for the
  // camera, the radius and the evaluation.
  std::string robot_url;
  std::string camera_path;        // the robot's camera file (default: the world's)
  double radius_m = 0.0;          // the robot's radius (default: the world's)
  double robot_timeout_s = 30.0;  // longest wait for a reply of the robot
  // The simulator's motion error, overriding the world file's: standard
  // deviations {translation, rotation} and biases {translation, rotation},
  // as fractions of each move (core::OdometryNoise).
  std::optional<std::array<double, 2>> odometry_noise;
  std::optional<std::array<double, 2>> odometry_bias;
  // Set: publish the run to ROS 2 over DDS as it goes (Ros2RunPublisher).
  std::optional<Ros2PublishOptions> ros2_publish;
  // Set: serve the live view (LiveViewPublisher) from before the robot is
  // reached to after the run, and tell `on_view` where it listens.
  std::optional<LiveViewOptions> live_view;
  std::function<void(const view::Endpoint&)> on_view;
};

// What it made.
struct ExploreReport {
  ExplorationResult result;
  nlohmann::json run;  // run.json's content
  // Why the run log stopped being written, if it did (the run went on).
  std::string record_error;
};

// Explores the world of the request and writes, atomically, OUT/map.yaml,
// OUT/map.pgm, OUT/map.png, OUT/map_colours.png, OUT/run.json (SPEC.md) and with `video`
// OUT/explore.mp4, and with `record_dir` a run log; the outputs are written whatever the status, so
// an interrupted or stuck run keeps its map. After every stop it checkpoints OUT/map.pgm,
// OUT/map.yaml and OUT/run.json (`status: running`; CheckpointWriter), so that a run killed at any
// moment keeps its map up to its last stop. Progress goes to standard error unless `quiet`. Throws
// core::InputError for a bad world or option.
ExploreReport RunExplore(const ExploreRequest& request);

// The part of a grid a run writes and publishes: the cells the robot saw,
// with a margin of 5 cells.
mapping::OccupancyGrid SeenPart(const mapping::OccupancyGrid& grid);

// Writes OUT/map.yaml, OUT/map.pgm (the part of the result's grid the robot
// saw, with a margin), OUT/map.png (with its path and stops) and
// OUT/map_colours.png (the result's colour layer on that part,
// io::WriteColourMap), atomically; returns
// the map written.
mapping::TrinaryMap WriteMapOutputs(const std::string& out_dir, const ExplorationResult& result);

// The fields of run.json known before the run: format, world, seed, planner,
// method, localize, robot.
nlohmann::json RunJsonBase(const ExploreRequest& request);

// run.json's `localization` object for a result mapped with `localize`
// (graph: its stops, edges, loop closures and times; scan: its matches),
// null for none.
nlohmann::json LocalizationJson(LocalizeKind localize, const ExplorationResult& result);
// run.json's `odometry_noise` object.
nlohmann::json OdometryNoiseJson(const core::OdometryNoise& noise);
// run.json's `pose_error` object.
nlohmann::json PoseErrorJson(const eval::PoseError& error);

// run.json (SPEC.md's `pirouette-run/1`) for a result; `eval` is the map's
// evaluation object (null: none, no world).
nlohmann::json RunJson(const ExploreRequest& request, const ExplorationResult& result,
                       const nlohmann::json& eval);

}  // namespace pirouette::run
