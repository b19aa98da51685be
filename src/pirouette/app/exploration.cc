#include "pirouette/app/exploration.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <set>
#include <stdexcept>
#include <utility>

#include "pirouette/app/image_io.h"
#include "pirouette/app/look_ahead.h"
#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/input_error.h"
#include "pirouette/explore/distance_transform.h"
#include "pirouette/explore/frontier_planner.h"
#include "pirouette/explore/path.h"
#include "pirouette/explore/planner.h"
#include "pirouette/mapping/range_sensor_model.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/sim/sim_robot.h"
#include "pirouette/vision/profile_extractor.h"

namespace pirouette::app {
namespace {

using Clock = std::chrono::steady_clock;

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// Adds the time from construction to destruction to a counter.
class StageTimer {
 public:
  explicit StageTimer(double& total) : total_(total), start_(Clock::now()) {}
  ~StageTimer() { total_ += Seconds(Clock::now() - start_); }
  StageTimer(const StageTimer&) = delete;
  StageTimer& operator=(const StageTimer&) = delete;

 private:
  double& total_;
  Clock::time_point start_;
};

// The grid the robot starts with: 2 m square around its start, on whole
// cells; it grows as the robot sees farther.
mapping::OccupancyGrid InitialGrid(const core::Pose2& start, double cell_m,
                                   const mapping::OccupancyOptions& occupancy) {
  constexpr double kHalf = 1.0;
  const Eigen::Vector2d lo(std::floor((start.x() - kHalf) / cell_m) * cell_m,
                           std::floor((start.y() - kHalf) / cell_m) * cell_m);
  return mapping::OccupancyGrid(
      core::GridGeometry::Covering(cell_m, lo, Eigen::Vector2d(2 * kHalf, 2 * kHalf)), occupancy);
}

// The loop of one exploration; owns the simulated robot and the perception.
class Explorer {
 public:
  Explorer(const sim::World& world, const ExplorationOptions& options,
           const ExplorationObserver& observer)
      : world_(world),
        options_(options),
        observer_(observer),
        cell_m_(options.cell_m > 0.0 ? options.cell_m : DefaultCellSize(world)),
        max_range_m_(options.max_range_m > 0.0 ? options.max_range_m
                                               : camera::MaxRange(world.robot().camera, cell_m_)),
        radius_m_(world.robot().radius),
        renderer_(world, world.robot().camera, RenderOptionsFor(options)),
        robot_(world, options.seed,
               [this](const core::Pose2& world_T_robot) {
                 StageTimer timer(result_.times.render_s);
                 return renderer_.Render(world_T_robot);
               }),
        ipm_(world.robot().camera),
        extractor_(ipm_, max_range_m_),
        masker_(options.method, world, world.robot().camera),
        look_(LookAheadOptions{radius_m_, NearRange(ipm_), max_range_m_, cell_m_}),
        start_(Clock::now()) {
    explore::PlannerOptions planner_options;
    planner_options.robot_radius_m = radius_m_;
    planner_ = options.planner == PlannerKind::kFrontier
                   ? explore::MakeFrontierPlanner(planner_options)
                   : explore::MakeDistanceTransformPlanner(planner_options);
    coarse_m_ = planner_options.CoarseFactor(cell_m_) * cell_m_;
    result_.grid = InitialGrid(robot_.Odometry(), cell_m_, options.occupancy);
  }

  ExplorationResult Run() {
    start_pose_ = robot_.Odometry();
    result_.path.push_back(start_pose_);
    Pirouette();
    int failures = 0;  // plans in a row that could not be followed
    while (result_.status.empty()) {
      if (Interrupted()) break;
      std::optional<explore::Plan> plan;
      {
        StageTimer timer(result_.times.plan_s);
        plan = planner_->Next(PlanningMap(), robot_.Odometry());
      }
      if (!plan) {
        if (!StepAwayToSeeNearby()) result_.status = "complete";
        continue;
      }
      StopWhereTheGoalIsInView(*plan);
      if (plan->waypoints_world.empty() && AtLastPirouette()) {
        // Already looked all round from here and the goal stays unknown:
        // it cannot be seen from here; the planner is not to offer it again.
        planner_->ReportUnreachable(*plan);
        continue;
      }
      const FollowOutcome outcome = Follow(*plan);
      if (outcome == FollowOutcome::kReached) {
        failures = 0;
        Pirouette();
      } else if (outcome == FollowOutcome::kBlocked) {
        if (++failures % 4 == 0) planner_->ReportUnreachable(*plan);
        if (failures >= kMaxFailures) {
          result_.status = "stuck";
          result_.reason = fmt::format(
              "{} plans in a row were blocked by what the robot saw before moving", failures);
        }
      }
    }
    if (result_.status == "complete" && options_.return_home) {
      result_.status.clear();
      ReturnHome();
      if (result_.status.empty()) result_.status = "complete";
    }
    result_.final_true_pose = robot_.TruePose();
    result_.wall_time_s = Seconds(Clock::now() - start_);
    return std::move(result_);
  }

 private:
  enum class FollowOutcome { kReached, kBlocked, kStopped };
  static constexpr int kMaxFailures = 40;

  static sim::RenderOptions RenderOptionsFor(const ExplorationOptions& options) {
    sim::RenderOptions render;
    render.seed = options.seed;
    return render;
  }

  bool Interrupted() {
    if (options_.stop_requested != nullptr && options_.stop_requested->load()) {
      result_.status = "interrupted";
      return true;
    }
    return false;
  }

  // Takes a frame, reads its obstacle profile and puts it in the map.
  core::ObstacleProfile Look() {
    const robot::Frame frame = robot_.Capture();
    ++result_.frames;
    cv::Mat3b bgr;
    cv::Mat1b mask;
    core::ObstacleProfile profile;
    {
      StageTimer timer(result_.times.perceive_s);
      bgr = ToBgrMat(frame.image);
      mask = masker_.Mask(bgr, robot_.TruePose());
      profile = extractor_.Extract(mask);
    }
    {
      StageTimer timer(result_.times.update_s);
      mapping::InsertProfile(result_.grid, profile, frame.odometry);
      mapping::MarkFootprintFree(result_.grid, frame.odometry.translation(), radius_m_);
    }
    if (observer_.on_frame) observer_.on_frame({bgr, mask, frame.odometry, result_.grid});
    return profile;
  }

  void Turn(double radians) {
    if (std::abs(radians) < 1e-9) return;
    robot_.Execute(robot::Move::Turn(radians));
    ++result_.turns;
    result_.rotation_deg += std::abs(radians) * 180.0 / std::numbers::pi;
  }

  // A straight move as made; false when it stopped at contact.
  bool Drive(double metres) {
    const robot::MoveOutcome outcome = robot_.Execute(robot::Move::Straight(metres));
    ++result_.moves;
    result_.path_length_m += std::abs(outcome.achieved);
    result_.path.push_back(outcome.odometry);
    {
      StageTimer timer(result_.times.update_s);
      mapping::MarkFootprintFree(result_.grid, outcome.odometry.translation(), radius_m_);
      if (outcome.stopped_at_contact) {
        // The bumper's reading: something touches the robot's front.
        core::ObstacleProfile bump;
        bump.max_range_m = radius_m_ + cell_m_;
        bump.readings.push_back({0.0, radius_m_ + 0.5 * cell_m_, core::ReadingKind::kHit});
        mapping::InsertProfile(result_.grid, bump, outcome.odometry);
      }
    }
    Report();
    if (result_.moves >= options_.max_steps && result_.status.empty()) {
      result_.status = "step-limit";
    }
    return !outcome.stopped_at_contact;
  }

  void Pirouette() {
    const int turns = options_.pirouette_turns;
    for (int i = 0; i < turns; ++i) {
      Look();
      Turn(2.0 * std::numbers::pi / turns);
    }
    ++result_.pirouettes;
    result_.stops.push_back(robot_.Odometry());
    last_pirouette_ = robot_.Odometry().translation();
    Report();
  }

  // Follows a plan's waypoints: for each leg, face it, then in pieces no
  // longer than the camera checks, look and drive.
  FollowOutcome Follow(const explore::Plan& plan) {
    for (const Eigen::Vector2d& target : MergeCollinear(plan.waypoints_world)) {
      while (true) {
        if (!result_.status.empty() || Interrupted()) return FollowOutcome::kStopped;
        const core::Pose2 pose = robot_.Odometry();
        const Eigen::Vector2d to = target - pose.translation();
        const double distance = to.norm();
        if (distance < 0.25 * cell_m_) break;
        Turn(core::NormalizeAngle(std::atan2(to.y(), to.x()) - pose.heading()));
        const double leg = std::min(distance, look_.LongestCheckedMove());
        const core::ObstacleProfile profile = Look();
        const LookAhead::Finding finding = look_.Blocking(profile, leg);
        const LookVerdict verdict = finding.verdict;
        if (verdict == LookVerdict::kBlind &&
            !CorridorKnownFree(result_.grid.ToExploredMap(), pose.translation(),
                               pose.translation() + leg * robot_.Odometry().Direction(),
                               radius_m_)) {
          BackUpToSee();
          ++result_.blocked_looks;
          return FollowOutcome::kBlocked;
        }
        if (verdict == LookVerdict::kBlocked) {
          ConfirmBlocking(finding.hits_robot);
          ++result_.blocked_looks;
          return FollowOutcome::kBlocked;
        }
        if (!Drive(leg)) return FollowOutcome::kBlocked;
      }
    }
    return FollowOutcome::kReached;
  }

  // The look found the way blocked: make sure the map says so, so that the
  // next plan goes another way (a cell the map thought free takes a few
  // looks' hits to read occupied).
  void ConfirmBlocking(const std::vector<Eigen::Vector2d>& hits_robot) {
    StageTimer timer(result_.times.update_s);
    const core::Pose2 pose = robot_.Odometry();
    for (int round = 0; round < 4; ++round) {
      result_.grid.BeginFrame();
      for (const Eigen::Vector2d& hit : hits_robot) {
        const core::CellIndex c = result_.grid.geometry().CellOf(pose * hit);
        if (result_.grid.LogOdds(c) <= 0.0F) result_.grid.Apply(c, mapping::CellUpdate::kHit);
      }
    }
  }

  // The waypoints without those in line with their neighbours: one look and
  // one drive a straight leg (as far as one look reaches).
  std::vector<Eigen::Vector2d> MergeCollinear(const std::vector<Eigen::Vector2d>& waypoints) const {
    std::vector<Eigen::Vector2d> merged;
    Eigen::Vector2d from = robot_.Odometry().translation();
    for (std::size_t i = 0; i < waypoints.size(); ++i) {
      if (i + 1 < waypoints.size()) {
        const Eigen::Vector2d a = (waypoints[i] - from).normalized();
        const Eigen::Vector2d b = (waypoints[i + 1] - waypoints[i]).normalized();
        if (a.dot(b) > 1.0 - 1e-6) continue;
      }
      merged.push_back(waypoints[i]);
      from = waypoints[i];
    }
    return merged;
  }

  // The paper's unfinished active vision: an obstacle's base hides in the
  // blind area under the camera, so back up, where the map knows the floor
  // behind is free, and look again.
  void BackUpToSee() {
    const double back = look_.options().near_m;
    const mapping::TrinaryMap map = result_.grid.ToTrinary();
    const core::Pose2 pose = robot_.Odometry();
    if (!CorridorKnownFree(map, pose.translation(), pose.translation() - back * pose.Direction(),
                           radius_m_)) {
      return;
    }
    ++result_.backups;
    Drive(-back);
    Look();
  }

  // The map the planner sees: unknown cells the robot cannot see from here
  // (under the camera, within its near range, when it has just looked all
  // round) and those it gave up on count as free.
  mapping::TrinaryMap PlanningMap() const {
    mapping::TrinaryMap map = result_.grid.ToExploredMap();
    for (const WorldCell& key : given_up_) {
      const std::optional<core::CellIndex> c = map.geometry.CellAt(CentreOf(key));
      if (!c) continue;
      mapping::CellState& state = map.cells[map.geometry.Flat(*c)];
      if (state == mapping::CellState::kUnknown) state = mapping::CellState::kFree;
    }
    if (AtLastPirouette()) {
      ForEachUnknownNear(map, *last_pirouette_, NearBlindRadius(),
                         [&](std::size_t i) { map.cells[i] = mapping::CellState::kFree; });
    }
    return map;
  }

  // The distance from which the robot looks at a goal cell: past the
  // camera's near range by a coarse cell, so that all of the cell is in view.
  double ViewDistance() const { return look_.options().near_m + coarse_m_; }
  // Unknown cells nearer than this to where the robot just looked all round
  // cannot be seen from there.
  bool AtLastPirouette() const {
    return last_pirouette_ && (robot_.Odometry().translation() - *last_pirouette_).norm() < cell_m_;
  }

  double NearBlindRadius() const { return ViewDistance() + cell_m_; }

  // A map cell named by its place in the world (the map's origin moves by
  // whole cells as it grows, so a flat index would name another cell).
  using WorldCell = std::pair<std::int64_t, std::int64_t>;
  WorldCell KeyOf(const Eigen::Vector2d& centre) const {
    return {std::llround(centre.x() / cell_m_ - 0.5), std::llround(centre.y() / cell_m_ - 0.5)};
  }
  Eigen::Vector2d CentreOf(const WorldCell& key) const {
    return {(static_cast<double>(key.first) + 0.5) * cell_m_,
            (static_cast<double>(key.second) + 0.5) * cell_m_};
  }

  template <typename F>
  static void ForEachUnknownNear(const mapping::TrinaryMap& map, const Eigen::Vector2d& centre,
                                 double radius, F&& f) {
    const core::GridGeometry& g = map.geometry;
    const core::CellIndex lo = g.CellOf(centre - Eigen::Vector2d(radius, radius));
    const core::CellIndex hi = g.CellOf(centre + Eigen::Vector2d(radius, radius));
    for (int y = std::max(0, lo.y); y <= std::min(g.height() - 1, hi.y); ++y) {
      for (int x = std::max(0, lo.x); x <= std::min(g.width() - 1, hi.x); ++x) {
        const core::CellIndex c{x, y};
        if ((g.CellCentre(c) - centre).norm() > radius) continue;
        const std::size_t i = g.Flat(c);
        if (map.cells[i] == mapping::CellState::kUnknown) f(i);
      }
    }
  }

  // When the only unknown space left is under the camera's near range around
  // the robot, drive away from it, where the map knows the floor is free, and
  // look back. What stays unknown after that is given up. False when there is
  // nothing to see or nowhere to go.
  bool StepAwayToSeeNearby() {
    if (!last_pirouette_) return false;
    const mapping::TrinaryMap map = result_.grid.ToTrinary();
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
    if (nearby.size() < 4 || step_aways_ >= kMaxStepAways) {
      given_up_.insert(nearby.begin(), nearby.end());
      return false;
    }
    ++step_aways_;
    const Eigen::Vector2d here = robot_.Odometry().translation();
    const Eigen::Vector2d centroid = sum / static_cast<double>(nearby.size());
    const double away = std::atan2(here.y() - centroid.y(), here.x() - centroid.x());
    const double distance = look_.options().near_m + 3.0 * cell_m_;
    for (int k = 0; k < 12; ++k) {
      // Directions away from the unknown first, alternating either side.
      const int steps = (k + 1) / 2;  // 0, 1, 1, 2, 2, ...
      const double offset = (k % 2 == 0 ? 1 : -1) * steps * std::numbers::pi / 6.0;
      const double heading = away + offset;
      const Eigen::Vector2d to =
          here + distance * Eigen::Vector2d(std::cos(heading), std::sin(heading));
      if (!CorridorKnownFree(map, here, to, radius_m_)) continue;
      explore::Plan plan;
      plan.waypoints_world = {to};
      if (Follow(plan) == FollowOutcome::kReached) Pirouette();
      break;
    }
    // Whatever near the old stop is still unknown cannot be seen: give it up.
    for (const WorldCell& key : nearby) {
      const core::CellIndex c = result_.grid.geometry().CellOf(CentreOf(key));
      if (result_.grid.State(c) == mapping::CellState::kUnknown) given_up_.insert(key);
    }
    return true;
  }

  // The robot need not drive into the unknown to see it, and cannot see it
  // from too near (the camera sees no floor nearer than its near range):
  // the plan ends at the first point of its path within the view distance
  // of the goal.
  void StopWhereTheGoalIsInView(explore::Plan& plan) const {
    const double view = ViewDistance();
    Eigen::Vector2d from = robot_.Odometry().translation();
    std::vector<Eigen::Vector2d> kept;
    for (const Eigen::Vector2d& to : plan.waypoints_world) {
      if ((from - plan.goal_world).norm() <= view) break;
      if ((to - plan.goal_world).norm() > view) {
        kept.push_back(to);
        from = to;
        continue;
      }
      // The point of the leg from -> to at the view distance of the goal.
      const Eigen::Vector2d d = to - from;
      double lo = 0.0;
      double hi = 1.0;
      for (int i = 0; i < 30; ++i) {
        const double mid = 0.5 * (lo + hi);
        ((from + mid * d - plan.goal_world).norm() > view ? lo : hi) = mid;
      }
      kept.emplace_back(from + hi * d);
      break;
    }
    plan.waypoints_world = std::move(kept);
  }

  // Back to the start over known-free floor: the distance transform from the
  // start's coarse cell alone, the unknown counted as blocked.
  void ReturnHome() {
    for (int attempt = 0; attempt < 5; ++attempt) {
      explore::PlannerOptions planner_options;
      planner_options.robot_radius_m = radius_m_;
      explore::CoarseGrid grid = explore::PlanningGrid(result_.grid.ToTrinary(), planner_options);
      const std::optional<core::CellIndex> home = grid.geometry().CellAt(start_pose_.translation());
      const std::optional<core::CellIndex> here =
          grid.geometry().CellAt(robot_.Odometry().translation());
      if (!home || !here) return;
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
      if (!path) return;
      explore::Plan plan =
          explore::PlanAlong(grid, *path, robot_.Odometry().translation(), /*enter_goal=*/true);
      plan.waypoints_world.push_back(start_pose_.translation());
      if (Follow(plan) == FollowOutcome::kReached) {
        Turn(core::NormalizeAngle(start_pose_.heading() - robot_.Odometry().heading()));
        result_.path.push_back(robot_.Odometry());
        return;
      }
      if (!result_.status.empty()) return;
    }
  }

  void Report() {
    if (!observer_.on_progress) return;
    ExplorationProgress progress;
    progress.moves = result_.moves;
    progress.pirouettes = result_.pirouettes;
    progress.known_area_m2 = static_cast<double>(result_.grid.KnownCellCount()) * cell_m_ * cell_m_;
    progress.elapsed_s = Seconds(Clock::now() - start_);
    observer_.on_progress(progress);
  }

  static constexpr int kMaxStepAways = 8;

  const sim::World& world_;
  ExplorationOptions options_;
  const ExplorationObserver& observer_;
  double cell_m_;
  double max_range_m_;
  double radius_m_;
  double coarse_m_ = 0.0;
  ExplorationResult result_;
  sim::Renderer renderer_;
  sim::SimRobot robot_;
  camera::InversePerspectiveMap ipm_;
  vision::ProfileExtractor extractor_;  // the profile tables, built once
  FloorMasker masker_;
  LookAhead look_;
  std::unique_ptr<explore::Planner> planner_;
  std::optional<Eigen::Vector2d> last_pirouette_;
  core::Pose2 start_pose_;
  std::set<WorldCell> given_up_;  // unknown cells the robot gave up seeing
  int step_aways_ = 0;
  Clock::time_point start_;
};

}  // namespace

std::string_view PlannerKindName(PlannerKind kind) {
  return kind == PlannerKind::kFrontier ? "frontier" : "dt";
}

std::optional<PlannerKind> ParsePlannerKind(std::string_view name) {
  if (name == "dt") return PlannerKind::kDistanceTransform;
  if (name == "frontier") return PlannerKind::kFrontier;
  return std::nullopt;
}

double DefaultCellSize(const sim::World& world) { return world.robot().radius < 0.1 ? 0.01 : 0.02; }

void CheckExplorationOptions(const ExplorationOptions& options) {
  try {
    options.occupancy.Check();
  } catch (const std::invalid_argument& e) {
    throw core::InputError("sensor model", 0, "", e.what());
  }
  if (options.max_steps < 1) {
    throw core::InputError("--max-steps", 0, "", "must be at least 1");
  }
  if (options.cell_m < 0.0 || !std::isfinite(options.cell_m) ||
      (options.cell_m > 0.0 && (options.cell_m < 0.002 || options.cell_m > 0.5))) {
    throw core::InputError("--cell", 0, "", "the map cell must be between 0.002 and 0.5 m");
  }
  if (options.max_range_m < 0.0 || !std::isfinite(options.max_range_m)) {
    throw core::InputError("--max-range", 0, "", "must be a number > 0 (metres)");
  }
  if (options.pirouette_turns < 4 || options.pirouette_turns > 72) {
    throw core::InputError("--turns", 0, "", "a pirouette has between 4 and 72 turns");
  }
}

ExplorationResult Explore(const sim::World& world, const ExplorationOptions& options,
                          const ExplorationObserver& observer) {
  CheckExplorationOptions(options);
  Explorer explorer(world, options, observer);
  return explorer.Run();
}

}  // namespace pirouette::app
