#pragma once

#include <Eigen/Core>
#include <vector>

#include "pirouette/core/obstacle_profile.h"
#include "pirouette/mapping/occupancy_grid.h"

namespace pirouette::localize {

// What the map says along one bearing from a point.
struct MapRay {
  enum class Kind { kHit, kClear, kUnknown };
  Kind kind = Kind::kUnknown;
  double range_m = 0.0;  // to the first occupied cell (kHit)
};

// The map's own radial profile from `origin` (Taylor, Geva & Boles 2005,
// §5.3's ROP, read off the map instead of the camera): for each of `bins`
// bearings counter-clockwise from the map's +x, the first occupied cell
// within max_range_m along the ray (kHit), or free cells all the way
// (kClear), or kUnknown when the ray meets a cell that is neither free nor
// occupied first: the map cannot say what the camera would see there.
class MapProfile {
 public:
  // Throws std::invalid_argument unless bins >= 1 and max_range_m >= 0.
  MapProfile(const mapping::OccupancyGrid& grid, const Eigen::Vector2d& origin, double max_range_m,
             int bins = 3600);

  // The ray nearest `bearing_rad`.
  const MapRay& At(double bearing_rad) const;
  int bins() const { return static_cast<int>(rays_.size()); }

 private:
  std::vector<MapRay> rays_;
};

struct HeadingMatch {
  double offset_rad = 0.0;  // add to the predicted heading
  double score = 0.0;       // the compared readings' mean agreement there, [0, 1]
  int compared = 0;         // readings compared with a known ray
  bool accepted = false;    // enough readings compared; else offset 0
};

struct HeadingMatcherOptions {
  double step_rad = 0.05 * 3.14159265358979323846 / 180.0;
  // A hit agrees with a map hit by exp(-d²/2σ²), σ = max(floor, fraction × range).
  double sigma_floor_m = 0.01;
  double sigma_fraction = 0.02;
  int min_compared = 30;
  // The odometry prior's weight, in readings per unit of (offset / σ)² / 2:
  // the readings' errors are not independent (a wall's range is off by the
  // same millimetres all along it), so their sum is worth far less than as
  // many independent readings. A wall seen face on pins no heading: its
  // agreement hardly changes with the offset, and then the prior keeps the
  // odometry's heading.
  double prior_weight = 20.0;
  // Between two views' readings (MatchToViews): σ = max(floor, fraction × range).
  double view_sigma_floor_m = 0.002;
  double view_sigma_fraction = 0.01;

  // Throws std::invalid_argument unless every field is in range.
  void Check() const;
};

// The heading of a frame taken at the map profile's origin, by a beam model
// (Thrun, Burgard & Fox 2005, §6.3) against the map's rays: the offset from
// `predicted_heading` within ±3σ (σ = sigma_rad, the odometry's) that
// maximises the sum of the readings' agreement with the map minus the
// prior's prior_weight × (offset / σ)² / 2. Hits are compared by range,
// clear readings agree with clear rays, a hit against a clear ray or the
// other way round disagrees; blind readings and those whose rays reach the
// unknown anywhere in the window take no part (the same readings count at
// every offset, so none can gain by moving onto the known part of a wall).
HeadingMatch MatchHeading(const MapProfile& map, const core::ObstacleProfile& profile,
                          double predicted_heading, double sigma_rad,
                          const HeadingMatcherOptions& options = {});

// A frame's profile and its heading in the map, taken where the others were.
struct HeadedView {
  const core::ObstacleProfile* profile = nullptr;
  double heading_rad = 0.0;
};

// The heading of a frame taken where `views` were (one stop: the robot only
// turned), by comparing its readings directly with theirs along the same
// bearings (each view's readings interpolated between its columns): the
// offset from `predicted_heading` within ±3σ maximising the summed
// agreement minus the prior, as MatchHeading, but without the map's cells
// in between (a centimetre cell hides the millimetres that tell a degree
// on a wall seen nearly face on). Only readings that fall inside some view
// at both ends of the window take part. Where the view's neighbouring
// columns differ in kind (an edge, which could lie anywhere between them) a
// reading takes the better agreement of the two; a blind column counts as
// a hit at its range. score is the mean agreement of those compared at the
// answer.
HeadingMatch MatchToViews(const std::vector<HeadedView>& views,
                          const core::ObstacleProfile& profile, double predicted_heading,
                          double sigma_rad, const HeadingMatcherOptions& options = {});

}  // namespace pirouette::localize
