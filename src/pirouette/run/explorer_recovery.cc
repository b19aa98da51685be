// The explorer's ways out of where its loop cannot go on: backing up to see
// an obstacle's base or off a contact, stepping away to see the floor the
// camera cannot see near a stop, and the way home (explorer_loop.h).
#include "pirouette/run/explorer_loop.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <optional>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/explore/coarse_grid.h"
#include "pirouette/explore/configuration_space.h"
#include "pirouette/explore/distance_transform.h"
#include "pirouette/explore/path.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::run::internal {
namespace {

// Off a contact the robot backs over floor known free within this fraction
// of its radius (see BackOffContact).
constexpr double kBackOffWidthRadii = 0.5;
// Slack on the shortest back-off tried, for rounding in its steps.
constexpr double kBackOffSlackM = 1e-9;
// Fewer unknown cells than this near the last stop are its own footprint's
// rim and specks: not worth a trip (StepAwayToSeeNearby).
constexpr std::size_t kMinNearbyUnknown = 4;
// Stepping away to see nearby unknown floor: how far past the camera's
// near range (cells), and in how many directions, π / kStepAwayHalfTurnSteps
// (30°) apart, alternating either side of straight away.
constexpr double kStepAwayPastNearCells = 3.0;
constexpr int kStepAwayDirections = 12;
constexpr double kStepAwayHalfTurnSteps = 6.0;
// Step-aways a run makes at most (each a short trip and a pirouette).
constexpr int kMaxStepAways = 8;
// Probing across the blind ring: headings tried (360° / kProbeHeadings
// apart), how far past the near range a probe may end (coarse cells), and
// probes a run makes at most.
constexpr int kProbeHeadings = 36;
constexpr double kProbePastNearCoarse = 2.0;
constexpr int kMaxProbes = 16;
// Tries to plan home again after a way home was blocked.
constexpr int kReturnHomeAttempts = 5;

}  // namespace

bool Explorer::BackUpOverKnownFree(double half_width_m, double longest_m, double shortest_m) {
  const core::Pose2 pose = Pose();
  const mapping::TrinaryMap known = mapper_.grid().ToTrinary();  // once for every length tried
  for (double back = longest_m; back > shortest_m - kBackOffSlackM; back -= cell_m_) {
    if (mapping::CorridorKnownFree(known, pose.translation(),
                                   pose.translation() - back * pose.Direction(), half_width_m)) {
      ++result_.backups;
      Drive(-back);
      return true;
    }
  }
  return false;
}

void Explorer::BackUpToSee() {
  const double near = look_.options().near_m;
  if (BackUpOverKnownFree(radius_m_, near, near)) Look();
}

void Explorer::BackOffContact() {
  // As far as the known-free floor behind allows, from the near range down
  // to a radius: clear of what it touches, the robot can turn away, and in a
  // corridor's bend a wall less than the near range behind it would refuse
  // every back-off (maze 103: its disc on a wall's end, 40 moves in a row
  // stopped at once, `stuck`).
  if (BackUpOverKnownFree(kBackOffWidthRadii * radius_m_, look_.options().near_m, radius_m_)) {
    ++result_.contact_backoffs;
  }
}

Explorer::WorldCell Explorer::KeyOf(const Eigen::Vector2d& centre) const {
  return {std::llround(centre.x() / cell_m_ - 0.5), std::llround(centre.y() / cell_m_ - 0.5)};
}

bool Explorer::StepAwayToSeeNearby() {
  if (!last_pirouette_) return false;
  const mapping::TrinaryMap map = mapper_.grid().ToTrinary();
  std::vector<WorldCell> nearby;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  ForEachUnknownNear(map, *last_pirouette_, NearBlindRadius(), [&](std::size_t i) {
    const Eigen::Vector2d centre = map.geometry.CellCentre(map.geometry.Unflat(i));
    const WorldCell key = KeyOf(centre);
    if (given_up_.contains(key)) return;
    nearby.push_back(key);
    sum += centre;
  });
  // Ignore the robot's own footprint's rim and specks: not worth a trip.
  if (nearby.size() < kMinNearbyUnknown || step_aways_ >= kMaxStepAways) {
    GiveUpNearby(nearby, nearby.size() < kMinNearbyUnknown
                             ? "unknown near a stop, too little for a trip to see it"
                             : "unknown near a stop, after as many step-aways as a run makes");
    return false;
  }
  ++step_aways_;
  const Eigen::Vector2d here = Pose().translation();
  const Eigen::Vector2d centroid = sum / static_cast<double>(nearby.size());
  const double away = std::atan2(here.y() - centroid.y(), here.x() - centroid.x());
  const double distance = look_.options().near_m + kStepAwayPastNearCells * cell_m_;
  for (int k = 0; k < kStepAwayDirections; ++k) {
    // Directions away from the unknown first, alternating either side.
    const int steps = (k + 1) / 2;  // 0, 1, 1, 2, 2, ...
    const double offset = (k % 2 == 0 ? 1 : -1) * steps * std::numbers::pi / kStepAwayHalfTurnSteps;
    const double heading = away + offset;
    const Eigen::Vector2d to =
        here + distance * Eigen::Vector2d(std::cos(heading), std::sin(heading));
    if (!mapping::CorridorKnownFree(map, here, to, radius_m_)) continue;
    explore::Plan plan;
    plan.waypoints_world = {to};
    if (Follow(plan).outcome == FollowOutcome::kReached) Pirouette();
    break;
  }
  // Whatever near the old stop is still unknown cannot be seen: give it up.
  std::vector<WorldCell> unseen;
  for (const WorldCell& key : nearby) {
    const core::CellIndex c = mapper_.grid().geometry().CellOf(CentreOf(key));
    if (mapper_.grid().State(c) == mapping::CellState::kUnknown) unseen.push_back(key);
  }
  GiveUpNearby(unseen, "unknown near a stop, unseen after stepping away to look back");
  return true;
}

bool Explorer::ProbeAcrossTheBlindRing(const mapping::TrinaryMap& planning) {
  if (!AtLastPirouette() || result_.probes >= kMaxProbes) return false;
  const explore::CoarseGrid grid = explore::PlanningGrid(planning, planner_options_);
  const explore::DistanceField field = explore::ChamferDistanceTransform(grid);
  const core::GridGeometry& coarse = grid.geometry();
  const Eigen::Vector2d here = Pose().translation();
  const auto reachable = [&](const Eigen::Vector2d& p) -> std::optional<std::int32_t> {
    const std::optional<core::CellIndex> c = coarse.CellAt(p);
    if (!c || grid.At(*c) == explore::CoarseCell::kBlocked) return std::nullopt;
    const std::int32_t d = field.At(*c);
    if (d >= explore::kUnreachable) return std::nullopt;
    return d;
  };
  if (reachable(here)) return false;  // the planner's business, not a probe's
  const mapping::OccupancyGrid& occupancy = mapper_.grid();
  const core::GridGeometry& g = occupancy.geometry();
  const double half = look_.SweptHalfWidth();  // the look's swept corridor
  // Whether a cell within `half` of the segment here -> to was hit (a blind
  // area or nothing seen is what a probe crosses; a hit is not).
  const auto hit_on_the_way = [&](const Eigen::Vector2d& to) {
    return core::AnyCellNearSegment(g, here, to, half, [&](const core::CellIndex& c) {
      return g.Contains(c) && occupancy.State(c) == mapping::CellState::kOccupied &&
             !occupancy.BlindOnly(c);
    });
  };
  const WorldCell place = KeyOf(here);
  const double near = look_.options().near_m;
  struct Candidate {
    std::int32_t distance;  // from its end to unknown space, the field's units
    double length;
    int heading;
    Eigen::Vector2d to;
  };
  std::optional<Candidate> best;
  for (int k = 0; k < kProbeHeadings; ++k) {
    if (probes_tried_.contains({place, k})) continue;
    const double heading = 2.0 * std::numbers::pi * k / kProbeHeadings;
    const Eigen::Vector2d direction(std::cos(heading), std::sin(heading));
    for (double length = cell_m_; length <= near + kProbePastNearCoarse * coarse_m_;
         length += cell_m_) {
      const Eigen::Vector2d to = here + length * direction;
      const std::optional<std::int32_t> distance = reachable(to);
      if (!distance) continue;
      if (!hit_on_the_way(to) &&
          (!best || std::pair(*distance, length) < std::pair(best->distance, best->length))) {
        best = Candidate{*distance, length, k, to};
      }
      break;
    }
  }
  if (!best) return false;
  ++result_.probes;
  probes_tried_.insert({place, best->heading});
  explore::Plan plan;
  plan.waypoints_world = {best->to};
  if (Follow(plan).outcome == FollowOutcome::kReached) Pirouette();
  return true;
}

bool Explorer::ReturnHome() {
  for (int attempt = 0; attempt < kReturnHomeAttempts; ++attempt) {
    explore::PlannerOptions planner_options;
    planner_options.robot_radius_m = radius_m_;
    // The robot stands where it stands and stood at its start: nothing under
    // its disc in either place is in the way, whatever the map says (a wall
    // mapped a cell thick beside it, as for exploring's plans).
    mapping::TrinaryMap map = mapper_.grid().ToTrinary();
    explore::ClearFootprint(map, Pose().translation(), radius_m_);
    explore::ClearFootprint(map, start_pose_.translation(), radius_m_);
    explore::CoarseGrid grid = explore::PlanningGrid(map, planner_options);
    const std::optional<core::CellIndex> home = grid.geometry().CellAt(start_pose_.translation());
    const std::optional<core::CellIndex> here = grid.geometry().CellAt(Pose().translation());
    if (!home || !here) return false;
    for (int y = 0; y < grid.height(); ++y) {
      for (int x = 0; x < grid.width(); ++x) {
        if (grid.At({x, y}) == explore::CoarseCell::kGoal) {
          grid.Set({x, y}, explore::CoarseCell::kBlocked);
        }
      }
    }
    grid.Set(*home, explore::CoarseCell::kGoal);
    const explore::DistanceField field = explore::ChamferDistanceTransform(grid);
    const std::optional<explore::Path> path = explore::SteepestDescent(grid, field, *here);
    if (!path) return false;
    explore::Plan plan = explore::PlanAlong(grid, *path, Pose().translation(), /*enter_goal=*/true);
    plan.waypoints_world.push_back(start_pose_.translation());
    if (Follow(plan).outcome == FollowOutcome::kReached) {
      Turn(core::NormalizeAngle(start_pose_.heading() - Pose().heading()));
      result_.path.push_back(Pose());
      return true;
    }
    if (!result_.status.empty()) return false;
  }
  return false;
}

}  // namespace pirouette::run::internal
