#pragma once

#include <Eigen/Core>
#include <cmath>
#include <optional>
#include <vector>

namespace pirouette::core {

// What one bearing of a camera frame says about the floor around the robot
// (Taylor, Geva & Boles 2005, §3: the floor's edge read as a range sensor).
enum class ReadingKind {
  kHit,    // the floor ends at range_m, within the maximum range: an obstacle's base
  kClear,  // floor is seen all the way out to range_m: the maximum range, or less where
           // what lies past it is unresolved (vision::FloorSegmenter::Unresolved)
  kBlind,  // no floor is seen at all at this bearing: something fills the view;
           // range_m = the range of the nearest floor point the camera could see there
};

// One reading, in the robot's frame at the moment the frame was taken.
struct RangeReading {
  double bearing_rad = 0.0;  // counter-clockwise from the robot's forward axis
  double range_m = 0.0;      // from the robot's centre of rotation, on the floor
  ReadingKind kind = ReadingKind::kHit;
};

// The floor point reading `r` names, in the robot's frame (x forward, y to
// the left): range_m along bearing_rad.
inline Eigen::Vector2d PointOf(const RangeReading& r) {
  return {r.range_m * std::cos(r.bearing_rad), r.range_m * std::sin(r.bearing_rad)};
}

// The obstacle profile of one frame: one reading per image column, left to
// right (so bearings decrease), and the maximum range they were read with.
// `feet` are hits besides the columns' readings, in no order: the bases of
// obstacles that columns met above their base, each read kClear at its
// edge (vision::ExtractProfile). A column that crosses the slanted image of
// an obstacle's vertical side sees the floor up to where the side ends it,
// but the obstacle stands at the foot of that side (Taylor, Geva & Boles
// 2005, §5.2); the foot is what the column's reading would otherwise lose.
struct ObstacleProfile {
  std::vector<RangeReading> readings;
  double max_range_m = 0.0;
  std::vector<RangeReading> feet;  // all kHit, within max_range_m
};

// A column that meets an obstacle this many image rows or more above the
// image of its base meets the obstacle's side, not its base: the extractor
// (vision::ExtractProfile, by its walk down the vertical) and the ray-cast
// truth (sim::RayCaster::TrueProfile) tell it by the same count. Fewer rows
// are a base line sloping across the columns.
inline constexpr int kMinSideRows = 3;

// How a profile's readings read: counts of each kind (the columns'), its
// feet, and the nearest hit, a column's or a foot's.
struct ProfileCounts {
  int hit = 0;
  int clear = 0;
  int blind = 0;
  int feet = 0;
  std::optional<double> nearest_hit_m;  // nullopt: no hit and no foot
};

inline ProfileCounts CountReadings(const ObstacleProfile& profile) {
  ProfileCounts counts;
  for (const RangeReading& r : profile.readings) {
    switch (r.kind) {
      case ReadingKind::kHit:
        ++counts.hit;
        if (!counts.nearest_hit_m || r.range_m < *counts.nearest_hit_m) {
          counts.nearest_hit_m = r.range_m;
        }
        break;
      case ReadingKind::kClear:
        ++counts.clear;
        break;
      case ReadingKind::kBlind:
        ++counts.blind;
        break;
    }
  }
  counts.feet = static_cast<int>(profile.feet.size());
  for (const RangeReading& foot : profile.feet) {
    if (!counts.nearest_hit_m || foot.range_m < *counts.nearest_hit_m) {
      counts.nearest_hit_m = foot.range_m;
    }
  }
  return counts;
}

}  // namespace pirouette::core
