#include "pirouette/run/exploration_options.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

#include "pirouette/core/input_error.h"

namespace pirouette::run {

std::string_view PlannerKindName(PlannerKind kind) {
  return kind == PlannerKind::kFrontier ? "frontier" : "dt";
}

std::optional<PlannerKind> ParsePlannerKind(std::string_view name) {
  if (name == "dt") return PlannerKind::kDistanceTransform;
  if (name == "frontier") return PlannerKind::kFrontier;
  return std::nullopt;
}

std::string_view LocalizeKindName(LocalizeKind kind) {
  switch (kind) {
    case LocalizeKind::kScan:
      return "scan";
    case LocalizeKind::kGraph:
      return "graph";
    case LocalizeKind::kNone:
      break;
  }
  return "none";
}

std::optional<LocalizeKind> ParseLocalizeKind(std::string_view name) {
  if (name == "none") return LocalizeKind::kNone;
  if (name == "scan") return LocalizeKind::kScan;
  if (name == "graph") return LocalizeKind::kGraph;
  return std::nullopt;
}

localize::OdometryModel GraphOdometryModel(const ExplorationOptions& options,
                                           const core::OdometryNoise* world_noise) {
  localize::OdometryModel model = options.graph.odometry;
  if (options.odometry_model) {
    model.translation_fraction = (*options.odometry_model)[0];
    model.rotation_fraction = (*options.odometry_model)[1];
  } else if (world_noise != nullptr) {
    const core::OdometryNoise& noise = options.odometry_noise.value_or(*world_noise);
    model.translation_fraction = std::hypot(noise.translation, noise.translation_bias);
    model.rotation_fraction = std::hypot(noise.rotation, noise.rotation_bias);
  }
  return model;
}

int DefaultMaxSteps(double floor_area_m2, double radius_m) {
  // Beyond this the limit would not stop a run in circles within a day.
  constexpr double kMostSteps = 1e6;
  const double disc_m2 = std::numbers::pi * radius_m * radius_m;
  if (!(floor_area_m2 > 0.0) || !(disc_m2 > 0.0)) return kDefaultMaxSteps;
  const double steps = std::ceil(kDefaultStepsPerDisc * floor_area_m2 / disc_m2);
  return static_cast<int>(std::clamp(steps, static_cast<double>(kDefaultMaxSteps), kMostSteps));
}

void CheckExplorationOptions(const ExplorationOptions& options) {
  try {
    options.occupancy.Check();
  } catch (const std::invalid_argument& e) {
    throw core::InputError("sensor model", 0, "", e.what());
  }
  if (options.max_steps < 0) {
    throw core::InputError("--max-steps", 0, "", "must be at least 1");
  }
  if (options.cell_m < 0.0 || !std::isfinite(options.cell_m) ||
      (options.cell_m > 0.0 &&
       (options.cell_m < mapping::kMinCellM || options.cell_m > mapping::kMaxCellM))) {
    throw core::InputError("--cell", 0, "", "the map cell must be between 0.002 and 0.5 m");
  }
  if (options.max_range_m < 0.0 || !std::isfinite(options.max_range_m)) {
    throw core::InputError("--max-range", 0, "", "must be a number > 0 (metres)");
  }
  if (options.max_map_m < 0.0 || !std::isfinite(options.max_map_m)) {
    throw core::InputError("--max-map-m", 0, "", "must be a number > 0 (metres)");
  }
  if (options.odometry_noise) core::CheckOdometryNoise(*options.odometry_noise);
  try {
    GraphOdometryModel(options, nullptr).Check();
  } catch (const std::invalid_argument& e) {
    throw core::InputError("--odometry-model", 0, "", e.what());
  }
}

}  // namespace pirouette::run
