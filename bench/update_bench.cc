// Occupancy grid updates: pirouette's grid against OctoMap inserting the same
// rays, one thread.
//
//   build/release/bench/pirouette_bench --benchmark_filter='update/'
//
// The rays: 16 stops on a 4 × 4 m floor, a pirouette of 12 frames at each
// (192 frames), 320 columns a frame over a 60° field of view (the paper's
// camera), ranges up to 0.4 m: runs of hits along walls, clear runs out to the
// maximum range, now and then a blind run, from a fixed seed. Cells are 1 cm.
//
// update/pirouette: mapping::InsertProfile into an OccupancyGrid covering the
//   floor and 0.5 m around it (so it never grows while timed).
// update/octomap: an octomap::OcTree of resolution 0.01 with the same
//   probabilities and clamps, the rays in the plane z = 0.005 (the middle of
//   the layer of voxels on the floor). Per frame it does what
//   OcTree::insertPointCloud does (computeUpdate, then updateNode), with the
//   same sensor model as ours: computeRayKeys into key sets so that each voxel
//   changes once a frame, occupied ends removed from the free and blind sets
//   (a hit wins), blind removed from free, then updateNode on each (blind: a
//   plain Bayes step with the log-odds of 0.6, not capped as ours).
//   insertPointCloud cannot be called as is: it has no blind reading and one
//   maximum range for a whole cloud.
//
// items/s is cell updates a second: the cells each side changed (the sizes of
// its key sets for OctoMap, InsertProfile's count for us). Both use the same
// exact traversal (OctoMap's 3-D DDA in a plane is Amanatides–Woo in 2-D), so
// the counts agree (`updates`, a frame: the same on both). The ratio of the
// two rates is the ratio of the times for the same frames. OctoMap casts every
// ray whole (~50 cells, a key-set insert each); InsertProfile skips the parts
// of a ray that its neighbours already covered.
// Both maps persist across iterations, so after the first pass most cells sit
// at a clamp, as in a long run that keeps looking at the same floor.

#include <benchmark/benchmark.h>
#include <octomap/OcTree.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <random>
#include <utility>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/core/grid_geometry.h"
#include "pirouette/core/obstacle_profile.h"
#include "pirouette/core/pose2.h"
#include "pirouette/mapping/occupancy_grid.h"
#include "pirouette/mapping/range_sensor_model.h"

namespace {

using pirouette::core::DegToRad;
using pirouette::core::ObstacleProfile;
using pirouette::core::Pose2;
using pirouette::core::ReadingKind;

constexpr double kCell = 0.01;
constexpr double kMaxRange = 0.4;
constexpr double kBlindRange = 0.12;
constexpr int kColumns = 320;
constexpr double kFieldOfViewDeg = 60.0;

struct Frame {
  Pose2 world_T_robot;
  ObstacleProfile profile;
};

// The frames, built once from a fixed seed (std::mt19937's output is fixed by
// the standard; the ranges are derived from it by hand, not by a
// distribution, so they are the same everywhere).
const std::vector<Frame>& Frames() {
  static const std::vector<Frame> frames = [] {
    std::mt19937 random(20050101);
    const auto uniform = [&random](double lo, double hi) {
      return lo + (hi - lo) * static_cast<double>(random()) / 4294967296.0;
    };
    std::vector<Frame> result;
    for (int stop = 0; stop < 16; ++stop) {
      const int stop_x = stop % 4;
      const int stop_y = stop / 4;
      const double x = 0.5 + stop_x + uniform(-0.2, 0.2);
      const double y = 0.5 + stop_y + uniform(-0.2, 0.2);
      const double start = uniform(0.0, 30.0);
      for (int view = 0; view < 12; ++view) {
        Frame frame{Pose2(x, y, DegToRad(start + 30.0 * view)), ObstacleProfile{{}, kMaxRange, {}}};
        // Runs of 20 to 80 columns, each a wall seen at an angle (a range
        // that changes linearly), clear floor, or a blind patch.
        int column = 0;
        while (column < kColumns) {
          const int run = 20 + static_cast<int>(uniform(0.0, 61.0));
          const double kind = uniform(0.0, 1.0);
          const double near = uniform(0.12, kMaxRange);
          const double slope = uniform(-0.003, 0.003);
          for (int i = 0; i < run && column < kColumns; ++i, ++column) {
            const double bearing =
                DegToRad(kFieldOfViewDeg / 2 - kFieldOfViewDeg * (column + 0.5) / kColumns);
            if (kind < 0.6) {
              const double range = std::clamp(near + slope * i, 0.1, kMaxRange - 1e-3);
              frame.profile.readings.push_back({bearing, range, ReadingKind::kHit});
            } else if (kind < 0.9) {
              frame.profile.readings.push_back({bearing, kMaxRange, ReadingKind::kClear});
            } else {
              frame.profile.readings.push_back({bearing, kBlindRange, ReadingKind::kBlind});
            }
          }
        }
        result.push_back(std::move(frame));
      }
    }
    return result;
  }();
  return frames;
}

// With solid walls (the default) or without (two_places_m 0: no ray is
// ever stopped, and the walk that looks for solid cells is skipped): what
// that walk costs.
void UpdatePirouette(benchmark::State& state, bool solid) {
  const auto& frames = Frames();
  pirouette::mapping::OccupancyOptions options;
  if (!solid) options.two_places_m = 0.0;
  // The floor and the 0.4 m the robot sees past its edges: no growth.
  pirouette::mapping::OccupancyGrid grid(
      pirouette::core::GridGeometry::Covering(kCell, {-0.5, -0.5}, {5.0, 5.0}), options);
  std::int64_t updates = 0;
  for (auto _ : state) {
    for (const Frame& frame : frames) {
      updates += static_cast<std::int64_t>(
          pirouette::mapping::InsertProfile(grid, frame.profile, frame.world_T_robot));
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(updates);
  state.counters["updates"] =
      static_cast<double>(updates) / static_cast<double>(state.iterations() * frames.size());
}

void UpdateOctomap(benchmark::State& state) {
  const auto& frames = Frames();
  const pirouette::mapping::OccupancyOptions options;
  octomap::OcTree tree(kCell);
  tree.setProbHit(options.hit_probability);
  tree.setProbMiss(options.miss_probability);
  tree.setClampingThresMin(options.clamp_min_probability);
  tree.setClampingThresMax(options.clamp_max_probability);
  const float blind_log_odds = octomap::logodds(options.blind_probability);
  constexpr double kZ = 0.005;
  octomap::KeyRay key_ray;
  octomap::KeySet free_cells;
  octomap::KeySet occupied_cells;
  octomap::KeySet blind_cells;
  std::int64_t updates = 0;
  for (auto _ : state) {
    for (const Frame& frame : frames) {
      free_cells.clear();
      occupied_cells.clear();
      blind_cells.clear();
      const Pose2& pose = frame.world_T_robot;
      const octomap::point3d origin(static_cast<float>(pose.x()), static_cast<float>(pose.y()),
                                    static_cast<float>(kZ));
      for (const auto& reading : frame.profile.readings) {
        const Eigen::Vector2d end =
            pose * Eigen::Vector2d(reading.range_m * std::cos(reading.bearing_rad),
                                   reading.range_m * std::sin(reading.bearing_rad));
        const octomap::point3d end3(static_cast<float>(end.x()), static_cast<float>(end.y()),
                                    static_cast<float>(kZ));
        if (!tree.computeRayKeys(origin, end3, key_ray)) continue;
        switch (reading.kind) {
          case ReadingKind::kHit:
            free_cells.insert(key_ray.begin(), key_ray.end());
            occupied_cells.insert(tree.coordToKey(end3));
            break;
          case ReadingKind::kClear:
            free_cells.insert(key_ray.begin(), key_ray.end());
            free_cells.insert(tree.coordToKey(end3));
            break;
          case ReadingKind::kBlind:
            blind_cells.insert(key_ray.begin(), key_ray.end());
            blind_cells.insert(tree.coordToKey(end3));
            break;
        }
      }
      for (const auto& key : occupied_cells) {
        tree.updateNode(key, true);
        ++updates;
      }
      for (const auto& key : blind_cells) {
        if (occupied_cells.count(key) != 0) continue;
        tree.updateNode(key, blind_log_odds);
        ++updates;
      }
      for (const auto& key : free_cells) {
        if (occupied_cells.count(key) != 0 || blind_cells.count(key) != 0) continue;
        tree.updateNode(key, false);
        ++updates;
      }
    }
    benchmark::ClobberMemory();
  }
  state.SetItemsProcessed(updates);
  state.counters["updates"] =
      static_cast<double>(updates) / static_cast<double>(state.iterations() * frames.size());
}

}  // namespace

BENCHMARK_CAPTURE(UpdatePirouette, solid, true)
    ->Name("update/pirouette")
    ->Unit(benchmark::kMillisecond);
BENCHMARK_CAPTURE(UpdatePirouette, no_solid, false)
    ->Name("update/pirouette-without-solid-walls")
    ->Unit(benchmark::kMillisecond);
BENCHMARK(UpdateOctomap)->Name("update/octomap")->Unit(benchmark::kMillisecond);
