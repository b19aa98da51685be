#include "pirouette/mapping/range_sensor_model.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace pirouette::mapping {
namespace {

using core::CellIndex;
using core::ReadingKind;

// One ray of a frame.
struct Ray {
  Eigen::Vector2d direction;  // unit, world (and cell units: the same)
  Eigen::Vector2d end;        // world, then cell units once the grid has grown
  double length;              // metres, then cells
  bool end_hit;               // the end cell takes a hit
  bool include_end;           // the end cell takes the ray's update (never with end_hit)

  // How far (cells) from the robot every cell the ray passes through has
  // taken an update in this frame once the ray was walked: all of its length
  // when its end cell was updated too (by the ray or as a hit), else 1.5
  // cells (more than a cell's diagonal) short of it.
  double Covered() const { return include_end || end_hit ? length : length - 1.5; }

  // How far (cells) from the robot the ray was checked free of solid cells
  // (StopAtSolidCells): every cell it enters nearer than this is not solid.
  double checked = 0.0;
};

double Cross(const Eigen::Vector2d& a, const Eigen::Vector2d& b) {
  return a.x() * b.y() - a.y() * b.x();
}

// Visits every cell the segment from `from` to `to` (cell units) passes
// through, in order, the end cell only when include_end: an exact grid
// traversal (Amanatides & Woo 1987, "A Fast Voxel Traversal Algorithm for Ray
// Tracing"), 4-connected. Both ends lie on the grid, so every cell between
// does too. The number of steps is fixed by the end cells, so rounding can
// never carry the walk past its end. visit(flat index, t) gets where the
// segment enters the cell (t in [0, 1] along it, 0 for the first) and
// returns whether to go on.
template <class Visit>
void Traverse(std::ptrdiff_t width, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
              bool include_end, Visit&& visit) {
  const int x0 = static_cast<int>(std::floor(from.x()));
  const int y0 = static_cast<int>(std::floor(from.y()));
  int steps_x = std::abs(static_cast<int>(std::floor(to.x())) - x0);
  int steps_y = std::abs(static_cast<int>(std::floor(to.y())) - y0);
  const Eigen::Vector2d d = to - from;
  constexpr double kNever = std::numeric_limits<double>::infinity();
  // Ray parameter t in [0, 1]: where the next column / row boundary is
  // crossed, and how far apart the boundaries are.
  const double delta_x = steps_x > 0 ? 1.0 / std::abs(d.x()) : kNever;
  const double delta_y = steps_y > 0 ? 1.0 / std::abs(d.y()) : kNever;
  double next_x = steps_x > 0 ? (d.x() > 0 ? x0 + 1 - from.x() : from.x() - x0) * delta_x : kNever;
  double next_y = steps_y > 0 ? (d.y() > 0 ? y0 + 1 - from.y() : from.y() - y0) * delta_y : kNever;
  const std::ptrdiff_t step_x = d.x() > 0 ? 1 : -1;
  const std::ptrdiff_t step_y = d.y() > 0 ? width : -width;

  auto index = static_cast<std::ptrdiff_t>(y0) * width + x0;
  double t = 0.0;
  for (int n = steps_x + steps_y; n > 0; --n) {
    if (!visit(static_cast<std::size_t>(index), t)) return;
    if (next_x < next_y) {
      index += step_x;
      t = next_x;
      next_x = --steps_x > 0 ? next_x + delta_x : kNever;
    } else {
      index += step_y;
      t = next_y;
      next_y = --steps_y > 0 ? next_y + delta_y : kNever;
    }
  }
  if (include_end) visit(static_cast<std::size_t>(index), t);
}

// Applies kUpdate to every cell the segment from `from` to `to` (cell units)
// passes through (Traverse). Returns the number of updates applied.
template <CellUpdate kUpdate>
std::size_t WalkSegment(OccupancyGrid& grid, const Eigen::Vector2d& from, const Eigen::Vector2d& to,
                        bool include_end) {
  std::size_t applied = 0;
  Traverse(grid.geometry().width(), from, to, include_end, [&](std::size_t flat, double) {
    applied += grid.ApplyAt(flat, kUpdate) ? 1 : 0;
    return true;
  });
  return applied;
}

// How far (cells) from the robot ray m's cells have all been updated already
// in this pass, given that rays lo and hi, on either side of it, have been
// walked; 0 when that cannot be shown. A cell that m passes through within a
// distance D meets lo or hi within D + √2 unless the whole cell fits inside
// the wedge between them, which it cannot while the wedge is narrower than a
// cell there: 2·(D + √2)·sin(α/2) = (D + √2)·|lo.direction − hi.direction| < 1.
// So m's walk may start at D where that holds and lo and hi reach D + √2.
// lo_reach and hi_reach are how far along lo and hi that holds (their
// Covered() for a walk).
double SkipDistance(const Ray& lo, const Ray& m, const Ray& hi, double lo_reach, double hi_reach) {
  const Eigen::Vector2d& a = lo.direction;
  const Eigen::Vector2d& b = hi.direction;
  const Eigen::Vector2d& d = m.direction;
  if (!(a.dot(b) > 0.0) || !(a.dot(d) > 0.0)) return 0.0;  // wedges up to 90° only
  const double ad = Cross(a, d);
  const double db = Cross(d, b);
  if (Cross(a, b) >= 0.0 ? (ad < 0.0 || db < 0.0) : (ad > 0.0 || db > 0.0)) return 0.0;
  // reach = min(lo_reach, hi_reach, 0.99 / chord), without the square root
  // and division where the wedge is narrow enough.
  double reach = std::min(lo_reach, hi_reach);
  const double chord_squared = (a - b).squaredNorm();
  if (chord_squared * reach * reach > 0.99 * 0.99) {
    reach = std::min(reach, 0.99 / std::sqrt(chord_squared));
  }
  return std::max(0.0, reach - 1.5);  // 1.5 > √2
}

// Walks ray m from `skip` cells out.
template <CellUpdate kUpdate>
std::size_t WalkRay(OccupancyGrid& grid, const Eigen::Vector2d& from, const Ray& ray, double skip) {
  if (skip <= 0.0) return WalkSegment<kUpdate>(grid, from, ray.end, ray.include_end);
  if (skip >= ray.length) return 0;
  return WalkSegment<kUpdate>(grid, from + skip * ray.direction, ray.end, ray.include_end);
}

// Visits every ray of a pass, in the profile's order of bisection: the
// first and the last whole (skip 0), then each middle one between the two
// around it, from where they leave it nothing to do: visit(i, skip), with
// SkipDistance from reach(ray), how far each visited ray has covered. Rays
// of one frame are dense (0.2° apart for the paper's camera, ~1/20 of a cell
// at 0.4 m) and all start at the robot, so most of each ray's cells are
// ones its neighbours have already covered; bisecting visits each cell of
// such a frame about three times instead of about 25, with the same result
// as visiting every ray whole.
template <class Reach, class Visit>
void VisitBisected(const std::vector<Ray>& rays, Reach&& reach, Visit&& visit) {
  if (rays.empty()) return;
  visit(std::size_t{0}, 0.0);
  if (rays.size() == 1) return;
  visit(rays.size() - 1, 0.0);
  const auto between = [&](const auto& self, std::size_t lo, std::size_t hi) -> void {
    if (hi - lo < 2) return;
    const std::size_t m = lo + (hi - lo) / 2;
    visit(m, SkipDistance(rays[lo], rays[m], rays[hi], reach(rays[lo]), reach(rays[hi])));
    self(self, lo, m);
    self(self, m, hi);
  };
  between(between, 0, rays.size() - 1);
}

// Walks the rays of one pass (VisitBisected).
template <CellUpdate kUpdate>
std::size_t WalkPass(OccupancyGrid& grid, const Eigen::Vector2d& from,
                     const std::vector<Ray>& rays) {
  std::size_t applied = 0;
  VisitBisected(
      rays, [](const Ray& r) { return r.Covered(); },
      [&](std::size_t i, double skip) { applied += WalkRay<kUpdate>(grid, from, rays[i], skip); });
  return applied;
}

void CheckReading(const core::RangeReading& reading) {
  if (!std::isfinite(reading.bearing_rad) || !std::isfinite(reading.range_m) ||
      reading.range_m < 0.0) {
    throw std::invalid_argument(
        "InsertProfile: a reading's bearing and range must be finite and its range >= 0");
  }
}

}  // namespace

namespace {

// Directions along a frame's bearings, each by rotating the previous one when
// the bearing moved less than kMaxRotationStepRad (the columns of one image),
// by the Taylor series of sin and cos of the step (to x^5 and x^6: within an
// ulp for such steps), and afresh at least every kMaxRotations readings, so
// that rounding never builds up.
class DirectionStepper {
 public:
  static constexpr double kMaxRotationStepRad = 0.01;
  static constexpr int kMaxRotations = 64;

  explicit DirectionStepper(double heading) : heading_(heading) {}

  Eigen::Vector2d Next(double bearing) {
    const double step = bearing - last_bearing_;
    if (std::abs(step) < kMaxRotationStepRad && rotations_ < kMaxRotations &&
        !std::isnan(last_.x())) {
      const double s2 = step * step;
      const double c = 1.0 - s2 * (0.5 - s2 * (1.0 / 24.0 - s2 / 720.0));
      const double s = step * (1.0 - s2 * (1.0 / 6.0 - s2 / 120.0));
      last_ = {c * last_.x() - s * last_.y(), s * last_.x() + c * last_.y()};
      ++rotations_;
    } else {
      last_ = {std::cos(heading_ + bearing), std::sin(heading_ + bearing)};
      rotations_ = 0;
    }
    last_bearing_ = bearing;
    return last_;
  }

 private:
  double heading_;
  double last_bearing_ = 0.0;
  Eigen::Vector2d last_{std::numeric_limits<double>::quiet_NaN(), 0.0};
  int rotations_ = 0;
};

// A frame's rays by pass, in world metres: blind areas, then misses (hit and
// clear readings and the fill between them); the hits' ends are the hit pass.
struct FrameRays {
  std::vector<Ray> blind;
  std::vector<Ray> miss;
};

FrameRays RaysOf(const std::vector<core::RangeReading>& readings, const core::Pose2& world_T_robot,
                 double resolution) {
  const Eigen::Vector2d& origin = world_T_robot.translation();
  DirectionStepper directions(world_T_robot.heading());
  const auto ray = [&](double bearing, double range, bool end_hit, bool include_end) {
    const Eigen::Vector2d direction = directions.Next(bearing);
    return Ray{direction, origin + range * direction, range, end_hit, include_end};
  };
  FrameRays rays;
  rays.miss.reserve(readings.size());
  for (std::size_t i = 0; i < readings.size(); ++i) {
    const auto& r = readings[i];
    if (r.kind == ReadingKind::kBlind) {
      rays.blind.push_back(ray(r.bearing_rad, r.range_m, false, true));
      continue;
    }
    rays.miss.push_back(
        ray(r.bearing_rad, r.range_m, r.kind == ReadingKind::kHit, r.kind == ReadingKind::kClear));
    if (i + 1 == readings.size()) break;
    // Fill the gap to the next reading when their rays part by more than a cell.
    const auto& next = readings[i + 1];
    if (next.kind == ReadingKind::kBlind) continue;
    double gap = next.bearing_rad - r.bearing_rad;
    if (std::abs(gap) > std::numbers::pi) gap = core::NormalizeAngle(gap);
    if (std::abs(gap) > kMaxFillGapRad) continue;
    const double range = std::min(r.range_m, next.range_m);
    const int fills = static_cast<int>(std::floor(std::abs(gap) * range / resolution));
    // The end cell is seen through only where both readings saw past it.
    const bool end_free = r.kind == ReadingKind::kClear && next.kind == ReadingKind::kClear;
    for (int k = 1; k <= fills; ++k) {
      rays.miss.push_back(ray(r.bearing_rad + gap * k / (fills + 1), range, false, end_free));
    }
  }
  return rays;
}

// Adds the profile's feet to rays.miss: hit rays, with no fill between them.
void AddFeet(const std::vector<core::RangeReading>& feet, const core::Pose2& world_T_robot,
             FrameRays& rays) {
  const Eigen::Vector2d& origin = world_T_robot.translation();
  for (const core::RangeReading& f : feet) {
    const double angle = world_T_robot.heading() + f.bearing_rad;
    const Eigen::Vector2d direction(std::cos(angle), std::sin(angle));
    rays.miss.push_back(Ray{direction, origin + f.range_m * direction, f.range_m, true, false});
  }
}

// Grows the grid to hold the robot and every ray's end.
void GrowToHold(OccupancyGrid& grid, const Eigen::Vector2d& origin, const FrameRays& rays) {
  Eigen::Vector2d lo = origin;
  Eigen::Vector2d hi = origin;
  for (const auto* pass : {&rays.blind, &rays.miss}) {
    for (const Ray& r : *pass) {
      lo = lo.cwiseMin(r.end);
      hi = hi.cwiseMax(r.end);
    }
  }
  grid.GrowToCover(lo, hi);
}

// A point in cell units: (world - grid origin) / resolution, whose floor is
// the cell (as GridGeometry::CellOf computes it).
CellIndex CellOfCells(const Eigen::Vector2d& p_cells) {
  return CellIndex{static_cast<int>(std::floor(p_cells.x())),
                   static_cast<int>(std::floor(p_cells.y()))};
}

// A ray that meets a solid cell (OccupancyGrid::Solid) more than this many
// cells short of its end stops there: the reading saw through a wall seen for
// sure, so it is taken for a wall passing as floor and says nothing of the
// wall or beyond. Within it, the reading is of the wall itself (a range a
// cell or two short or long).
constexpr double kSolidStopMarginCells = 3.0;

// Checks ray r for solid cells from `skip` cells out to where a solid cell
// no longer stops it (kSolidStopMarginCells short of its end): returns where
// it enters the first (cells from the robot), or -1, and sets r.checked.
double CheckRay(const OccupancyGrid& grid, const Eigen::Vector2d& from, Ray& r, double skip) {
  const double limit = r.length - kSolidStopMarginCells;
  r.checked = std::max(skip, limit);
  if (skip >= limit) return -1.0;
  // From the point at `skip`: the cell holding it is one r passes within
  // `skip` of the robot, so (SkipDistance) it was checked already and is not
  // solid; every cell after it is entered at a true crossing. Over blocks
  // first, to the first flagged one; then cell by cell from where the ray
  // enters it (a block's edge is a cell's edge).
  const Eigen::Vector2d start = from + skip * r.direction;
  const Eigen::Vector2d end = from + limit * r.direction;
  constexpr double kBlock = OccupancyGrid::kSolidBlockCells;
  double flagged = -1.0;  // where the ray enters the first flagged block, along start→end
  Traverse(grid.solid_blocks_width(), start / kBlock, end / kBlock, true,
           [&](std::size_t flat_block, double t) {
             if (!grid.SolidBlockAt(flat_block)) return true;
             flagged = t;
             return false;
           });
  if (flagged < 0.0) return -1.0;
  const double fine_skip = skip + flagged * (limit - skip);
  const double span = limit - fine_skip;
  double stop = -1.0;
  // Up to the cell holding the point at `limit`, entered before it.
  Traverse(grid.geometry().width(), start + flagged * (end - start), end, true,
           [&](std::size_t flat, double t) {
             if (!grid.SolidAt(flat)) return true;
             stop = fine_skip + t * span;
             return false;
           });
  if (stop >= 0.0) r.checked = stop;
  return stop;
}

// Ends ray `r` (from `from`, cell units) just short of `stop` along it, so
// that the cell it then enters is the first it does not pass through.
void EndJustShortOf(const Eigen::Vector2d& from, double stop, Ray& r) {
  constexpr double kJustShort = 1e-6;
  r.length = std::max(0.0, stop - kJustShort);
  r.end = from + r.length * r.direction;
  r.include_end = r.length > 0.0;
}

// Shortens each miss ray that passes through a solid cell more than
// kSolidStopMarginCells short of its end to end just before that cell, no
// hit at its end; returns how many it shortened. Rays are in cell units.
// The search skips, as the walk does, what the neighbouring rays covered
// (VisitBisected, with how far each was checked).
std::size_t StopAtSolidCells(const OccupancyGrid& grid, const Eigen::Vector2d& from,
                             std::vector<Ray>& rays) {
  if (!(grid.options().two_places_m > 0.0)) return 0;  // none is ever solid
  std::size_t stopped = 0;
  VisitBisected(
      rays, [](const Ray& r) { return r.checked; },
      [&](std::size_t i, double skip) {
        Ray& r = rays[i];
        const double stop = CheckRay(grid, from, r, skip);
        if (stop < 0.0) return;
        ++stopped;
        // The cell before the solid one is the last the ray passes through.
        EndJustShortOf(from, stop, r);
        r.end_hit = false;
      });
  return stopped;
}

// Ends each blind ray just before the first cell on it that the grid holds
// occupied (this frame's hits in): the base of what fills the view lies in
// front of an obstacle the map already has in the way, never behind it. Left
// whole, a blind ray from a robot beside a thin wall runs on through it and
// marks the floor on its far side blind, known without being seen; in a
// maze of such walls that made corridors "known" and shut their way in for
// the planner (generated maze 102 ended complete at coverage 0.49; 0.94 with
// the cut). Returns how many it shortened. Rays are in cell units.
std::size_t StopBlindAtOccupiedCells(const OccupancyGrid& grid, const Eigen::Vector2d& from,
                                     std::vector<Ray>& rays) {
  const core::GridGeometry& geometry = grid.geometry();
  std::size_t stopped = 0;
  for (Ray& r : rays) {
    double stop = -1.0;
    Traverse(geometry.width(), from, r.end, r.include_end, [&](std::size_t flat, double t) {
      if (grid.StateAt(flat) != CellState::kOccupied) return true;
      stop = t;
      return false;
    });
    if (stop < 0.0) continue;
    ++stopped;
    EndJustShortOf(from, stop * r.length, r);
  }
  return stopped;
}

// Turns the rays into cell units.
void ToCells(const OccupancyGrid& grid, FrameRays& rays) {
  const core::GridGeometry& geometry = grid.geometry();
  const double resolution = geometry.resolution();
  for (auto* pass : {&rays.blind, &rays.miss}) {
    for (Ray& r : *pass) {
      r.end = (r.end - geometry.origin()) / resolution;
      r.length /= resolution;
      if (!geometry.Contains(CellOfCells(r.end))) {
        throw std::logic_error("InsertProfile: a ray ends off the grown grid");
      }
    }
  }
}

// The hit pass: each hit ray's end cell. Returns the cells it updated.
std::size_t ApplyHits(OccupancyGrid& grid, const std::vector<Ray>& rays) {
  const core::GridGeometry& geometry = grid.geometry();
  std::size_t applied = 0;
  for (const Ray& r : rays) {
    if (!r.end_hit) continue;
    applied += grid.ApplyAt(geometry.Flat(CellOfCells(r.end)), CellUpdate::kHit) ? 1 : 0;
  }
  return applied;
}

}  // namespace

std::size_t InsertProfile(OccupancyGrid& grid, const core::ObstacleProfile& profile,
                          const core::Pose2& world_T_robot) {
  for (const auto& reading : profile.readings) CheckReading(reading);
  for (const auto& foot : profile.feet) CheckReading(foot);
  FrameRays rays = RaysOf(profile.readings, world_T_robot, grid.geometry().resolution());
  AddFeet(profile.feet, world_T_robot, rays);
  GrowToHold(grid, world_T_robot.translation(), rays);
  grid.BeginFrame(world_T_robot.translation());
  const core::GridGeometry& geometry = grid.geometry();
  const Eigen::Vector2d from =
      (world_T_robot.translation() - geometry.origin()) / geometry.resolution();
  if (!geometry.Contains(CellOfCells(from))) {
    throw std::logic_error("InsertProfile: the robot is off the grown grid");
  }
  ToCells(grid, rays);
  StopAtSolidCells(grid, from, rays.miss);
  std::size_t applied = ApplyHits(grid, rays.miss);
  StopBlindAtOccupiedCells(grid, from, rays.blind);
  applied += WalkPass<CellUpdate::kBlind>(grid, from, rays.blind);
  applied += WalkPass<CellUpdate::kMiss>(grid, from, rays.miss);
  return applied;
}

void MarkFootprintFree(OccupancyGrid& grid, const Eigen::Vector2d& centre, double radius_m) {
  if (!centre.allFinite() || !std::isfinite(radius_m) || radius_m < 0.0) {
    throw std::invalid_argument("MarkFootprintFree: needs a finite centre and radius >= 0");
  }
  const Eigen::Vector2d half(radius_m, radius_m);
  grid.GrowToCover(centre - half, centre + half);
  const core::GridGeometry& geometry = grid.geometry();
  const CellIndex lo = geometry.CellOf(centre - half);
  const CellIndex hi = geometry.CellOf(centre + half);
  for (int y = lo.y; y <= hi.y; ++y) {
    for (int x = lo.x; x <= hi.x; ++x) {
      if ((geometry.CellCentre({x, y}) - centre).norm() <= radius_m) grid.SetFree({x, y});
    }
  }
  grid.SetFree(geometry.CellOf(centre));
}

}  // namespace pirouette::mapping
