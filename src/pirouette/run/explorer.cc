#include "pirouette/run/explorer.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <memory>
#include <numbers>
#include <set>
#include <stdexcept>
#include <thread>
#include <utility>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/input_error.h"
#include "pirouette/explore/distance_transform.h"
#include "pirouette/explore/frontier_planner.h"
#include "pirouette/explore/look_ahead.h"
#include "pirouette/explore/moves.h"
#include "pirouette/explore/path.h"
#include "pirouette/explore/planner.h"
#include "pirouette/mapping/trinary_map.h"
#include "pirouette/robot/robot_error.h"
#include "pirouette/run/frame_mapper.h"
#include "pirouette/run/stage_timer.h"

namespace pirouette::run {
namespace {

using Clock = std::chrono::steady_clock;

// The loop of one exploration, through any robot.
class Explorer {
 public:
  Explorer(robot::Robot& robot, const RobotDescription& description,
           const ExplorationOptions& options, MaskFunction mask,
           const ExplorationObserver& observer)
      : options_(options),
        observer_(observer),
        cell_m_(options.cell_m > 0.0 ? options.cell_m
                                     : mapping::DefaultCellSize(description.radius_m)),
        radius_m_(description.radius_m),
        robot_(robot),
        mapper_(
            MapperSetup{description.camera, description.radius_m, cell_m_,
                        options.max_range_m > 0.0 ? options.max_range_m
                                                  : camera::MaxRange(description.camera, cell_m_),
                        options.occupancy,
                        options.localize == LocalizeKind::kScan
                            ? std::optional<localize::TrackerOptions>(options.tracker)
                            : std::nullopt,
                        options.localize == LocalizeKind::kGraph
                            ? std::optional<localize::GraphTrackerOptions>(options.graph)
                            : std::nullopt,
                        options.max_map_m},
            std::move(mask), robot.Odometry()),
        look_(mapper_.look_ahead()),
        start_(Clock::now()) {
    explore::PlannerOptions planner_options;
    planner_options.robot_radius_m = radius_m_;
    planner_ = options.planner == PlannerKind::kFrontier
                   ? explore::MakeFrontierPlanner(planner_options)
                   : explore::MakeDistanceTransformPlanner(planner_options);
    coarse_m_ = planner_options.CoarseFactor(cell_m_) * cell_m_;
  }

  // The whole run; a robot that fails (robot::RobotError: it stopped
  // answering, dropped the connection, answered garbage) ends it with status
  // "stuck" and the map so far.
  ExplorationResult Run() {
    try {
      Loop();
    } catch (const robot::RobotError& e) {
      result_.status = "stuck";
      result_.reason = e.what();
    } catch (const mapping::MapTooLarge& e) {
      // The frame was refused before it changed the map: the map so far stands.
      result_.status = "stuck";
      result_.reason = e.what();
    }
    try {
      result_.final_pose = Pose();
    } catch (const robot::RobotError&) {
      // A robot that stopped answering has no final pose to give.
    }
    mapper_.Finish();
    if (const auto& graph = mapper_.graph()) {
      // The path and the stops where the graph now puts them.
      result_.path.clear();
      for (const core::Pose2& p : graph->graph().poses()) result_.path.push_back(p);
      for (std::size_t i = 0; i < result_.stops.size(); ++i) {
        result_.stops[i] = mapper_.FramePoses().at(pirouette_frames_[i]);
      }
      result_.graph = graph->graph();
      result_.loop_closures_accepted = graph->loop_closures_accepted();
      result_.loop_closures_rejected = graph->loop_closures_rejected();
      result_.scan_matches = graph->scan_matches();
      result_.optimise_s = graph->optimise_s();
      result_.per_stop_s = graph->per_stop_s();
      result_.rebuild_s = mapper_.rebuild_s();
      result_.rebuilds = mapper_.rebuilds();
    }
    result_.final_frame_poses = mapper_.FramePoses();
    result_.wall_time_s = run::Seconds(Clock::now() - start_);
    result_.times.perceive_s = mapper_.perceive_s();
    result_.times.update_s = mapper_.update_s();
    result_.times.localize_s = mapper_.localize_s();
    if (mapper_.tracker()) {
      result_.corrections = mapper_.tracker()->accepted();
      result_.matches = mapper_.tracker()->matches();
      result_.scan_matches = mapper_.tracker()->scan_matches();
    }
    result_.colour_sightings = mapper_.ColourSightings();
    result_.grid = mapper_.TakeGrid();
    return std::move(result_);
  }

 private:
  enum class FollowOutcome { kReached, kBlocked, kStopped };
  // Plans in a row blocked by what the robot saw before moving, before the
  // run ends "stuck"; every kFailuresPerGiveUp of them the goal is given up,
  // so the planner tries others first.
  static constexpr int kMaxFailures = 40;
  static constexpr int kFailuresPerGiveUp = 4;
  // Plans in a row after which the robot had not moved: a guard against a
  // planning loop that never moves (no shipped world comes near it).
  static constexpr int kMaxIdlePlans = 500;
  // Turns smaller than this are not made (radians).
  static constexpr double kMinTurnRad = 1e-9;
  // A waypoint is reached within this many cells; a straight move that made
  // less than this stopped at once.
  static constexpr double kReachedCells = 0.25;
  // Off a contact the robot backs over floor known free within this fraction
  // of its radius (see BackOffContact).
  static constexpr double kBackOffWidthRadii = 0.5;
  // Fewer unknown cells than this near the last stop are its own footprint's
  // rim and specks: not worth a trip (StepAwayToSeeNearby).
  static constexpr std::size_t kMinNearbyUnknown = 4;
  // Stepping away to see nearby unknown floor: how far past the camera's
  // near range (cells), and in how many directions, π / kStepAwayHalfTurnSteps
  // (30°) apart, alternating either side of straight away.
  static constexpr double kStepAwayPastNearCells = 3.0;
  static constexpr int kStepAwayDirections = 12;
  static constexpr double kStepAwayHalfTurnSteps = 6.0;
  // Bisections for the point of a leg at the view distance of the goal: 30
  // halve the leg to a billionth, far below a cell.
  static constexpr int kViewPointBisections = 30;
  // Tries to plan home again after a way home was blocked.
  static constexpr int kReturnHomeAttempts = 5;

  void Loop() {
    start_pose_ = Pose();
    result_.path.push_back(start_pose_);
    Pirouette();
    int failures = 0;  // plans in a row that could not be followed
    int idle = 0;      // plans in a row after which the robot had not moved
    int moves_before = result_.moves;
    while (result_.status.empty()) {
      if (Interrupted()) break;
      if (HomeRequested()) break;
      idle = result_.moves == moves_before ? idle + 1 : 0;
      moves_before = result_.moves;
      if (idle > kMaxIdlePlans) {
        // A guard: planning that never moves the robot must not spin forever.
        result_.status = "stuck";
        result_.reason = fmt::format("{} plans in a row did not move the robot", idle);
        break;
      }
      std::optional<explore::Plan> plan;
      {
        run::StageTimer timer(result_.times.plan_s);
        plan = planner_->Next(PlanningMap(), Pose());
      }
      if (!plan) {
        plan_.clear();
        if (!StepAwayToSeeNearby()) result_.status = "complete";
        continue;
      }
      StopWhereTheGoalIsInView(*plan);
      plan_ = plan->waypoints_world;
      Snapshot();
      if (plan->waypoints_world.empty() && AtLastPirouette()) {
        // Already looked all round from here and the goal stays unknown:
        // it cannot be seen from here; the planner is not to offer it again.
        planner_->ReportUnreachable(*plan);
        continue;
      }
      const FollowOutcome outcome = Follow(*plan);
      if (outcome == FollowOutcome::kReached && AtLastPirouette()) {
        // The plan's waypoints were all where the robot stands (within a
        // quarter cell): looking all round again would show nothing new.
        planner_->ReportUnreachable(*plan);
      } else if (outcome == FollowOutcome::kReached) {
        failures = 0;
        Pirouette();
      } else if (outcome == FollowOutcome::kBlocked) {
        if (++failures % kFailuresPerGiveUp == 0) planner_->ReportUnreachable(*plan);
        if (failures >= kMaxFailures) {
          result_.status = "stuck";
          result_.reason = fmt::format(
              "{} plans in a row were blocked by what the robot saw before moving", failures);
        }
      }
    }
    if (HomeRequested() && result_.status.empty()) {
      const bool home = ReturnHome();
      if (result_.status.empty()) {
        result_.status = "interrupted";
        result_.reason = home ? "sent home from the live view"
                              : "sent home from the live view, but found no way home over known "
                                "free floor";
      }
      return;
    }
    if (result_.status == "complete" && options_.return_home) {
      result_.status.clear();
      ReturnHome();
      if (result_.status.empty()) result_.status = "complete";
    }
  }

  // Where the robot is in the map: its odometry, corrected by the tracker.
  core::Pose2 Pose() const { return mapper_.ToMap(robot_.Odometry()); }

  bool Interrupted() {
    WaitWhilePaused();
    if (options_.stop_requested != nullptr && options_.stop_requested->load()) {
      result_.status = "interrupted";
      return true;
    }
    if (options_.control != nullptr && options_.control->stop.load()) {
      result_.status = "interrupted";
      result_.reason = "stopped from the live view";
      return true;
    }
    return false;
  }

  bool HomeRequested() const {
    return options_.control != nullptr && options_.control->home.load();
  }

  // Stands still while a live view holds the run paused (and nothing ends it).
  void WaitWhilePaused() const {
    constexpr auto kPoll = std::chrono::milliseconds(50);
    while (options_.control != nullptr && options_.control->pause.load() &&
           !options_.control->stop.load() &&
           (options_.stop_requested == nullptr || !options_.stop_requested->load())) {
      std::this_thread::sleep_for(kPoll);
    }
  }

  // Takes a frame, reads its obstacle profile and puts it in the map; the
  // motions since the previous frame go with it to the observer (a log).
  const FrameMapper::Seen& Look() {
    const robot::Frame frame = robot_.Capture();
    looked_since_drive_ = true;
    ++result_.frames;
    if (observer_.on_capture) observer_.on_capture(frame, motions_since_frame_);
    motions_since_frame_.clear();
    last_seen_ = mapper_.AddFrame(frame);
    result_.frame_poses.push_back(last_seen_.pose);
    if (observer_.on_frame) {
      observer_.on_frame({last_seen_.bgr, last_seen_.mask, last_seen_.pose, mapper_.grid()});
    }
    return last_seen_;
  }

  core::MoveOutcome Execute(const core::Move& move) {
    core::MoveOutcome outcome = robot_.Execute(move);
    motions_since_frame_.push_back(outcome);
    return outcome;
  }

  void Turn(double radians) {
    if (std::abs(radians) < kMinTurnRad) return;
    Execute(core::Move::Turn(radians));
    ++result_.turns;
    result_.rotation_deg += std::abs(radians) * 180.0 / std::numbers::pi;
  }

  // Turns to face a leg, which the caller then looks along. With tracking,
  // a turn is made in steps no larger than a pirouette's with a look after
  // each (and one before the first, where the robot has not looked since it
  // drove), so that the tracker matches every frame against one it overlaps
  // and a turn's error does not go unseen into the map.
  void Face(double radians) {
    if (options_.localize == LocalizeKind::kNone || std::abs(radians) < kMinTurnRad) {
      Turn(radians);
      return;
    }
    if (!looked_since_drive_) Look();
    const double most = 2.0 * std::numbers::pi / core::kPirouetteTurns;
    const int steps = static_cast<int>(std::ceil(std::abs(radians) / most - 1e-9));
    for (int i = 0; i < steps; ++i) {
      Turn(radians / steps);
      if (i + 1 < steps) Look();
    }
  }

  // A straight move as made; false when it stopped at contact (the robot
  // then looks at what it touched, which maps the bumper's hit with it).
  bool Drive(double metres) {
    const core::MoveOutcome outcome = Execute(core::Move::Straight(metres));
    looked_since_drive_ = false;
    ++result_.moves;
    result_.path_length_m += std::abs(outcome.achieved);
    result_.path.push_back(mapper_.ToMap(outcome.odometry));
    if (outcome.stopped_at_contact) {
      mapper_.AddContact(outcome.odometry);
      Look();
      // Stopped at once: the robot was already touching something, most
      // likely beside its front, where neither the bump (put straight ahead)
      // nor the camera says. Every move that way would stop at once again
      // (under odometry error this ended runs `stuck`), so back off first.
      if (metres > 0.0 && std::abs(outcome.achieved) < kReachedCells * cell_m_) BackOffContact();
    }
    Report();
    if (result_.moves >= options_.max_steps && result_.status.empty()) {
      result_.status = "step-limit";
    }
    return !outcome.stopped_at_contact;
  }

  void Pirouette() {
    const int turns = core::kPirouetteTurns;
    const auto first_frame = static_cast<std::size_t>(result_.frames);
    for (int i = 0; i < turns; ++i) {
      if (Interrupted()) return;  // a real robot's pirouette takes a while
      Look();
      Turn(2.0 * std::numbers::pi / turns);
    }
    ++result_.pirouettes;
    result_.stops.push_back(Pose());
    pirouette_frames_.push_back(first_frame);
    last_pirouette_ = Pose().translation();
    Report();
  }

  // Follows a plan's waypoints: for each leg, face it, then in pieces no
  // longer than the camera checks, look and drive.
  FollowOutcome Follow(const explore::Plan& plan) {
    for (const Eigen::Vector2d& target :
         explore::MergeCollinear(Pose().translation(), plan.waypoints_world)) {
      while (true) {
        if (!result_.status.empty() || Interrupted()) return FollowOutcome::kStopped;
        const core::Pose2 pose = Pose();
        const Eigen::Vector2d to = target - pose.translation();
        const double distance = to.norm();
        if (distance < kReachedCells * cell_m_) break;
        Face(core::NormalizeAngle(std::atan2(to.y(), to.x()) - pose.heading()));
        const double leg = std::min(distance, look_.LongestCheckedMove());
        const core::ObstacleProfile& profile = Look().profile;
        const explore::LookAhead::Finding finding = look_.Blocking(profile, leg);
        const explore::LookVerdict verdict = finding.verdict;
        if (verdict == explore::LookVerdict::kBlind &&
            !mapping::CorridorKnownFree(mapper_.grid().ToExploredMap(), pose.translation(),
                                        pose.translation() + leg * Pose().Direction(), radius_m_)) {
          BackUpToSee();
          ++result_.blocked_looks;
          return FollowOutcome::kBlocked;
        }
        if (verdict == explore::LookVerdict::kBlocked) {
          mapper_.ConfirmBlocking(profile, last_seen_.pose, leg);
          if (observer_.on_blocked) observer_.on_blocked(leg);
          ++result_.blocked_looks;
          return FollowOutcome::kBlocked;
        }
        if (!Drive(leg)) return FollowOutcome::kBlocked;
      }
    }
    return FollowOutcome::kReached;
  }

  // Backs straight up by the camera's near blind range where the map knows
  // the floor behind is free within `half_width_m` of the path (counted in
  // backups); returns whether it did.
  bool BackUpOverKnownFree(double half_width_m) {
    const double back = look_.options().near_m;
    const core::Pose2 pose = Pose();
    if (!mapping::CorridorKnownFree(mapper_.grid().ToTrinary(), pose.translation(),
                                    pose.translation() - back * pose.Direction(), half_width_m)) {
      return false;
    }
    ++result_.backups;
    Drive(-back);
    return true;
  }

  // The paper's unfinished active vision: an obstacle's base hides in the
  // blind area under the camera, so back up, where the map knows the floor
  // behind is free, and look again.
  void BackUpToSee() {
    if (BackUpOverKnownFree(radius_m_)) Look();
  }

  // Backs away from a contact where the floor behind is known free within
  // half the robot's radius of its path: a robot touching a wall it has
  // mapped a few centimetres off (odometry error) overlaps that wall in the
  // map, so the whole disc's corridor would refuse the very back-off that
  // frees it.
  void BackOffContact() {
    if (BackUpOverKnownFree(kBackOffWidthRadii * radius_m_)) ++result_.contact_backoffs;
  }

  // The map the planner sees: unknown cells the robot cannot see from here
  // (under the camera, within its near range, when it has just looked all
  // round) and those it gave up on count as free.
  mapping::TrinaryMap PlanningMap() const {
    mapping::TrinaryMap map = mapper_.grid().ToExploredMap();
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
    return last_pirouette_ && (Pose().translation() - *last_pirouette_).norm() < cell_m_;
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
      given_up_.insert(nearby.begin(), nearby.end());
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
      const double offset =
          (k % 2 == 0 ? 1 : -1) * steps * std::numbers::pi / kStepAwayHalfTurnSteps;
      const double heading = away + offset;
      const Eigen::Vector2d to =
          here + distance * Eigen::Vector2d(std::cos(heading), std::sin(heading));
      if (!mapping::CorridorKnownFree(map, here, to, radius_m_)) continue;
      explore::Plan plan;
      plan.waypoints_world = {to};
      if (Follow(plan) == FollowOutcome::kReached) Pirouette();
      break;
    }
    // Whatever near the old stop is still unknown cannot be seen: give it up.
    for (const WorldCell& key : nearby) {
      const core::CellIndex c = mapper_.grid().geometry().CellOf(CentreOf(key));
      if (mapper_.grid().State(c) == mapping::CellState::kUnknown) given_up_.insert(key);
    }
    return true;
  }

  // The robot need not drive into the unknown to see it, and cannot see it
  // from too near (the camera sees no floor nearer than its near range):
  // the plan ends at the first point of its path within the view distance
  // of the goal.
  void StopWhereTheGoalIsInView(explore::Plan& plan) const {
    const double view = ViewDistance();
    Eigen::Vector2d from = Pose().translation();
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
      for (int i = 0; i < kViewPointBisections; ++i) {
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
  // True when the robot reached its start.
  bool ReturnHome() {
    for (int attempt = 0; attempt < kReturnHomeAttempts; ++attempt) {
      explore::PlannerOptions planner_options;
      planner_options.robot_radius_m = radius_m_;
      explore::CoarseGrid grid = explore::PlanningGrid(mapper_.grid().ToTrinary(), planner_options);
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
      explore::Plan plan =
          explore::PlanAlong(grid, *path, Pose().translation(), /*enter_goal=*/true);
      plan.waypoints_world.push_back(start_pose_.translation());
      if (Follow(plan) == FollowOutcome::kReached) {
        Turn(core::NormalizeAngle(start_pose_.heading() - Pose().heading()));
        result_.path.push_back(Pose());
        return true;
      }
      if (!result_.status.empty()) return false;
    }
    return false;
  }

  ExplorationProgress Progress() const {
    ExplorationProgress progress;
    progress.moves = result_.moves;
    progress.pirouettes = result_.pirouettes;
    progress.known_area_m2 =
        static_cast<double>(mapper_.grid().KnownCellCount()) * cell_m_ * cell_m_;
    progress.elapsed_s = run::Seconds(Clock::now() - start_);
    return progress;
  }

  void Report() {
    if (observer_.on_progress) observer_.on_progress(Progress());
    Snapshot();
  }

  // The run as it stands, to the live views.
  void Snapshot() {
    if (!observer_.on_snapshot) return;
    const core::Pose2 odom_T_robot = robot_.Odometry();
    const core::Pose2 map_T_robot = mapper_.ToMap(odom_T_robot);
    observer_.on_snapshot(RunSnapshot{mapper_.grid(), result_.path, result_.stops, plan_,
                                      map_T_robot, map_T_robot * odom_T_robot.Inverse(),
                                      last_seen_.bgr, last_seen_.mask, result_.frames, Progress()});
  }

  // Step-aways a run makes at most (each a short trip and a pirouette).
  static constexpr int kMaxStepAways = 8;

  ExplorationOptions options_;
  const ExplorationObserver& observer_;
  double cell_m_;
  double radius_m_;
  double coarse_m_ = 0.0;
  ExplorationResult result_;
  robot::Robot& robot_;
  FrameMapper mapper_;
  const explore::LookAhead& look_;
  FrameMapper::Seen last_seen_;
  std::vector<core::MoveOutcome> motions_since_frame_;
  std::vector<Eigen::Vector2d> plan_;  // the plan being followed, for the live views
  std::unique_ptr<explore::Planner> planner_;
  std::optional<Eigen::Vector2d> last_pirouette_;
  core::Pose2 start_pose_;
  std::set<WorldCell> given_up_;  // unknown cells the robot gave up seeing
  int step_aways_ = 0;
  bool looked_since_drive_ = false;            // a frame was taken where the robot stands
  std::vector<std::size_t> pirouette_frames_;  // each pirouette's first frame
  Clock::time_point start_;
};

}  // namespace

ExplorationResult ExploreWithRobot(robot::Robot& robot, const RobotDescription& description,
                                   const ExplorationOptions& options, MaskFunction mask,
                                   const ExplorationObserver& observer) {
  CheckExplorationOptions(options);
  if (!(description.radius_m > 0.0) || !std::isfinite(description.radius_m)) {
    throw core::InputError("robot radius", 0, "", "must be a number > 0 (metres)");
  }
  Explorer explorer(robot, description, options, std::move(mask), observer);
  return explorer.Run();
}

}  // namespace pirouette::run
