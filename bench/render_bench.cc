// The renderer's frames per second on the CPU path (Mesa's llvmpipe through
// EGL where there is no GPU), against the straightforward version: a plain
// CPU ray caster of the same scene (floor and vertical prisms, the same
// shading, the same lens and vignetting, one ray a pixel, no anti-aliasing).
//
//   build/release/bench/pirouette_bench --benchmark_filter='render/'
//
// Names follow `<stage>/<who>/<size>`.

#include <benchmark/benchmark.h>

#include <cmath>
#include <limits>
#include <optional>
#include <string>

#include "pirouette/core/angle.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/sim/world_file.h"

namespace {

using pirouette::camera::CameraModel;
using pirouette::core::ImageRgb8;
using pirouette::core::Pose2;
using pirouette::sim::World;

const World& SoccerField() {
  static const World world =
      pirouette::sim::LoadWorldFile(std::string(PIROUETTE_WORLDS_DIR) + "/soccer_field.yaml");
  return world;
}

// The paper's camera scaled to another resolution (same field of view).
CameraModel Scaled(const CameraModel& camera, int width, int height) {
  const double s = static_cast<double>(width) / camera.width();
  auto k = camera.intrinsics();
  k.fx *= s;
  k.fy *= s;
  k.cx = (k.cx + 0.5) * s - 0.5;
  k.cy = (k.cy + 0.5) * s - 0.5;
  return {camera.name(),      width, height, k, camera.distortion(), camera.mount(),
          camera.vignetting()};
}

// The straightforward renderer: cast each pixel's ray against the floor and
// every prism's sides and top.
class RayCaster {
 public:
  RayCaster(const World& world, const CameraModel& camera) : world_(world), camera_(camera) {
    rays_.reserve(static_cast<std::size_t>(camera.width()) * camera.height());
    for (int v = 0; v < camera.height(); ++v) {
      for (int u = 0; u < camera.width(); ++u) rays_.push_back(camera.Backproject({u, v}));
    }
    towards_light_ = -world.light().direction.normalized();
  }

  ImageRgb8 Render(const Pose2& world_T_robot) const {
    Eigen::Isometry3d world_T_robot3 = Eigen::Isometry3d::Identity();
    world_T_robot3.linear() =
        Eigen::AngleAxisd(world_T_robot.heading(), Eigen::Vector3d::UnitZ()).toRotationMatrix();
    world_T_robot3.translation() << world_T_robot.x(), world_T_robot.y(), 0.0;
    const Eigen::Isometry3d world_T_camera = world_T_robot3 * camera_.robot_T_camera();
    const Eigen::Vector3d origin = world_T_camera.translation();
    ImageRgb8 image(camera_.width(), camera_.height());
    for (int v = 0; v < camera_.height(); ++v) {
      for (int u = 0; u < camera_.width(); ++u) {
        const Eigen::Vector3d d =
            world_T_camera.linear() * rays_[static_cast<std::size_t>(v) * camera_.width() + u];
        const Eigen::Vector3d rgb = Shade(origin, d);
        std::uint8_t* p = image.Pixel(u, v);
        for (int c = 0; c < 3; ++c) {
          const double value = 255.0 * rgb[c] * camera_.VignettingGain(c, {u, v});
          p[c] = static_cast<std::uint8_t>(std::clamp(std::lround(value), 0L, 255L));
        }
      }
    }
    return image;
  }

 private:
  Eigen::Vector3d Shade(const Eigen::Vector3d& o, const Eigen::Vector3d& d) const {
    double best = std::numeric_limits<double>::infinity();
    Eigen::Vector3d normal = Eigen::Vector3d::UnitZ();
    pirouette::core::Rgb colour{0, 0, 0};
    if (d.z() < 0.0) {
      best = -o.z() / d.z();
      const Eigen::Vector2d p = (o + best * d).head<2>();
      colour = world_.OnFloor(p) ? world_.floor().colour : pirouette::core::Rgb{120, 120, 120};
    }
    for (const auto& solid : world_.solids()) {
      const auto& poly = solid.footprint;
      for (std::size_t i = 0; i < poly.size(); ++i) {
        const Eigen::Vector2d a = poly[i];
        const Eigen::Vector2d e = poly[(i + 1) % poly.size()] - a;
        // Solve o.xy + t d.xy = a + s e.
        const double den = d.x() * e.y() - d.y() * e.x();
        if (std::abs(den) < 1e-12) continue;
        const Eigen::Vector2d w = a - o.head<2>();
        const double t = (w.x() * e.y() - w.y() * e.x()) / den;
        const double s = (w.x() * d.y() - w.y() * d.x()) / den;
        const double z = o.z() + t * d.z();
        if (t > 0.0 && t < best && s >= 0.0 && s <= 1.0 && z >= 0.0 && z <= solid.height) {
          best = t;
          normal = Eigen::Vector3d(e.y(), -e.x(), 0.0).normalized();
          colour = solid.colour;
        }
      }
      if (d.z() < 0.0 && o.z() > solid.height) {
        const double t = (solid.height - o.z()) / d.z();
        if (t < best && solid.SignedDistance((o + t * d).head<2>()) <= 0.0) {
          best = t;
          normal = Eigen::Vector3d::UnitZ();
          colour = solid.colour;
        }
      }
    }
    const double shade = world_.light().ambient +
                         world_.light().intensity * std::max(0.0, normal.dot(towards_light_));
    return Eigen::Vector3d(colour.r, colour.g, colour.b) * (shade / 255.0);
  }

  const World& world_;
  CameraModel camera_;
  std::vector<Eigen::Vector3d> rays_;
  Eigen::Vector3d towards_light_;
};

void RenderPirouette(benchmark::State& state, int width, int height) {
  const World& world = SoccerField();
  const CameraModel camera = Scaled(world.robot().camera, width, height);
  pirouette::sim::Renderer renderer(world, camera, {});
  state.SetLabel(renderer.gl_renderer());
  double heading = 0.0;
  for (auto _ : state) {
    heading += pirouette::core::DegToRad(30.0);
    benchmark::DoNotOptimize(renderer.Render(Pose2(0.75, 0.65, heading)));
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

void RenderRayCaster(benchmark::State& state, int width, int height) {
  const World& world = SoccerField();
  const RayCaster caster(world, Scaled(world.robot().camera, width, height));
  double heading = 0.0;
  for (auto _ : state) {
    heading += pirouette::core::DegToRad(30.0);
    benchmark::DoNotOptimize(caster.Render(Pose2(0.75, 0.65, heading)));
  }
  state.counters["fps"] =
      benchmark::Counter(static_cast<double>(state.iterations()), benchmark::Counter::kIsRate);
}

BENCHMARK_CAPTURE(RenderPirouette, 320x240, 320, 240)
    ->Name("render/pirouette/320x240")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RenderRayCaster, 320x240, 320, 240)
    ->Name("render/straightforward/320x240")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RenderPirouette, 640x480, 640, 480)
    ->Name("render/pirouette/640x480")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(RenderRayCaster, 640x480, 640, 480)
    ->Name("render/straightforward/640x480")
    ->Unit(benchmark::kMillisecond);

}  // namespace
