// The exploration loop (Taylor, Geva & Boles 2005, §4); the class is
// declared in explorer_loop.h, its recovery moves are in explorer_recovery.cc.
#include "pirouette/run/explorer.h"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <optional>
#include <thread>
#include <utility>
#include <vector>

#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/input_error.h"
#include "pirouette/explore/configuration_space.h"
#include "pirouette/explore/frontier_planner.h"
#include "pirouette/explore/moves.h"
#include "pirouette/robot/robot_error.h"
#include "pirouette/run/explorer_loop.h"
#include "pirouette/run/stage_timer.h"

namespace pirouette::run {
namespace internal {
namespace {

// Plans in a row blocked by what the robot saw before moving, before the
// run ends "stuck"; every kFailuresPerGiveUp of them the goal is given up,
// so the planner tries others first.
constexpr int kMaxFailures = 40;
constexpr int kFailuresPerGiveUp = 4;
// Plans in a row after which the robot had not moved: a guard against a
// planning loop that never moves (no shipped world comes near it).
constexpr int kMaxIdlePlans = 500;
// Trips a run makes at most to see again from a second place the floor one
// place saw free (Explorer::CorroborationMap), as a fraction of the
// pirouettes made so far: a bound on what they cost (in a maze, whose
// corridors each stop sees alone, they would double the run). With the
// trips' own pirouettes counted, trips <= pirouettes / 4 keeps them under a
// third of the exploring pirouettes.
constexpr int kCorroborationTripsPerPirouettes = 4;
// The wall error a plan through a passage the robot's own radius closes
// allows for (Explorer::narrower_planner_), in map cells: walls are mapped
// up to a cell thicker than they are (wall_error_m, a cell at most on the
// generated worlds within the bounds); the rest of the radius must stay at
// least kMinNarrowerRadiusShare of it, or there is no such planner.
constexpr double kWallErrorCells = 1.0;
constexpr double kMinNarrowerRadiusShare = 0.5;
// Turns smaller than this are not made (radians).
constexpr double kMinTurnRad = 1e-9;
// A waypoint is reached within this many cells; a straight move that made
// less than this stopped at once.
constexpr double kReachedCells = 0.25;
// Bisections for the point of a leg where the goal comes into view, between
// two samples half a cell apart: 30 take it far below a cell.
constexpr int kViewPointBisections = 30;
// A goal is in view when no obstacle lies within this many map cells of the
// line of sight to it (StopWhereTheGoalIsInView).
constexpr double kSightLineHalfCells = 1.0;

}  // namespace

Explorer::Explorer(robot::Robot& robot, const RobotDescription& description,
                   const ExplorationOptions& options, FrameMasks masks,
                   const ExplorationObserver& observer)
    : options_(options),
      observer_(observer),
      cell_m_(options.cell_m > 0.0 ? options.cell_m
                                   : mapping::DefaultCellSize(description.radius_m)),
      radius_m_(description.radius_m),
      robot_(robot),
      mapper_(MapperSetup{description.camera, description.radius_m, cell_m_,
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
              std::move(masks), robot.Odometry()),
      look_(mapper_.look_ahead()),
      start_(Clock::now()) {
  planner_options_.robot_radius_m = radius_m_;
  planner_ = options.planner == PlannerKind::kFrontier
                 ? explore::MakeFrontierPlanner(planner_options_)
                 : explore::MakeDistanceTransformPlanner(planner_options_);
  coarse_m_ = planner_options_.CoarseFactor(cell_m_) * cell_m_;
  const auto make = [&](const explore::PlannerOptions& o) {
    return options.planner == PlannerKind::kFrontier ? explore::MakeFrontierPlanner(o)
                                                     : explore::MakeDistanceTransformPlanner(o);
  };
  explore::PlannerOptions fine = planner_options_;
  fine.coarse_factor = 1;
  if (planner_options_.CoarseFactor(cell_m_) > 1) fine_planner_ = make(fine);
  explore::PlannerOptions narrower = fine;
  narrower.robot_radius_m = radius_m_ - kWallErrorCells * cell_m_;
  if (narrower.robot_radius_m >= kMinNarrowerRadiusShare * radius_m_) {
    narrower_planner_ = make(narrower);
  }
}

ExplorationResult Explorer::Run() {
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
  }
  TakeGraphOutcome(mapper_, result_);
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
  result_.colour_map = mapper_.MakeColourMap();
  result_.grid = mapper_.TakeGrid();
  return std::move(result_);
}

void Explorer::Loop() {
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
    // Every plan below starts from the one planning map: nothing changes
    // the map until a plan is followed.
    std::optional<explore::Plan> plan;
    const mapping::TrinaryMap planning = [this] {
      run::StageTimer timer(result_.times.plan_s);
      return PlanningMap();
    }();
    {
      run::StageTimer timer(result_.times.plan_s);
      plan = planner_->Next(planning, Pose());
    }
    if (!plan) {
      run::StageTimer timer(result_.times.plan_s);
      plan = PlanOutOfTheBlindArea(planning);
    }
    bool verifying = false;  // the plan goes to look again at what one look closed
    if (!plan) {
      run::StageTimer timer(result_.times.plan_s);
      plan = planner_->Next(VerificationMap(planning), Pose());
      verifying = plan.has_value();
    }
    explore::Planner* planner = planner_.get();  // the planner that made the plan
    // The plan passes where the coarse grid (or the robot's radius, less a
    // cell of wall error) closes the way: a look that blocks it gives its
    // goal up at once.
    bool fine = false;
    if (!plan && fine_planner_) {
      // The coarse grid closes a passage whose clearance is under about two
      // coarse cells (explore::DefaultCoarseFactor): a doorway or a maze's
      // corridor just wider than the robot. Where it has no plan left, the
      // map's own cells may still have one; a look that blocks such a plan
      // gives its goal up at once, not counted toward stuck.
      run::StageTimer timer(result_.times.plan_s);
      plan = fine_planner_->Next(planning, Pose());
      if (plan) planner = fine_planner_.get();
      fine = plan.has_value();
    }
    bool corroborating = false;  // the plan goes to see from a second place what one saw free
    // The budget grows with the run: exploring may go on after a trip (in
    // a maze, from a place that sees round a corner the stops before did
    // not), and its pirouettes leave more floor seen from one place.
    const int corroboration_budget = (result_.pirouettes + kCorroborationTripsPerPirouettes - 1) /
                                     kCorroborationTripsPerPirouettes;
    if (!plan && corroboration_trips_ < corroboration_budget) {
      run::StageTimer timer(result_.times.plan_s);
      const mapping::TrinaryMap corroboration = CorroborationMap(planning);
      plan = planner_->Next(corroboration, Pose());
      if (!plan && fine_planner_) {
        // As when exploring: the floor to see again may lie past a doorway
        // the coarse grid closes (the robot came in through it).
        plan = fine_planner_->Next(corroboration, Pose());
        if (plan) planner = fine_planner_.get();
      }
      corroborating = plan.has_value();
      if (corroborating) ++corroboration_trips_;
    }
    if (!plan && narrower_planner_) {
      // The last plan: through a passage that one cell of wall error on each
      // side closes (see narrower_planner_). A look that blocks it gives its
      // goal up at once, as for the fine planner's.
      run::StageTimer timer(result_.times.plan_s);
      plan = narrower_planner_->Next(planning, Pose());
      if (plan) planner = narrower_planner_.get();
      fine = plan.has_value();
    }
    if (!plan) {
      plan_.clear();
      if (!ProbeAcrossTheBlindRing(planning) && !StepAwayToSeeNearby()) result_.status = "complete";
      continue;
    }
    StopWhereTheGoalIsInView(*plan, planning);
    plan_ = plan->waypoints_world;
    Snapshot();
    if (plan->waypoints_world.empty() && AtLastPirouette()) {
      // Already looked all round from here and the goal stays unknown:
      // it cannot be seen from here; the planner is not to offer it again.
      GiveUp(*planner, *plan, "still unknown after a pirouette where the robot stands");
      continue;
    }
    const Followed followed = Follow(*plan);
    const FollowOutcome outcome = followed.outcome;
    if ((outcome == FollowOutcome::kReached && AtLastPirouette()) ||
        (outcome == FollowOutcome::kBlocked && (corroborating || fine))) {
      // Reached: the plan's waypoints were all where the robot stands
      // (within a quarter cell), and looking all round again would show
      // nothing new. Blocked on a second look: nothing was left to explore,
      // and a second look is not worth a stuck run.
      if (outcome == FollowOutcome::kReached) {
        GiveUp(*planner, *plan, "reached, after a pirouette there had left it unknown");
      } else {
        GiveUp(
            *planner, *plan,
            fmt::format("{} blocked: {}",
                        corroborating                        ? "a second look's way"
                        : planner == narrower_planner_.get() ? "a way for a robot a cell narrower"
                                                             : "a way on the map's own cells",
                        followed.blocked_by));
      }
    } else if (outcome == FollowOutcome::kReached) {
      failures = 0;
      Pirouette();
      // It has looked again: what the evidence opened is planned as usual,
      // and the goal is not checked again.
      if (verifying || corroborating) planner->ReportUnreachable(*plan);
    } else if (outcome == FollowOutcome::kBlocked) {
      if (++failures % kFailuresPerGiveUp == 0) {
        GiveUp(*planner, *plan,
               fmt::format("{} plans in a row blocked: {}", failures, followed.blocked_by));
      }
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

bool Explorer::Interrupted() {
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

void Explorer::WaitWhilePaused() const {
  constexpr auto kPoll = std::chrono::milliseconds(50);
  while (options_.control != nullptr && options_.control->pause.load() &&
         !options_.control->stop.load() &&
         (options_.stop_requested == nullptr || !options_.stop_requested->load())) {
    std::this_thread::sleep_for(kPoll);
  }
}

const FrameMapper::Seen& Explorer::Look() {
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

core::MoveOutcome Explorer::Execute(const core::Move& move) {
  core::MoveOutcome outcome = robot_.Execute(move);
  motions_since_frame_.push_back(outcome);
  return outcome;
}

void Explorer::Turn(double radians) {
  if (std::abs(radians) < kMinTurnRad) return;
  Execute(core::Move::Turn(radians));
  ++result_.turns;
  result_.rotation_deg += std::abs(radians) * 180.0 / std::numbers::pi;
}

void Explorer::Face(double radians) {
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

bool Explorer::Drive(double metres) {
  const core::MoveOutcome outcome = Execute(core::Move::Straight(metres));
  looked_since_drive_ = false;
  ++result_.moves;
  result_.path_length_m += std::abs(outcome.achieved);
  result_.path.push_back(mapper_.ToMap(outcome.odometry));
  if (outcome.stopped_at_contact) {
    ++result_.contacts;
    mapper_.AddContact(outcome.odometry);
    Look();
    // Stopped at once: the robot was already touching something, most
    // likely beside its front, where neither the bump (put straight ahead)
    // nor the camera says. Every move that way would stop at once again
    // (under odometry error this ended runs `stuck`), so back off first.
    if (metres > 0.0 && std::abs(outcome.achieved) < kReachedCells * cell_m_) BackOffContact();
  }
  Report();
  const int max_steps = options_.max_steps > 0 ? options_.max_steps : kDefaultMaxSteps;
  if (result_.moves >= max_steps && result_.status.empty()) {
    result_.status = "step-limit";
  }
  return !outcome.stopped_at_contact;
}

void Explorer::Pirouette() {
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

Explorer::Followed Explorer::Follow(const explore::Plan& plan) {
  for (const Eigen::Vector2d& target :
       explore::MergeCollinear(Pose().translation(), plan.waypoints_world)) {
    while (true) {
      if (!result_.status.empty() || Interrupted()) return {FollowOutcome::kStopped, {}};
      const core::Pose2 pose = Pose();
      const Eigen::Vector2d to = target - pose.translation();
      const double distance = to.norm();
      if (distance < kReachedCells * cell_m_) break;
      Face(core::NormalizeAngle(std::atan2(to.y(), to.x()) - pose.heading()));
      const double leg = std::min(distance, look_.LongestCheckedMove());
      const core::ObstacleProfile& profile = Look().profile;
      const explore::LookAhead::Finding finding = look_.Blocking(profile, leg);
      const explore::LookVerdict verdict = finding.verdict;
      // A view filled by something near vouches for nothing; the map may,
      // for the look's own corridor (CorridorKnownFree adding the cells its
      // rim touches): with the disc's whole rim, a robot the planner put
      // beside a wall's end (its disc 3 mm off the face) was refused every
      // move there (maze 108, `stuck` after 40 refusals).
      if (verdict == explore::LookVerdict::kBlind &&
          !mapping::CorridorKnownFree(mapper_.grid().ToExploredMap(), pose.translation(),
                                      pose.translation() + leg * Pose().Direction(),
                                      look_.SweptHalfWidth())) {
        BackUpToSee();
        ++result_.blocked_looks;
        return {FollowOutcome::kBlocked, "the view ahead was filled by something near"};
      }
      if (verdict == explore::LookVerdict::kBlocked) {
        mapper_.ConfirmBlocking(profile, last_seen_.pose, leg);
        if (observer_.on_blocked) observer_.on_blocked(leg);
        ++result_.blocked_looks;
        return {FollowOutcome::kBlocked, "the look before a move saw an obstacle on the leg"};
      }
      // Past where the floor ahead is unresolved the frame vouches for
      // nothing: go as far as it does, and look again from there.
      const double vouched = std::min(leg, finding.seen_m);
      if (vouched < kReachedCells * cell_m_) {
        ++result_.blocked_looks;
        return {FollowOutcome::kBlocked, "the look before a move did not see the floor ahead"};
      }
      if (!Drive(vouched)) {
        return {FollowOutcome::kBlocked, "a contact stopped a move"};
      }
    }
  }
  return {FollowOutcome::kReached, {}};
}

void Explorer::GiveUp(explore::Planner& planner, const explore::Plan& plan, std::string why) {
  planner.ReportUnreachable(plan);
  result_.given_up.push_back({plan.goal_world, Pose().translation(), std::move(why), 0});
}

void Explorer::GiveUpNearby(const std::vector<WorldCell>& cells, std::string why) {
  if (cells.empty()) return;
  Eigen::Vector2d sum = Eigen::Vector2d::Zero();
  for (const WorldCell& key : cells) {
    sum += CentreOf(key);
    given_up_.insert(key);
  }
  result_.given_up.push_back({sum / static_cast<double>(cells.size()), Pose().translation(),
                              std::move(why), static_cast<int>(cells.size())});
}

mapping::TrinaryMap Explorer::PlanningMap() const {
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
  // Where the robot stands nothing is in its way, whatever the map says of
  // the cells under its disc (a wall mapped a cell thick beside it).
  explore::ClearFootprint(map, Pose().translation(), radius_m_);
  return map;
}

mapping::TrinaryMap Explorer::VerificationMap(const mapping::TrinaryMap& planning) const {
  mapping::TrinaryMap map = planning;
  const mapping::OccupancyGrid& occupancy = mapper_.grid();
  const core::GridGeometry& g = map.geometry;
  const Eigen::Vector2d here = Pose().translation();
  const double near = NearBlindRadius();
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const core::CellIndex c{x, y};
      mapping::CellState& state = map.cells[g.Flat(c)];
      if (state != mapping::CellState::kOccupied || !occupancy.OnOneLook(c)) continue;
      if ((g.CellCentre(c) - here).norm() <= near) continue;
      state = mapping::CellState::kFree;
    }
  }
  return map;
}

mapping::TrinaryMap Explorer::CorroborationMap(const mapping::TrinaryMap& planning) const {
  mapping::TrinaryMap map = planning;
  const mapping::OccupancyGrid& occupancy = mapper_.grid();
  const core::GridGeometry& g = map.geometry;
  const Eigen::Vector2d here = Pose().translation();
  for (std::size_t i = 0; i < map.cells.size(); ++i) {
    if (map.cells[i] != mapping::CellState::kFree) continue;
    if (occupancy.WouldCorroborate(g.Unflat(i), here)) map.cells[i] = mapping::CellState::kUnknown;
  }
  return map;
}

std::optional<explore::Plan> Explorer::PlanOutOfTheBlindArea(const mapping::TrinaryMap& planning) {
  if (!AtLastPirouette()) return std::nullopt;
  mapping::TrinaryMap map = planning;
  const core::Pose2 pose = Pose();
  const explore::CoarseGrid grid = explore::PlanningGrid(map, planner_options_);
  const std::optional<core::CellIndex> here = grid.geometry().CellAt(pose.translation());
  if (!here || grid.At(*here) != explore::CoarseCell::kBlocked) return std::nullopt;
  // The blind cells whose growth by the radius can reach the robot's coarse
  // cell: within the radius of it, and no farther.
  const mapping::OccupancyGrid& occupancy = mapper_.grid();
  const core::GridGeometry& g = map.geometry;
  const double radius = radius_m_ + std::numbers::sqrt2 * coarse_m_;
  const Eigen::Vector2d& centre = pose.translation();
  const core::CellIndex lo = g.CellOf(centre - Eigen::Vector2d(radius, radius));
  const core::CellIndex hi = g.CellOf(centre + Eigen::Vector2d(radius, radius));
  bool freed = false;
  for (int y = std::max(0, lo.y); y <= std::min(g.height() - 1, hi.y); ++y) {
    for (int x = std::max(0, lo.x); x <= std::min(g.width() - 1, hi.x); ++x) {
      const core::CellIndex c{x, y};
      if ((g.CellCentre(c) - centre).norm() > radius || !occupancy.BlindOnly(c)) continue;
      map.cells[g.Flat(c)] = mapping::CellState::kFree;
      freed = true;
    }
  }
  if (!freed) return std::nullopt;
  return planner_->Next(map, pose);
}

void Explorer::StopWhereTheGoalIsInView(explore::Plan& plan,
                                        const mapping::TrinaryMap& planning) const {
  const double view = ViewDistance();
  const mapping::OccupancyGrid& occupancy = mapper_.grid();
  const core::GridGeometry& g = planning.geometry;
  // In view: past the camera's near range and within the view distance, and
  // no obstacle the map holds (a blind area is not one) across the line of
  // sight short of the goal's own coarse cell.
  const auto in_view = [&](const Eigen::Vector2d& p) {
    const Eigen::Vector2d to_goal = plan.goal_world - p;
    const double distance = to_goal.norm();
    if (distance > view || distance < look_.options().near_m) return false;
    const double short_of_goal = distance - 0.5 * coarse_m_;
    if (short_of_goal <= 0.0) return true;
    const Eigen::Vector2d end = p + to_goal * (short_of_goal / distance);
    return !core::AnyCellNearSegment(
        g, p, end, kSightLineHalfCells * cell_m_, [&](const core::CellIndex& c) {
          return g.Contains(c) && planning.cells[g.Flat(c)] == mapping::CellState::kOccupied &&
                 !occupancy.BlindOnly(c);
        });
  };
  Eigen::Vector2d from = Pose().translation();
  std::vector<Eigen::Vector2d> kept;
  for (const Eigen::Vector2d& to : plan.waypoints_world) {
    if (in_view(from)) break;
    const Eigen::Vector2d d = to - from;
    // The first point of the leg in view, sampled every half cell (sight
    // lines open and close along a leg: a distance alone is not monotone
    // enough to bisect the whole leg).
    const int samples = std::max(1, static_cast<int>(std::ceil(d.norm() / (0.5 * cell_m_))));
    int first = 1;
    while (first <= samples && !in_view(from + (static_cast<double>(first) / samples) * d)) ++first;
    if (first > samples) {
      kept.push_back(to);
      from = to;
      continue;
    }
    // The point between the last sample out of view and the first in it.
    double lo = static_cast<double>(first - 1) / samples;
    double hi = static_cast<double>(first) / samples;
    for (int i = 0; i < kViewPointBisections; ++i) {
      const double mid = 0.5 * (lo + hi);
      (in_view(from + mid * d) ? hi : lo) = mid;
    }
    kept.emplace_back(from + hi * d);
    break;
  }
  // (Where no point of it is in view, the whole path is kept: the robot
  // goes to the last free coarse cell before the goal and looks from there.)
  plan.waypoints_world = std::move(kept);
}

ExplorationProgress Explorer::Progress() const {
  ExplorationProgress progress;
  progress.moves = result_.moves;
  progress.pirouettes = result_.pirouettes;
  progress.known_area_m2 = static_cast<double>(mapper_.grid().KnownCellCount()) * cell_m_ * cell_m_;
  progress.elapsed_s = run::Seconds(Clock::now() - start_);
  return progress;
}

void Explorer::Report() {
  if (observer_.on_progress) observer_.on_progress(Progress());
  Snapshot();
}

void Explorer::Snapshot() {
  if (!observer_.on_snapshot) return;
  const core::Pose2 odom_T_robot = robot_.Odometry();
  const core::Pose2 map_T_robot = mapper_.ToMap(odom_T_robot);
  observer_.on_snapshot(RunSnapshot{mapper_.grid(), result_.path, result_.stops, plan_, map_T_robot,
                                    map_T_robot * odom_T_robot.Inverse(), last_seen_.bgr,
                                    last_seen_.mask, result_.frames, Progress()});
}

}  // namespace internal

ExplorationResult ExploreWithRobot(robot::Robot& robot, const RobotDescription& description,
                                   const ExplorationOptions& options, FrameMasks masks,
                                   const ExplorationObserver& observer) {
  CheckExplorationOptions(options);
  if (!(description.radius_m > 0.0) || !std::isfinite(description.radius_m)) {
    throw core::InputError("robot radius", 0, "", "must be a number > 0 (metres)");
  }
  internal::Explorer explorer(robot, description, options, std::move(masks), observer);
  return explorer.Run();
}

void TakeGraphOutcome(const FrameMapper& mapper, ExplorationResult& result) {
  const auto& graph = mapper.graph();
  if (!graph) return;
  result.graph = graph->graph();
  result.frame_stops.clear();
  for (std::size_t k = 0; k < graph->FrameCount(); ++k) {
    result.frame_stops.push_back(graph->StopOf(k));
  }
  result.loop_closures_accepted = graph->loop_closures_accepted();
  result.loop_reach_m = graph->OverlapReachM();
  result.loop_closures_rejected = graph->loop_closures_rejected();
  result.scan_matches = graph->scan_matches();
  result.optimise_s = graph->optimise_s();
  result.per_stop_s = graph->per_stop_s();
  result.rebuild_s = mapper.rebuild_s();
  result.rebuilds = mapper.rebuilds();
}

}  // namespace pirouette::run
