#include "pirouette/sim/ray_caster.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "pirouette/sim/scene_mesh.h"

namespace pirouette::sim {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

// Bisections of a pixel step at a floor's edge: 2^-10 pixel.
constexpr int kEdgeBisections = 10;

}  // namespace

RayCaster::RayCaster(const World& world, const camera::CameraModel& camera)
    : world_(world), camera_(camera) {
  rays_.reserve(static_cast<std::size_t>(camera.width()) * camera.height());
  for (int v = 0; v < camera.height(); ++v) {
    for (int u = 0; u < camera.width(); ++u) rays_.push_back(camera.Backproject({u, v}));
  }
}

Eigen::Isometry3d RayCaster::WorldTCamera(const core::Pose2& world_T_robot) const {
  Eigen::Isometry3d world_T_robot3 = Eigen::Isometry3d::Identity();
  world_T_robot3.linear() =
      Eigen::AngleAxisd(world_T_robot.heading(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
  world_T_robot3.translation() << world_T_robot.x(), world_T_robot.y(), 0.0;
  return world_T_robot3 * camera_.robot_T_camera();
}

RayHit RayCaster::Cast(const Eigen::Isometry3d& world_T_camera,
                       const Eigen::Vector2d& pixel) const {
  return Cast(world_T_camera.translation(), world_T_camera.linear() * camera_.Backproject(pixel));
}

RayHit RayCaster::Cast(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
  RayHit hit;
  double best = kInfinity;
  if (d.z() < 0.0) {
    best = -o.z() / d.z();
    hit.kind =
        world_.OnFloor((o + best * d).head<2>()) ? RayHit::Kind::kFloor : RayHit::Kind::kGround;
  }
  const std::vector<Solid>& solids = world_.solids();
  for (std::size_t k = 0; k < solids.size(); ++k) {
    const Solid& solid = solids[k];
    const auto take = [&](double t, const Eigen::Vector3d& normal) {
      best = t;
      hit.kind = RayHit::Kind::kSolid;
      hit.normal = normal;
      hit.solid = static_cast<int>(k);
    };
    if (solid.circle) {
      // The side: |o + t·d - c|² = r² in the plane, the nearer root ahead.
      const Eigen::Vector2d f = o.head<2>() - solid.circle->centre;
      const Eigen::Vector2d dxy = d.head<2>();
      const double a = dxy.squaredNorm();
      const double b = f.dot(dxy);
      const double c = f.squaredNorm() - solid.circle->radius * solid.circle->radius;
      const double discriminant = b * b - a * c;
      if (a > 0.0 && discriminant >= 0.0 && c > 0.0 && b < 0.0) {
        const double t = c / (-b + std::sqrt(discriminant));  // the nearer root, stably
        const double z = o.z() + t * d.z();
        if (t > 0.0 && t < best && z >= 0.0 && z <= solid.height) {
          take(t, Eigen::Vector3d(f.x() + t * dxy.x(), f.y() + t * dxy.y(), 0.0).normalized());
        }
      }
    } else {
      const std::vector<Eigen::Vector2d>& polygon = solid.footprint;
      for (std::size_t i = 0; i < polygon.size(); ++i) {
        const Eigen::Vector2d a = polygon[i];
        const Eigen::Vector2d e = polygon[(i + 1) % polygon.size()] - a;
        // Solve o.xy + t·d.xy = a + s·e.
        const double den = d.x() * e.y() - d.y() * e.x();
        if (std::abs(den) < 1e-12) continue;
        const Eigen::Vector2d w = a - o.head<2>();
        const double t = (w.x() * e.y() - w.y() * e.x()) / den;
        const double s = (w.x() * d.y() - w.y() * d.x()) / den;
        const double z = o.z() + t * d.z();
        if (t > 0.0 && t < best && s >= 0.0 && s <= 1.0 && z >= 0.0 && z <= solid.height) {
          // Counter-clockwise footprint: the outward normal is the edge turned right.
          take(t, Eigen::Vector3d(e.y(), -e.x(), 0.0).normalized());
        }
      }
    }
    if (d.z() < 0.0 && o.z() > solid.height) {
      const double t = (solid.height - o.z()) / d.z();
      if (t < best && solid.SignedDistance((o + t * d).head<2>()) <= 0.0) {
        take(t, Eigen::Vector3d::UnitZ());
      }
    }
  }
  if (hit.kind != RayHit::Kind::kNothing) {
    hit.distance = best;
    hit.p_world = o + best * d;
  }
  return hit;
}

core::ImageRgb8 RayCaster::Render(const core::Pose2& world_T_robot) const {
  const Eigen::Isometry3d world_T_camera = WorldTCamera(world_T_robot);
  const Eigen::Vector3d origin = world_T_camera.translation();
  const Eigen::Vector3d towards_light = -world_.light().direction.normalized();
  core::ImageRgb8 image(camera_.width(), camera_.height());
  for (int v = 0; v < camera_.height(); ++v) {
    for (int u = 0; u < camera_.width(); ++u) {
      const RayHit hit = Cast(origin, world_T_camera.linear() *
                                          rays_[static_cast<std::size_t>(v) * camera_.width() + u]);
      core::Rgb colour{0, 0, 0};
      switch (hit.kind) {
        case RayHit::Kind::kFloor:
          colour = world_.floor().colour;
          break;
        case RayHit::Kind::kGround:
          colour = kOutsideColour;
          break;
        case RayHit::Kind::kSolid:
          colour = world_.solids()[static_cast<std::size_t>(hit.solid)].colour;
          break;
        case RayHit::Kind::kNothing:
          break;
      }
      const double shade = world_.light().ambient +
                           world_.light().intensity * std::max(0.0, hit.normal.dot(towards_light));
      const double rgb[3] = {colour.r * shade, colour.g * shade, colour.b * shade};
      std::uint8_t* p = image.Pixel(u, v);
      for (int c = 0; c < 3; ++c) {
        const double value = rgb[c] * camera_.VignettingGain(c, {u, v});
        p[c] = static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
      }
    }
  }
  return image;
}

std::vector<std::uint8_t> RayCaster::FloorMask(const core::Pose2& world_T_robot) const {
  const Eigen::Isometry3d world_T_camera = WorldTCamera(world_T_robot);
  std::vector<std::uint8_t> mask(rays_.size(), 0);
  for (std::size_t i = 0; i < rays_.size(); ++i) {
    const RayHit hit = Cast(world_T_camera.translation(), world_T_camera.linear() * rays_[i]);
    if (hit.kind == RayHit::Kind::kFloor) mask[i] = 255;
  }
  return mask;
}

const Eigen::Vector3d& RayCaster::PixelRay(int u, int v) const {
  return rays_[static_cast<std::size_t>(v) * camera_.width() + u];
}

bool RayCaster::SeesFreeFloor(const Eigen::Isometry3d& world_T_camera,
                              const Eigen::Vector2d& pixel) const {
  const double u = pixel.x();
  const double v = pixel.y();
  if (u == std::floor(u) && v == std::floor(v) && u >= 0 && v >= 0 && u < camera_.width() &&
      v < camera_.height()) {
    // A pixel centre: its ray is precomputed.
    const Eigen::Vector3d& ray = PixelRay(static_cast<int>(u), static_cast<int>(v));
    return Cast(world_T_camera.translation(), world_T_camera.linear() * ray).kind ==
           RayHit::Kind::kFloor;
  }
  return Cast(world_T_camera, pixel).kind == RayHit::Kind::kFloor;
}

std::optional<Eigen::Vector2d> RayCaster::FloorPoint(int u, double v) const {
  // A wide lens's pixel may see nothing (beyond a fisheye's image circle),
  // which only CameraModel::FloorPoint knows.
  if (v != std::floor(v) || v < 0 || v >= camera_.height() ||
      camera_.distortion().model != camera::Distortion::Model::kPlumbBob) {
    return camera_.FloorPoint({u, v});
  }
  // CameraModel::FloorPoint from the precomputed ray: the same arithmetic.
  const Eigen::Isometry3d robot_T_camera = camera_.robot_T_camera();
  const Eigen::Vector3d ray_robot = robot_T_camera.linear() * PixelRay(u, static_cast<int>(v));
  if (!(ray_robot.z() < -1e-5)) return std::nullopt;
  const Eigen::Vector3d origin = robot_T_camera.translation();
  const double t = -origin.z() / ray_robot.z();
  return (origin + t * ray_robot).head<2>();
}

core::ObstacleProfile RayCaster::TrueProfile(const core::Pose2& world_T_robot,
                                             double max_range_m) const {
  const Eigen::Isometry3d world_T_camera = WorldTCamera(world_T_robot);
  const Eigen::Isometry3d camera_T_world = world_T_camera.inverse();
  core::ObstacleProfile profile;
  profile.max_range_m = max_range_m;
  profile.readings.reserve(static_cast<std::size_t>(camera_.width()));
  const int bottom = camera_.height() - 1;
  for (int u = 0; u < camera_.width(); ++u) {
    const auto floor_point = [&](double v) { return FloorPoint(u, v); };
    const auto reading = [](const Eigen::Vector2d& p_robot, double range, core::ReadingKind kind) {
      return core::RangeReading{std::atan2(p_robot.y(), p_robot.x()), range, kind};
    };
    const std::optional<Eigen::Vector2d> bottom_point = floor_point(bottom);
    if (!SeesFreeFloor(world_T_camera, {u, bottom})) {
      const Eigen::Vector2d p = bottom_point.value_or(Eigen::Vector2d::UnitX());
      profile.readings.push_back(
          reading(p, bottom_point ? p.norm() : 0.0, core::ReadingKind::kBlind));
      continue;
    }
    std::optional<core::RangeReading> found;
    Eigen::Vector2d last_floor = *bottom_point;
    for (int v = bottom - 1; v >= 0 && !found; --v) {
      const std::optional<Eigen::Vector2d> p = floor_point(v);
      if (!SeesFreeFloor(world_T_camera, {u, v})) {
        // The edge lies between row v (not floor) and v + 1 (floor).
        double not_floor = v;
        double floor = v + 1.0;
        for (int i = 0; i < kEdgeBisections; ++i) {
          const double mid = 0.5 * (not_floor + floor);
          (SeesFreeFloor(world_T_camera, {u, mid}) ? floor : not_floor) = mid;
        }
        const Eigen::Vector2d edge = floor_point(floor).value_or(last_floor);
        found = edge.norm() <= max_range_m ? reading(edge, edge.norm(), core::ReadingKind::kHit)
                                           : reading(edge, max_range_m, core::ReadingKind::kClear);
        // Met above its base: the floor was seen to here, and what ends it
        // does not stand here.
        const RayHit hit = Cast(world_T_camera, {u, not_floor});
        if (hit.kind == RayHit::Kind::kSolid) {
          const Eigen::Vector3d foot(hit.p_world.x(), hit.p_world.y(), 0.0);
          const std::optional<Eigen::Vector2d> foot_pixel = camera_.Project(camera_T_world * foot);
          if (!foot_pixel || foot_pixel->y() - not_floor >= core::kMinSideRows) {
            found = reading(edge, std::min(edge.norm(), max_range_m), core::ReadingKind::kClear);
          }
        }
      } else if (!p || p->norm() > max_range_m) {
        found = reading(p.value_or(last_floor), max_range_m, core::ReadingKind::kClear);
      } else {
        last_floor = *p;
      }
    }
    profile.readings.push_back(
        found.value_or(reading(last_floor, max_range_m, core::ReadingKind::kClear)));
  }
  return profile;
}

}  // namespace pirouette::sim
