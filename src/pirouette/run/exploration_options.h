#pragma once

#include <array>
#include <atomic>
#include <cstdint>
#include <optional>
#include <string_view>

#include "pirouette/core/odometry_noise.h"
#include "pirouette/localize/graph_tracker.h"
#include "pirouette/localize/pose_tracker.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/vision/mask_source.h"

namespace pirouette::run {

enum class PlannerKind { kDistanceTransform, kFrontier };

// How the explorer keeps its pose: kNone trusts the odometry; kScan corrects
// each frame's heading against the earlier frames of its stop and the map
// (localize::PoseTracker; docs/measurements.md, "Pose tracking"); kGraph, the
// default, keeps a pose graph over the stops and makes the map again from it
// (localize::GraphTracker).
enum class LocalizeKind { kNone, kScan, kGraph };

// "none" | "scan" | "graph", the command line's and run.json's names.
std::string_view LocalizeKindName(LocalizeKind kind);
std::optional<LocalizeKind> ParseLocalizeKind(std::string_view name);

// "dt" | "frontier", the command line's and run.json's names.
std::string_view PlannerKindName(PlannerKind kind);
// The planner of a name; nullopt for any other.
std::optional<PlannerKind> ParsePlannerKind(std::string_view name);

// The sensor model of an exploration. OctoMap's defaults (hit 0.7, miss
// 0.4) need four looks before floor reads free (below 0.196): too timid for a
// camera that sees each bearing in two frames of a pirouette, so the explorer
// would keep going back to floor it has seen. One look decides here: a miss
// makes an unknown cell free, a hit occupied; a hit and a miss cancel into
// unknown, two hits outvote a miss.
inline constexpr mapping::OccupancyOptions kExplorationOccupancy{.hit_probability = 0.8,
                                                                 .miss_probability = 0.18};

// The most straight moves a run on a robot makes by default before it stops
// with status "step-limit": far more than any shipped world needs (the
// apartment takes a few hundred), so that only a run that goes round in
// circles meets it. In the simulator the floor's size is known and the
// default grows with it (DefaultMaxSteps).
inline constexpr int kDefaultMaxSteps = 2000;

// Straight moves allowed by default for each robot disc's area of floor: a
// run's moves grow with the floor's area over the robot's (mazes explored by
// the paper's robot needed up to 1.7 a disc, apartments 0.6), so a fixed
// limit stopped large worlds and mazes still exploring.
inline constexpr double kDefaultStepsPerDisc = 4.0;

// The default step limit in the simulator for a floor of `floor_area_m2`
// and a robot of radius `radius_m`: kDefaultStepsPerDisc a disc's area of
// floor, and at least kDefaultMaxSteps.
int DefaultMaxSteps(double floor_area_m2, double radius_m);

// What a live view with --view-control may ask of a run (LiveServer's
// ControlCommand), read between the run's steps: while `pause` is set the
// robot stands still; `stop` ends the run with status "interrupted" and the
// map so far, as Ctrl-C does; `home` ends the exploration and drives the
// robot back to where it started, then ends as `stop` does.
struct RunControl {
  std::atomic<bool> pause{false};
  std::atomic<bool> stop{false};
  std::atomic<bool> home{false};
};

// How an exploration runs. Zero for a length means "derive it".
struct ExplorationOptions {
  std::uint64_t seed = 1;
  PlannerKind planner = PlannerKind::kDistanceTransform;
  vision::MaskSource method = vision::MaskSource::kDefault;
  // Straight moves allowed before the run stops with status "step-limit";
  // 0: the default (DefaultMaxSteps in the simulator, else kDefaultMaxSteps).
  int max_steps = 0;
  // The map's cell; 0: 1 cm for a robot of radius under 0.1 m (the paper's),
  // else 2 cm (the apartment robot).
  double cell_m = 0.0;
  // The range readings are trusted to; 0: the paper's rule for the camera
  // and the cell (camera::MaxRange).
  double max_range_m = 0.0;
  // The longest side the map may grow to, metres; 0: kDefaultMaxMapCells
  // cells (frame_mapper.h). A map that would pass it ends the run with status
  // "stuck" and the map so far.
  double max_map_m = 0.0;
  // The sensor model: kExplorationOccupancy.
  mapping::OccupancyOptions occupancy = kExplorationOccupancy;
  // Drive back to the start at the end.
  bool return_home = false;
  // Pose tracking, and what it assumes of the odometry.
  LocalizeKind localize = LocalizeKind::kGraph;
  localize::TrackerOptions tracker;
  // The graph's options; its odometry model is GraphOdometryModel's.
  localize::GraphTrackerOptions graph;
  // What the graph believes of the odometry, {translation, rotation} as
  // localize::OdometryModel's fractions (--odometry-model); none: the
  // simulator's own noise in the simulator, graph.odometry's on a real robot.
  std::optional<std::array<double, 2>> odometry_model;
  // The simulator's motion error; none: the world file's odometry_noise.
  std::optional<core::OdometryNoise> odometry_noise;
  // Checked between steps; when it becomes true the run ends with status
  // "interrupted" and the map so far.
  const std::atomic<bool>* stop_requested = nullptr;
  // A live view's controls (--view-control); none: nobody may ask.
  const RunControl* control = nullptr;
};

// The graph's odometry model: options.odometry_model's fractions when given;
// else, in the simulator (`world_noise` set), the simulated noise
// (options.odometry_noise, else the world's): the standard deviations with the
// biases (a bias is an error the graph cannot tell from noise), in
// quadrature; else options.graph.odometry.
localize::OdometryModel GraphOdometryModel(const ExplorationOptions& options,
                                           const core::OdometryNoise* world_noise);

// Throws core::InputError naming the option for a bad value.
void CheckExplorationOptions(const ExplorationOptions& options);

}  // namespace pirouette::run
