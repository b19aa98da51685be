#pragma once

// Internal to run/: the class behind ExploreWithRobot (run/explorer.h, the
// interface to include). explorer.cc holds the loop, explorer_recovery.cc the
// ways out of where the loop cannot go on (backing up to see or off a
// contact, stepping away to see nearby floor, the way home).

#include <Eigen/Core>
#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "pirouette/core/grid_geometry.h"
#include "pirouette/core/move.h"
#include "pirouette/core/pose2.h"
#include "pirouette/explore/look_ahead.h"
#include "pirouette/explore/planner.h"
#include "pirouette/mapping/trinary_map.h"
#include "pirouette/run/explorer.h"
#include "pirouette/run/frame_mapper.h"

namespace pirouette::run::internal {

using Clock = std::chrono::steady_clock;

// The loop of one exploration, through any robot.
class Explorer {
 public:
  Explorer(robot::Robot& robot, const RobotDescription& description,
           const ExplorationOptions& options, FrameMasks masks,
           const ExplorationObserver& observer);

  // The whole run; a robot that fails (robot::RobotError: it stopped
  // answering, dropped the connection, answered garbage) ends it with status
  // "stuck" and the map so far.
  ExplorationResult Run();

 private:
  enum class FollowOutcome { kReached, kBlocked, kStopped };
  struct Followed {
    FollowOutcome outcome = FollowOutcome::kReached;
    std::string_view blocked_by;  // kBlocked: by what, for given_up's why
  };

  // --- The loop (explorer.cc).

  void Loop();

  // Where the robot is in the map: its odometry, corrected by the tracker.
  core::Pose2 Pose() const { return mapper_.ToMap(robot_.Odometry()); }

  bool Interrupted();

  bool HomeRequested() const {
    return options_.control != nullptr && options_.control->home.load();
  }

  // Stands still while a live view holds the run paused (and nothing ends it).
  void WaitWhilePaused() const;

  // Takes a frame, reads its obstacle profile and puts it in the map; the
  // motions since the previous frame go with it to the observer (a log).
  const FrameMapper::Seen& Look();

  core::MoveOutcome Execute(const core::Move& move);

  void Turn(double radians);

  // Turns to face a leg, which the caller then looks along. With tracking,
  // a turn is made in steps no larger than a pirouette's with a look after
  // each (and one before the first, where the robot has not looked since it
  // drove), so that the tracker matches every frame against one it overlaps
  // and a turn's error does not go unseen into the map.
  void Face(double radians);

  // A straight move as made; false when it stopped at contact (the robot
  // then looks at what it touched, which maps the bumper's hit with it).
  bool Drive(double metres);

  void Pirouette();

  // Follows a plan's waypoints: for each leg, face it, then in pieces no
  // longer than the camera checks, look and drive.
  Followed Follow(const explore::Plan& plan);

  // Tells `planner` the plan's goal is not to be offered again and records
  // it, with `why`, in the result's given_up.
  void GiveUp(explore::Planner& planner, const explore::Plan& plan, std::string why);

  // The map the planner sees: unknown cells the robot cannot see from here
  // (under the camera, within its near range, when it has just looked all
  // round) and those it gave up on count as free, and so do the cells under
  // the robot's disc (explore::ClearFootprint: a plan starts where it stands).
  mapping::TrinaryMap PlanningMap() const;

  // The planning map without what single looks alone say is in the way
  // (OccupancyGrid::OnOneLook: a blind area, a cell one hit marks), for a plan
  // when the planning map has none: a phantom hit where a vertical edge cuts
  // a column of the tilted camera's picture, or a blind area that reaches
  // through a thin wall into the corridor behind it, grown by the robot's
  // radius closes a corridor as narrow as a maze's, and the run would end
  // complete with the space beyond unseen. A plan on this map takes the robot
  // where it sees that evidence again from elsewhere (the look before every
  // move stops it where an obstacle is really in the way, and confirms it);
  // its goal is given up once the robot has looked all round there, so each
  // goal is checked once. The cells within NearBlindRadius of the robot keep
  // their evidence: the camera cannot look at them from here.
  mapping::TrinaryMap VerificationMap(const mapping::TrinaryMap& planning) const;

  // The planning map in which the floor seen free from one place only, from
  // far enough away that a look from here would make it free from two
  // (OccupancyGrid::WouldCorroborate), counts as unknown: for a plan when
  // there is nothing else to explore, so that the map of record
  // (OccupancyGrid::ToMapOfRecord), which calls free only what two places saw
  // free, covers the floor. Each such goal is tried once: given up once the
  // robot has looked all round there, or at once when a look blocks the way;
  // at most a quarter as many trips as pirouettes so far. Planned
  // on the coarse grid, else on the map's own cells (a doorway the coarse
  // grid closes may lie between the robot and that floor).
  mapping::TrinaryMap CorroborationMap(const mapping::TrinaryMap& planning) const;

  // A plan out of the camera's blind area at the robot's feet, when the
  // planner found none because the robot's own coarse cell is blocked: where
  // a view was filled by something near (a wall a few centimetres off), the
  // cells out to the near range are a blind area, which counts as an obstacle
  // and, grown by the robot's radius, covers where it stands (nearly always at
  // the start, before anything around it was seen). The blind cells whose
  // growth reaches the robot's coarse cell (within a radius and a coarse
  // cell's diagonal of it) then count as free for this one plan: they are as
  // unknowable from here as the unknown ones PlanningMap frees, the rest of
  // the blind area still keeps plans out, and the look before every move
  // checks the floor before the robot drives. Nothing unless boxed in like
  // that, just after a pirouette.
  std::optional<explore::Plan> PlanOutOfTheBlindArea(const mapping::TrinaryMap& planning);

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
  WorldCell KeyOf(const Eigen::Vector2d& centre) const;
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

  // The robot need not drive into the unknown to see it, and cannot see it
  // from too near (the camera sees no floor nearer than its near range):
  // the plan ends at the first point of its path from which the goal is in
  // view: past the near range, within the view distance, and with no
  // obstacle of `planning` (a wall's end at a maze's corner; a blind area is
  // not one) across the line of sight to the goal's coarse cell. Where no
  // point of the path is, the whole path is followed.
  void StopWhereTheGoalIsInView(explore::Plan& plan, const mapping::TrinaryMap& planning) const;

  ExplorationProgress Progress() const;

  void Report();

  // The run as it stands, to the live views.
  void Snapshot();

  // --- Recovery (explorer_recovery.cc).

  // Backs straight up by the longest distance from `longest_m` down to
  // `shortest_m`, in steps of a cell, over which the map knows the floor
  // behind is free within `half_width_m` of the path (counted in backups);
  // returns whether it did.
  bool BackUpOverKnownFree(double half_width_m, double longest_m, double shortest_m);

  // The paper's unfinished active vision: an obstacle's base hides in the
  // blind area under the camera, so back up, where the map knows the floor
  // behind is free, and look again.
  void BackUpToSee();

  // Backs away from a contact, by the camera's near range or less (a radius
  // at least), where the floor behind is known free within
  // half the robot's radius of its path: a robot touching a wall it has
  // mapped a few centimetres off (odometry error) overlaps that wall in the
  // map, so the whole disc's corridor would refuse the very back-off that
  // frees it.
  void BackOffContact();

  // When the only unknown space left is under the camera's near range around
  // the robot, drive away from it, where the map knows the floor is free, and
  // look back. What stays unknown after that is given up. False when there is
  // nothing to see or nowhere to go.
  bool StepAwayToSeeNearby();
  // Records unknown cells near a stop given up together (given_up_).
  void GiveUpNearby(const std::vector<WorldCell>& cells, std::string why);

  // Out of the ring the camera cannot see, when no plan starts here: in a
  // corridor narrower than twice the camera's near range (a maze's) the
  // views across it are filled by its walls, whose blind areas, grown by
  // the radius, close every way out of the robot's coarse cell, though the
  // pirouette saw the corridor's floor beyond the ring. Picks the heading
  // whose nearest point past the ring the planner can go on from (a coarse
  // cell from which unknown space is reachable), with no hit (only blind or
  // unknown cells) within the swept corridor on the way, and follows that one
  // leg: the look before the move checks, as for any leg, that the frame
  // facing it shows the floor past the ring across the whole swept corridor
  // (anything tall enough to matter standing in the ring would fill the
  // bottom of the picture instead: LookVerdict::kBlind), and a contact stops
  // the rest. Each heading is tried once from a place; at most kMaxProbes a
  // run. False when there is no such heading.
  bool ProbeAcrossTheBlindRing(const mapping::TrinaryMap& planning);

  // Back to the start over known-free floor: the distance transform from the
  // start's coarse cell alone, the unknown counted as blocked, the cells under
  // the robot's disc where it stands and at the start counted free
  // (explore::ClearFootprint).
  // True when the robot reached its start.
  bool ReturnHome();

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
  explore::PlannerOptions planner_options_;
  std::unique_ptr<explore::Planner> planner_;
  // The same planner on a coarse grid of one map cell, for the plans the
  // coarse grid has none of (see Loop); none where the coarse factor is 1.
  std::unique_ptr<explore::Planner> fine_planner_;
  // The fine planner for a robot a cell of wall error narrower
  // (kWallErrorCells), for a plan when no other has one (see Loop): a maze's
  // corridor of three radii leaves the robot's centre a band of about two
  // cells, which a wall mapped a cell thick on each side closes, and a
  // phantom speck beside a wall's end closes a passage likewise; the run
  // would end complete with the maze beyond it unseen. The look before every
  // move checks each leg against what the camera sees, and the bumper stops
  // the rest. None where the radius is under two cells.
  std::unique_ptr<explore::Planner> narrower_planner_;
  std::optional<Eigen::Vector2d> last_pirouette_;
  core::Pose2 start_pose_;
  std::set<WorldCell> given_up_;  // unknown cells the robot gave up seeing
  int step_aways_ = 0;
  std::set<std::pair<WorldCell, int>> probes_tried_;  // (place, heading) probed
  int corroboration_trips_ = 0;
  bool looked_since_drive_ = false;            // a frame was taken where the robot stands
  std::vector<std::size_t> pirouette_frames_;  // each pirouette's first frame
  Clock::time_point start_;
};

}  // namespace pirouette::run::internal
