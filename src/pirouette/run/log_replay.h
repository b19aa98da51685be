#pragma once

#include <cstdint>
#include <functional>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>

#include "pirouette/core/odometry_noise.h"
#include "pirouette/run/explorer.h"
#include "pirouette/run/live_view_publisher.h"
#include "pirouette/run/ros2_run_publisher.h"

namespace pirouette::run {

// What `pirouette map --log` was asked. Zero or empty: the log's own value
// (log.yaml), else the explorer's default.
struct MapLogRequest {
  std::string log_dir;
  std::string out_dir = "out";
  std::string world_path;  // for the evaluation; empty: the log's world, if it has one
  double radius_m = 0.0;
  double cell_m = 0.0;
  double max_range_m = 0.0;
  std::string method;      // "default" | "paper"
  std::string localize;    // "scan" | "none"
  double max_map_m = 0.0;  // the map's longest side (0: kDefaultMaxMapCells cells)
  // Set: the log's odometry is taken as the truth (record the log without
  // noise) and the frames are mapped at the odometry a robot with this error
  // would have reported (sim::DriftedOdometry, drawn from `seed`); run.json
  // then gives the pose error and the loop closures against the truth. The
  // pose graph's odometry model is this error, as in the simulator.
  std::optional<core::OdometryNoise> odometry_noise;
  std::uint64_t seed = 1;
  bool quiet = false;
  // Set: publish the map to ROS 2 over DDS frame by frame (Ros2RunPublisher).
  std::optional<Ros2PublishOptions> ros2_publish;
  // Set: serve the live view frame by frame (LiveViewPublisher); `on_view`
  // is told where it listens.
  std::optional<LiveViewOptions> live_view;
  std::function<void(const view::Endpoint&)> on_view;
  // Checked between frames (Ctrl-C): the replay ends with the map so far.
  const std::atomic<bool>* stop_requested = nullptr;
};

struct MapLogReport {
  ExplorationResult result;  // grid, path (the frames' odometry), frames, times
  nlohmann::json run;        // run.json's content
};

// Builds the map of a run log (pirouette-log/1) frame by frame, exactly as
// the run that recorded it did (FrameMapper), and writes the outputs of
// explore: OUT/map.yaml, map.pgm, map.png and run.json (with the map's
// evaluation when a world is known). Throws core::InputError for a bad log
// or option (naming the file, line and field).
MapLogReport RunMapLog(const MapLogRequest& request);

}  // namespace pirouette::run
