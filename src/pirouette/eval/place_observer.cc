#include "pirouette/eval/place_observer.h"

#include <algorithm>
#include <vector>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/input_error.h"
#include "pirouette/eval/floor_masker.h"
#include "pirouette/explore/planner.h"
#include "pirouette/io/image_io.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/sim/simulated_pirouette.h"
#include "pirouette/vision/column_colour.h"
#include "pirouette/vision/profile_extractor.h"
#include "pirouette/vision/vertical_direction_field.h"

namespace pirouette::eval {
namespace {

// The noise of the table's pirouette at place i is seeded kTableSeedBase + i:
// fixed (a table is the same whatever the run's seed) and apart from the
// seeds of queries (tools::QuerySeed) for tables of up to a few thousand
// places.
constexpr std::uint64_t kTableSeedBase = 1000;

}  // namespace

struct PlaceObserver::Impl {
  Impl(const sim::World& world, vision::MaskSource method, double max_range_m,
       std::uint64_t render_seed)
      : world(world),
        renderer(world, world.robot().camera,
                 [render_seed] {
                   sim::RenderOptions options;
                   options.seed = render_seed;
                   return options;
                 }()),
        ipm(world.robot().camera),
        extractor(ipm, max_range_m, vision::VerticalDirectionField(world.robot().camera)),
        masker(method, world, world.robot().camera) {}

  const sim::World& world;
  sim::Renderer renderer;
  camera::InversePerspectiveMap ipm;
  vision::ProfileExtractor extractor;
  FloorMasker masker;
};

PlaceObserver::PlaceObserver(const sim::World& world, vision::MaskSource method, double max_range_m,
                             std::uint64_t render_seed)
    : impl_(std::make_unique<Impl>(world, method, max_range_m, render_seed)) {
  // The floor segmenter learns the floor over its first pirouette: let it
  // learn where the world puts the robot, not at a table's first place (a
  // corner, where walls fill the views).
  Observe(world.robot().start, render_seed);
}

PlaceObserver::~PlaceObserver() = default;

double PlaceObserver::max_range_m() const { return impl_->extractor.max_range_m(); }

localize::ObservedPlace PlaceObserver::Observe(const core::Pose2& world_T_robot,
                                               std::uint64_t seed) {
  const sim::World placed = sim::PlaceRobot(impl_->world, world_T_robot, "place");
  const std::vector<sim::SimulatedFrame> frames =
      sim::SimulatePirouette(placed, impl_->renderer, seed);
  // The odometry frame is the world frame at the start: bearings relative to
  // the robot's heading then are odometry bearings less that heading.
  const double start_heading = frames.front().frame.odometry.heading();
  std::vector<localize::PirouetteFrame> views;
  for (const sim::SimulatedFrame& frame : frames) {
    const cv::Mat3b bgr = io::ToBgrMat(frame.frame.image);
    const cv::Mat1b mask = impl_->masker.Mask(bgr, frame.world_T_robot);
    localize::PirouetteFrame view;
    view.heading_rad = frame.frame.odometry.heading() - start_heading;
    view.profile = impl_->extractor.Extract(mask, impl_->masker.Unresolved());
    for (std::size_t u = 0; u < view.profile.readings.size(); ++u) {
      view.column_colours.push_back(view.profile.readings[u].kind == core::ReadingKind::kClear
                                        ? core::ColourClass::kNone
                                        : vision::ColumnColour(bgr, mask, static_cast<int>(u)));
    }
    views.push_back(std::move(view));
  }
  return localize::ObservePlace(views);
}

double CoarseCellSize(const sim::World& world) {
  const double cell = mapping::DefaultCellSize(world.robot().radius);
  explore::PlannerOptions options;
  options.robot_radius_m = world.robot().radius;
  return cell * options.CoarseFactor(cell);
}

double DefaultTableSpacing(const sim::World& world) {
  return std::max(CoarseCellSize(world), kMinSpacingRadii * world.robot().radius);
}

double PlaceMaxRange(const sim::World& world, double range_factor) {
  if (!(range_factor >= 1.0)) {
    throw core::InputError("", 0, "--range-factor", "must be a number >= 1");
  }
  const camera::CameraModel& camera = world.robot().camera;
  return camera::LongRange(camera,
                           camera::MaxRange(camera, mapping::DefaultCellSize(world.robot().radius)),
                           range_factor);
}

localize::PlaceTable BuildPlaceTable(const sim::World& world, PlaceObserver& observer,
                                     double spacing_m,
                                     const std::function<void(int, int)>& progress) {
  std::vector<Eigen::Vector2d> where;
  const Eigen::Vector2d size = world.floor().size;
  for (double y = 0.5 * spacing_m; y < size.y(); y += spacing_m) {
    for (double x = 0.5 * spacing_m; x < size.x(); x += spacing_m) {
      if (world.DiscFits({x, y}, world.robot().radius)) where.emplace_back(x, y);
    }
  }
  std::vector<localize::PlaceEntry> entries;
  for (std::size_t i = 0; i < where.size(); ++i) {
    const localize::ObservedPlace seen =
        observer.Observe(core::Pose2(where[i].x(), where[i].y(), 0.0), kTableSeedBase + i);
    entries.push_back({where[i].x(), where[i].y(), 0.0, seen.view, seen.kinds});
    if (progress) progress(static_cast<int>(i + 1), static_cast<int>(where.size()));
  }
  return {world.name(), observer.max_range_m(), std::move(entries)};
}

}  // namespace pirouette::eval
