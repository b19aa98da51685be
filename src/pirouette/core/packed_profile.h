#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "pirouette/core/obstacle_profile.h"

namespace pirouette::core {

// An obstacle profile as a run keeps it for every frame (to put the frame in
// the map again where a pose graph moves it): bearings and ranges as floats
// and kinds as bytes, 9 bytes a reading instead of ObstacleProfile's 24.
// Unpacked, a reading differs from the original by float rounding only
// (a relative 6e-8: under a micrometre at 10 m); a run maps every frame
// from its packed profile, so the first map and every rebuild agree.
class PackedProfile {
 public:
  PackedProfile() = default;
  // The columns' readings first, then the feet.
  explicit PackedProfile(const ObstacleProfile& profile)
      : max_range_m_(profile.max_range_m), columns_(profile.readings.size()) {
    const std::size_t n = profile.readings.size() + profile.feet.size();
    bearing_rad_.reserve(n);
    range_m_.reserve(n);
    kind_.reserve(n);
    for (const auto* readings : {&profile.readings, &profile.feet}) {
      for (const RangeReading& r : *readings) {
        bearing_rad_.push_back(static_cast<float>(r.bearing_rad));
        range_m_.push_back(static_cast<float>(r.range_m));
        kind_.push_back(static_cast<std::uint8_t>(r.kind));
      }
    }
  }

  // Readings, the feet included.
  std::size_t size() const { return kind_.size(); }

  ObstacleProfile Unpack() const {
    ObstacleProfile profile;
    profile.max_range_m = max_range_m_;
    profile.readings.resize(columns_);
    profile.feet.resize(kind_.size() - columns_);
    for (std::size_t i = 0; i < kind_.size(); ++i) {
      RangeReading& r = i < columns_ ? profile.readings[i] : profile.feet[i - columns_];
      r = {bearing_rad_[i], range_m_[i], static_cast<ReadingKind>(kind_[i])};
    }
    return profile;
  }

 private:
  double max_range_m_ = 0.0;
  std::size_t columns_ = 0;
  std::vector<float> bearing_rad_;
  std::vector<float> range_m_;
  std::vector<std::uint8_t> kind_;
};

}  // namespace pirouette::core
