#pragma once

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "pirouette/core/obstacle_profile.h"
#include "pirouette/eval/floor_masker.h"

namespace pirouette::eval {

struct PerceptionEvalRequest {
  std::vector<std::string> world_paths;
  vision::MaskSource method = vision::MaskSource::kDefault;
  int poses = 20;                     // random poses a world, a pirouette (12 frames) at each
  std::uint64_t seed = 1;             // the poses, the sensor noise and the odometry noise
  double cell_m = 0.01;               // the max range is derived for this cell size...
  std::optional<double> max_range_m;  // ...unless given
};

// The comparison of measured obstacle profiles with the truth, column by column.
struct ProfileComparison {
  // confusion[truth][measured], indexed by core::ReadingKind.
  std::array<std::array<long, 3>, 3> confusion = {};
  // measured - true range of the columns that are hits in both (> 0: read too far).
  std::vector<double> range_errors_m;

  long columns() const;
  double WrongClassRate() const;
  void Add(const core::ObstacleProfile& truth, const core::ObstacleProfile& measured);
  void Add(const ProfileComparison& other);
};

struct WorldPerception {
  std::string world_path;
  std::string world_name;
  std::string camera_name;
  double max_range_m = 0.0;
  int frames = 0;
  double seconds_per_frame = 0.0;  // render, segment and extract, wall clock
  // The true hits, and those of them that end the floor at an obstacle's
  // silhouette (a column crossing the slanted image of a vertical edge, the
  // paper's §5.2) rather than at its base: their floor point lies in free
  // floor behind the obstacle. The truth reads a column that meets such an
  // edge 3 rows or more above its foot as clear (sim::RayCaster::
  // TrueProfile), so those left met it nearer its foot.
  long true_hits = 0;
  long silhouette_hits = 0;
  // The measured hits (the profiles' feet among them), and those of them
  // whose floor point lies farther than a map cell (the request's cell_m)
  // from every obstacle: obstacles seen on open floor, which the map draws a
  // cell or more off.
  long measured_hits = 0;
  long measured_hits_off_obstacles = 0;
  ProfileComparison comparison;
};

// `pirouette perception-eval`: in each world, the simulated robot makes a
// pirouette at `poses` random poses where it fits (one segmenter a world,
// learning online through the frames in order); each frame's obstacle
// profile (segmenter + vision::ExtractProfile) is compared column by column
// with sim::RayCaster::TrueProfile. Throws core::InputError for a bad world
// file or option, sim::RenderError when it cannot render.
std::vector<WorldPerception> EvaluatePerception(const PerceptionEvalRequest& request);

}  // namespace pirouette::eval
