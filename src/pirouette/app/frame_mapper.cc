#include "pirouette/app/frame_mapper.h"

#include <cmath>
#include <utility>

#include "pirouette/app/image_io.h"
#include "pirouette/app/stage_timer.h"
#include "pirouette/mapping/range_sensor_model.h"

namespace pirouette::app {
namespace {

// 2 m square around the start, on whole cells.
mapping::OccupancyGrid InitialGrid(const core::Pose2& start, double cell_m,
                                   const mapping::OccupancyOptions& occupancy) {
  constexpr double kHalf = 1.0;
  const Eigen::Vector2d lo(std::floor((start.x() - kHalf) / cell_m) * cell_m,
                           std::floor((start.y() - kHalf) / cell_m) * cell_m);
  return mapping::OccupancyGrid(
      core::GridGeometry::Covering(cell_m, lo, Eigen::Vector2d(2 * kHalf, 2 * kHalf)), occupancy);
}

}  // namespace

FrameMapper::FrameMapper(const MapperSetup& setup, MaskFunction mask, const core::Pose2& start)
    : setup_(setup),
      mask_(std::move(mask)),
      ipm_(setup.camera),
      extractor_(ipm_, setup.max_range_m),
      look_(LookAheadOptions{setup.radius_m, NearRange(ipm_), setup.max_range_m, setup.cell_m}),
      grid_(InitialGrid(start, setup.cell_m, setup.occupancy)) {}

FrameMapper::Seen FrameMapper::AddFrame(const robot::Frame& frame) {
  Seen seen;
  {
    StageTimer timer(perceive_s_);
    seen.bgr = ToBgrMat(frame.image);
    seen.mask = mask_(seen.bgr);
    seen.profile = extractor_.Extract(seen.mask);
  }
  StageTimer timer(update_s_);
  mapping::InsertProfile(grid_, seen.profile, frame.odometry);
  mapping::MarkFootprintFree(grid_, frame.odometry.translation(), setup_.radius_m);
  return seen;
}

void FrameMapper::AddContact(const core::Pose2& odom_T_robot) {
  StageTimer timer(update_s_);
  core::ObstacleProfile bump;
  bump.max_range_m = setup_.radius_m + setup_.cell_m;
  bump.readings.push_back({0.0, setup_.radius_m + 0.5 * setup_.cell_m, core::ReadingKind::kHit});
  mapping::InsertProfile(grid_, bump, odom_T_robot);
}

void FrameMapper::ConfirmBlocking(const core::ObstacleProfile& profile,
                                  const core::Pose2& odom_T_robot, double leg_m) {
  const LookAhead::Finding finding = look_.Blocking(profile, leg_m);
  StageTimer timer(update_s_);
  for (int round = 0; round < 4; ++round) {
    grid_.BeginFrame();
    for (const Eigen::Vector2d& hit : finding.hits_robot) {
      const core::CellIndex c = grid_.geometry().CellOf(odom_T_robot * hit);
      if (grid_.LogOdds(c) <= 0.0F) grid_.Apply(c, mapping::CellUpdate::kHit);
    }
  }
}

}  // namespace pirouette::app
