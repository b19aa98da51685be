#include "pirouette/run/frame_mapper.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <optional>
#include <utility>

#include "pirouette/core/angle.h"
#include "pirouette/io/image_io.h"
#include "pirouette/localize/colour_votes.h"
#include "pirouette/mapping/range_sensor_model.h"
#include "pirouette/run/stage_timer.h"
#include "pirouette/vision/column_colour.h"
#include "pirouette/vision/vertical_direction_field.h"

namespace pirouette::run {
namespace {

// kInitialSideM square around the start, on whole cells (the grid grows as
// readings need it, never past the setup's limit with room for the range on
// both sides and the graph's corrections: FrameMapper::CheckExtent refuses
// frames before the grid would).
mapping::OccupancyGrid InitialGrid(const core::Pose2& start, const MapperSetup& setup) {
  constexpr double kInitialSideM = 2.0;
  constexpr double kHalf = 0.5 * kInitialSideM;
  constexpr double kSlackM = 2.0;
  const double cell_m = setup.cell_m;
  const Eigen::Vector2d lo(std::floor((start.x() - kHalf) / cell_m) * cell_m,
                           std::floor((start.y() - kHalf) / cell_m) * cell_m);
  mapping::OccupancyGrid grid(
      core::GridGeometry::Covering(cell_m, lo, Eigen::Vector2d(2 * kHalf, 2 * kHalf)),
      setup.occupancy);
  const double side_cells =
      std::ceil((MaxMapSide(setup) + 2.0 * setup.max_range_m + kSlackM) / cell_m);
  grid.LimitSide(
      static_cast<int>(std::clamp(side_cells, static_cast<double>(grid.geometry().width()),
                                  static_cast<double>(mapping::OccupancyGrid::kMaxSideCells))));
  return grid;
}

}  // namespace

FrameMapper::FrameMapper(const MapperSetup& setup, FrameMasks masks, const core::Pose2& start)
    : setup_(setup),
      mask_(std::move(masks.mask)),
      unresolved_(std::move(masks.unresolved)),
      settling_left_(std::max(0, masks.settling_frames)),
      ipm_(setup.camera),
      extractor_(ipm_, setup.max_range_m, vision::VerticalDirectionField(setup.camera)),
      look_(explore::LookAheadOptions{setup.radius_m, camera::NearRange(ipm_), setup.max_range_m,
                                      setup.cell_m}),
      start_(start),
      grid_(InitialGrid(start, setup)) {
  if (setup.graph) {
    graph_.emplace(*setup.graph);
    view_extractor_.emplace(ipm_, setup.max_range_m * setup.graph->stop.view_range_factor,
                            extractor_.vertical());
  } else if (setup.tracking) {
    tracker_.emplace(*setup.tracking);
    view_extractor_.emplace(ipm_, setup.max_range_m * setup.tracking->view_range_factor,
                            extractor_.vertical());
  }
}

FrameMasks MasksOf(vision::FloorSegmenter& segmenter) {
  return {[&segmenter](const cv::Mat3b& bgr) { return segmenter.Segment(bgr); },
          segmenter.SettlingFrames(),
          [&segmenter]() -> const cv::Mat1b& { return segmenter.Unresolved(); }};
}

double MaxMapSide(const MapperSetup& setup) {
  return setup.max_map_m > 0.0 ? setup.max_map_m : kDefaultMaxMapCells * setup.cell_m;
}

void FrameMapper::CheckExtent(const core::Pose2& odometry) {
  const Eigen::Vector2d reach = Eigen::Vector2d::Constant(setup_.max_range_m);
  const Eigen::Vector2d lo = extent_lo_.cwiseMin(odometry.translation() - reach);
  const Eigen::Vector2d hi = extent_hi_.cwiseMax(odometry.translation() + reach);
  const double side = (hi - lo).maxCoeff();
  const double limit = MaxMapSide(setup_);
  if (!std::isfinite(side) || side > limit) {
    throw mapping::MapTooLarge(fmt::format(
        "the map would grow to {:.0f} m a side with the frame at odometry ({:.2f}, {:.2f}), past "
        "its limit of {:.0f} m (--max-map-m): the odometry jumped, or the floor is larger than "
        "the limit",
        side, odometry.x(), odometry.y(), limit));
  }
  extent_lo_ = lo;
  extent_hi_ = hi;
}

FrameMapper::Seen FrameMapper::AddFrame(const robot::Frame& frame) {
  if (settling_left_ == 0) return MapFrame(frame);
  CheckExtent(frame.odometry);
  Seen seen;
  {
    run::StageTimer timer(perceive_s_);
    seen.bgr = io::ToBgrMat(frame.image);
    seen.mask = mask_(seen.bgr);
    if (unresolved_) seen.unresolved = unresolved_().clone();
    seen.profile = extractor_.Extract(seen.mask, seen.unresolved);
  }
  seen.pose = ToMap(frame.odometry);
  settling_.push_back(frame);
  if (--settling_left_ > 0) return seen;
  return *MapSettlingFrames();
}

std::optional<FrameMapper::Seen> FrameMapper::MapSettlingFrames() {
  settling_left_ = 0;
  std::vector<robot::Frame> frames = std::move(settling_);
  settling_.clear();
  std::optional<Seen> last;
  for (const robot::Frame& f : frames) last = MapFrame(f);
  return last;
}

FrameMapper::Seen FrameMapper::MapFrame(const robot::Frame& frame) {
  CheckExtent(frame.odometry);
  Seen seen;
  {
    run::StageTimer timer(perceive_s_);
    seen.bgr = io::ToBgrMat(frame.image);
    seen.mask = mask_(seen.bgr);
    if (unresolved_) seen.unresolved = unresolved_().clone();
    seen.profile = extractor_.Extract(seen.mask, seen.unresolved);
    colour_frames_.push_back({frame.odometry, ColouredHits(seen.bgr, seen.mask, seen.profile)});
  }
  if (graph_) {
    AddFrameToGraph(seen, frame);
    return seen;
  }
  if (!tracker_) {
    seen.pose = frame.odometry;
    Insert(seen.profile, seen.pose);
    return seen;
  }
  {
    run::StageTimer timer(localize_s_);
    if (tracker_->StartsStop(frame.odometry)) {
      before_stop_ = grid_;
      stop_events_.clear();
    }
    stop_poses_ =
        tracker_->Track(*before_stop_, view_extractor_->Extract(seen.mask, seen.unresolved),
                        setup_.max_range_m, frame.odometry);
  }
  stop_events_.push_back({seen.profile, std::nullopt});
  seen.pose = stop_poses_.back();
  for (std::size_t i = 0; i < stop_poses_.size(); ++i) {
    colour_frames_[colour_frames_.size() - stop_poses_.size() + i].pose = stop_poses_[i];
  }
  // The stop's frames again, where the tracker now puts them.
  grid_ = *before_stop_;
  for (std::size_t i = 0; i < stop_events_.size(); ++i) {
    Insert(stop_events_[i].profile, stop_poses_[i]);
    if (stop_events_[i].blocked_leg_m) {
      Confirm(stop_events_[i].profile, stop_poses_[i], *stop_events_[i].blocked_leg_m);
    }
  }
  return seen;
}

void FrameMapper::AddFrameToGraph(Seen& seen, const robot::Frame& frame) {
  int moved = -1;
  const bool starts = graph_->StartsStop(frame.odometry);
  {
    run::StageTimer timer(localize_s_);
    moved = graph_->Track(grid_, view_extractor_->Extract(seen.mask, seen.unresolved),
                          setup_.max_range_m, frame.odometry);
  }
  const std::size_t k = frame_profiles_.size();
  if (moved >= 0) {
    // Moves that shift no earlier frame's readings by more than a fraction
    // of a cell are left out of the map until they add up (or the run ends).
    const std::optional<std::size_t> displaced =
        FirstDisplacedFrame(setup_.remap_cells * setup_.cell_m);
    moved = displaced ? graph_->StopOf(*displaced) : -1;
    UpdateColourPoses();
  }
  frame_profiles_.emplace_back(seen.profile);
  frame_odometry_.push_back(frame.odometry);
  mapped_poses_.push_back(graph_->FramePose(k));
  // Bumps made on the way here go with this frame (and its stop).
  std::size_t first_new = events_.size();
  for (std::size_t i = 0; i < events_.size(); ++i) {
    MapEvent& e = events_[i];
    if (e.kind == MapEvent::Kind::kContact && !e.resolved) {
      e.frame = k;
      e.frame_T_bump = frame.odometry.Inverse() * e.frame_T_bump;
      e.resolved = true;
      first_new = std::min(first_new, i);
    }
  }
  if (starts) {
    // The map before the stop (made again by Replay when a rebuild passes it).
    const int stop = graph_->StopOf(k);
    snapshots_.push_back({stop, first_new, std::nullopt});
    if (moved < 0) snapshots_.back().grid = grid_.CroppedToKnown(0);
    ThinSnapshots(stop);
  }
  events_.emplace_back(MapEvent::Kind::kFrame, k);
  seen.pose = graph_->FramePose(k);
  colour_frames_.back().pose = seen.pose;
  if (moved < 0) {
    for (std::size_t i = first_new; i < events_.size(); ++i) Apply(events_[i]);
  } else {
    Rebuild(moved);
  }
}

void FrameMapper::Apply(const MapEvent& event) {
  switch (event.kind) {
    case MapEvent::Kind::kFrame:
      mapped_poses_[event.frame] = graph_->FramePose(event.frame);
      Insert(frame_profiles_[event.frame].Unpack(), mapped_poses_[event.frame]);
      break;
    case MapEvent::Kind::kConfirm:
      Confirm(frame_profiles_[event.frame].Unpack(), graph_->FramePose(event.frame), event.leg_m);
      break;
    case MapEvent::Kind::kContact: {
      run::StageTimer timer(update_s_);
      InsertBump(
          grid_,
          event.resolved ? graph_->FramePose(event.frame) * event.frame_T_bump : event.map_T_bump,
          setup_.radius_m, setup_.cell_m);
      break;
    }
  }
}

void FrameMapper::Replay(std::size_t from) {
  auto next = snapshots_.begin();
  for (std::size_t i = from; i < events_.size(); ++i) {
    while (next != snapshots_.end() && next->first_event < i) ++next;
    if (next != snapshots_.end() && next->first_event == i) next->grid = grid_.CroppedToKnown(0);
    Apply(events_[i]);
  }
}

void FrameMapper::ThinSnapshots(int stop) {
  std::erase_if(snapshots_, [&](const StopSnapshot& s) {
    const int back = stop - s.stop;
    return back >= kRecentSnapshots && !(back < kNearSpan && s.stop % kNearStride == 0) &&
           s.stop % kFarStride != 0;
  });
}

void FrameMapper::Rebuild(int from_stop) {
  run::StageTimer timer(rebuild_s_);
  ++rebuilds_;
  // From the latest map kept from before a stop no later than from_stop, or
  // from nothing.
  auto kept = std::find_if(snapshots_.rbegin(), snapshots_.rend(), [&](const StopSnapshot& s) {
    return s.stop <= from_stop && s.grid.has_value();
  });
  if (kept != snapshots_.rend()) {
    grid_.Restore(*kept->grid);
    Replay(kept->first_event);
  } else {
    grid_ = InitialGrid(start_, setup_);
    Replay(0);
  }
  UpdateColourPoses();
}

mapping::OccupancyGrid FrameMapper::MapAgain() const {
  if (!graph_) return grid_;
  FrameMapper again = *this;
  again.snapshots_.clear();
  again.Rebuild(0);
  return std::move(again.grid_);
}

void FrameMapper::UpdateColourPoses() {
  for (std::size_t i = 0; i < colour_frames_.size(); ++i) {
    colour_frames_[i].pose = graph_->FramePose(i);
  }
}

std::optional<std::size_t> FrameMapper::FirstDisplacedFrame(double tolerance_m) const {
  for (std::size_t k = 0; k < mapped_poses_.size(); ++k) {
    const core::Pose2& was = mapped_poses_[k];
    const core::Pose2 now = graph_->FramePose(k);
    const double shift =
        (now.translation() - was.translation()).norm() +
        setup_.max_range_m * std::abs(core::NormalizeAngle(now.heading() - was.heading()));
    if (shift > tolerance_m) return k;
  }
  return std::nullopt;
}

void FrameMapper::Finish() {
  MapSettlingFrames();
  if (!graph_) return;
  int moved = -1;
  {
    run::StageTimer timer(localize_s_);
    moved = graph_->Finish();
  }
  // The last map from every frame exactly where the graph ends up.
  if (moved >= 0 || FirstDisplacedFrame(0.0)) Rebuild(0);
}

std::vector<core::Pose2> FrameMapper::FramePoses() const {
  std::vector<core::Pose2> poses;
  poses.reserve(colour_frames_.size());
  for (const ColourFrame& f : colour_frames_) poses.push_back(f.pose);
  return poses;
}

std::vector<FrameMapper::ColourHit> FrameMapper::ColouredHits(
    const cv::Mat3b& bgr, const cv::Mat1b& mask, const core::ObstacleProfile& profile) {
  std::vector<ColourHit> hits;
  for (std::size_t u = 0; u < profile.readings.size(); ++u) {
    const core::RangeReading& r = profile.readings[u];
    if (r.kind != core::ReadingKind::kHit) continue;
    const core::ColourClass c = vision::ColumnColour(bgr, mask, static_cast<int>(u));
    if (c == core::ColourClass::kNone) continue;
    hits.push_back({core::PointOf(r).cast<float>(), c});
  }
  return hits;
}

localize::ColourMap FrameMapper::MakeColourMap() const {
  localize::ColourVotes votes(grid_.geometry());
  for (const ColourFrame& f : colour_frames_) {
    for (const ColourHit& h : f.hits_robot) {
      votes.Add({f.pose * h.p_robot.cast<double>(), h.colour});
    }
  }
  return votes.Map();
}

void FrameMapper::Insert(const core::ObstacleProfile& profile, const core::Pose2& map_T_robot) {
  run::StageTimer timer(update_s_);
  mapping::InsertProfile(grid_, profile, map_T_robot);
  mapping::MarkFootprintFree(grid_, map_T_robot.translation(), setup_.radius_m);
}

void FrameMapper::InsertBump(mapping::OccupancyGrid& grid, const core::Pose2& map_T_robot,
                             double radius_m, double cell_m) {
  core::ObstacleProfile bump;
  const double range = radius_m + 0.5 * cell_m;
  bump.max_range_m = radius_m + cell_m;
  bump.readings.push_back({0.0, range, core::ReadingKind::kHit});
  mapping::InsertProfile(grid, bump, map_T_robot);
  // The touch is certain, as no camera reading is: the cell is solid, so that
  // frames that see on through it (a wall that passes for the floor, the
  // cause of most contacts) neither clear it nor map free floor past it
  // (OccupancyGrid::Solid). Left a single hit, the next look's misses
  // cleared it, and a robot could drive into the same wall again and again.
  const std::optional<core::CellIndex> c =
      grid.geometry().CellAt(map_T_robot.translation() + range * map_T_robot.Direction());
  if (c) grid.SetSolid(*c);
}

void FrameMapper::AddContact(const core::Pose2& odom_T_robot) {
  // A bump goes in after the frames before it.
  MapSettlingFrames();
  const core::Pose2 map_T_robot = ToMap(odom_T_robot);
  if (graph_) {
    // The bump goes with the stop it was made at: the stop of the frame
    // before where the robot has not moved since, else the next frame's.
    MapEvent bump(MapEvent::Kind::kContact);
    bump.map_T_bump = map_T_robot;
    if (!frame_odometry_.empty() && !graph_->StartsStop(odom_T_robot)) {
      bump.frame = frame_odometry_.size() - 1;
      bump.frame_T_bump = frame_odometry_.back().Inverse() * odom_T_robot;
      events_.push_back(bump);
      Apply(events_.back());
    } else {
      // Put in with the next frame (the explorer looks at once).
      bump.resolved = false;
      bump.frame_T_bump = odom_T_robot;  // its odometry, until its frame is known
      events_.push_back(bump);
    }
    return;
  }
  run::StageTimer timer(update_s_);
  InsertBump(grid_, map_T_robot, setup_.radius_m, setup_.cell_m);
  // With tracking, the stop's frames are put again in the map as it was
  // before the stop: the bump must be there too (a move that stopped at
  // contact at once leaves the robot in the same stop).
  if (before_stop_) InsertBump(*before_stop_, map_T_robot, setup_.radius_m, setup_.cell_m);
}

void FrameMapper::ConfirmBlocking(const core::ObstacleProfile& profile,
                                  const core::Pose2& map_T_robot, double leg_m) {
  MapSettlingFrames();
  // With tracking, the stop's last frame's confirmation is put in again with it.
  if (tracker_ && !stop_events_.empty()) stop_events_.back().blocked_leg_m = leg_m;
  if (graph_ && !frame_profiles_.empty()) {
    MapEvent confirm(MapEvent::Kind::kConfirm);
    confirm.frame = frame_profiles_.size() - 1;
    confirm.leg_m = leg_m;
    events_.push_back(confirm);
    Apply(events_.back());  // as a rebuild puts it in again (the frame is the last one mapped)
    return;
  }
  Confirm(profile, map_T_robot, leg_m);
}

void FrameMapper::Confirm(const core::ObstacleProfile& profile, const core::Pose2& map_T_robot,
                          double leg_m) {
  const explore::LookAhead::Finding finding = look_.Blocking(profile, leg_m);
  run::StageTimer timer(update_s_);
  // Rounds of a hit to each blocking cell that does not yet lean occupied:
  // with the exploration's sensor model two take a cell from the clamp's
  // floor (seen free many times) past the occupied threshold; four leave
  // room for any sensor model the options allow.
  constexpr int kConfirmingHits = 4;
  for (int round = 0; round < kConfirmingHits; ++round) {
    grid_.BeginFrame();
    for (const Eigen::Vector2d& hit : finding.hits_robot) {
      const core::CellIndex c = grid_.geometry().CellOf(map_T_robot * hit);
      if (grid_.LogOdds(c) <= 0.0F) grid_.Apply(c, mapping::CellUpdate::kHit);
    }
  }
}

}  // namespace pirouette::run
