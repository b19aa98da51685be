#include "pirouette/eval/perception_eval.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <numbers>
#include <random>

#include "pirouette/camera/inverse_perspective_map.h"
#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/image_io.h"
#include "pirouette/io/world_file.h"
#include "pirouette/sim/ray_caster.h"
#include "pirouette/sim/renderer.h"
#include "pirouette/sim/simulated_pirouette.h"
#include "pirouette/vision/profile_extractor.h"
#include "pirouette/vision/vertical_direction_field.h"

namespace pirouette::eval {
namespace {

// A true hit whose floor point is farther than this from every obstacle ends
// the floor at an obstacle's silhouette, not at its base.
constexpr double kSilhouetteGap = 0.001;

// Adds a profile's hits (its feet among them) to `hits`, and to `off` those whose floor point lies
// farther than gap_m from every obstacle of the world.
void CountHits(const core::ObstacleProfile& profile, const core::Pose2& world_T_robot,
               const sim::World& world, double gap_m, long& hits, long& off) {
  for (const auto* readings : {&profile.readings, &profile.feet}) {
    for (const core::RangeReading& r : *readings) {
      if (r.kind != core::ReadingKind::kHit) continue;
      ++hits;
      const Eigen::Vector2d p_world = world_T_robot * core::PointOf(r);
      if (world.Clearance(p_world) > gap_m) ++off;
    }
  }
}

// A pose where the robot's disc fits, uniformly over the floor and headings.
core::Pose2 RandomPose(const sim::World& world, std::mt19937_64& rng) {
  std::uniform_real_distribution<double> x(0.0, world.floor().size.x());
  std::uniform_real_distribution<double> y(0.0, world.floor().size.y());
  std::uniform_real_distribution<double> heading(-std::numbers::pi, std::numbers::pi);
  for (int attempt = 0; attempt < 100000; ++attempt) {
    const Eigen::Vector2d p(x(rng), y(rng));
    const double h = heading(rng);
    if (world.DiscFits(p, world.robot().radius)) return {p.x(), p.y(), h};
  }
  return world.robot().start;
}

}  // namespace

long ProfileComparison::columns() const {
  long n = 0;
  for (const auto& row : confusion) {
    for (const long count : row) n += count;
  }
  return n;
}

double ProfileComparison::WrongClassRate() const {
  const long n = columns();
  if (n == 0) return 0.0;
  return 1.0 - static_cast<double>(confusion[0][0] + confusion[1][1] + confusion[2][2]) /
                   static_cast<double>(n);
}

void ProfileComparison::Add(const core::ObstacleProfile& truth,
                            const core::ObstacleProfile& measured) {
  const std::size_t n = std::min(truth.readings.size(), measured.readings.size());
  for (std::size_t i = 0; i < n; ++i) {
    const core::RangeReading& t = truth.readings[i];
    const core::RangeReading& m = measured.readings[i];
    ++confusion[static_cast<std::size_t>(t.kind)][static_cast<std::size_t>(m.kind)];
    if (t.kind == core::ReadingKind::kHit && m.kind == core::ReadingKind::kHit) {
      range_errors_m.push_back(m.range_m - t.range_m);
    }
  }
}

void ProfileComparison::Add(const ProfileComparison& other) {
  for (std::size_t t = 0; t < 3; ++t) {
    for (std::size_t m = 0; m < 3; ++m) confusion[t][m] += other.confusion[t][m];
  }
  range_errors_m.insert(range_errors_m.end(), other.range_errors_m.begin(),
                        other.range_errors_m.end());
}

std::vector<WorldPerception> EvaluatePerception(const PerceptionEvalRequest& request) {
  if (request.poses < 1) throw core::InputError("--poses", 0, "", "must be at least 1");
  if (!(request.cell_m > 0.0)) throw core::InputError("--cell", 0, "", "must be > 0 (metres)");
  if (request.max_range_m && !(*request.max_range_m > 0.0)) {
    throw core::InputError("--max-range", 0, "", "must be > 0 (metres)");
  }
  std::vector<WorldPerception> results;
  for (const std::string& path : request.world_paths) {
    const sim::World world = io::LoadWorldFile(path);
    const camera::CameraModel& camera = world.robot().camera;
    WorldPerception result;
    result.world_path = path;
    result.world_name = world.name();
    result.camera_name = camera.name();
    result.max_range_m = request.max_range_m.value_or(camera::MaxRange(camera, request.cell_m));
    sim::RenderOptions options;
    options.seed = request.seed;
    sim::Renderer renderer(world, camera, options);
    const sim::RayCaster caster(world, camera);
    const camera::InversePerspectiveMap ipm(camera);
    const vision::VerticalDirectionField vertical(camera);
    FloorMasker masker(request.method, world, camera);
    std::mt19937_64 rng(request.seed);
    double seconds = 0.0;
    for (int i = 0; i < request.poses; ++i) {
      const sim::World placed = sim::PlaceRobot(world, RandomPose(world, rng), path);
      const auto since = [](std::chrono::steady_clock::time_point start) {
        return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      };
      const auto render_start = std::chrono::steady_clock::now();
      const std::vector<sim::SimulatedFrame> frames =
          sim::SimulatePirouette(placed, renderer, request.seed + static_cast<std::uint64_t>(i));
      seconds += since(render_start);
      for (const sim::SimulatedFrame& frame : frames) {
        const auto start = std::chrono::steady_clock::now();
        const cv::Mat1b mask = masker.Mask(io::ToBgrMat(frame.frame.image), frame.world_T_robot);
        const core::ObstacleProfile measured =
            vision::ExtractProfile(mask, ipm, result.max_range_m, masker.Unresolved(), &vertical);
        seconds += since(start);
        const core::ObstacleProfile truth =
            caster.TrueProfile(frame.world_T_robot, result.max_range_m);
        result.comparison.Add(truth, measured);
        CountHits(measured, frame.world_T_robot, world, request.cell_m, result.measured_hits,
                  result.measured_hits_off_obstacles);
        CountHits(truth, frame.world_T_robot, world, kSilhouetteGap, result.true_hits,
                  result.silhouette_hits);
        ++result.frames;
      }
    }
    result.seconds_per_frame = result.frames > 0 ? seconds / result.frames : 0.0;
    results.push_back(std::move(result));
  }
  return results;
}

}  // namespace pirouette::eval
