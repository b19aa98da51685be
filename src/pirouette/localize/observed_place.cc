#include "pirouette/localize/observed_place.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>

#include "pirouette/core/angle.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::localize {
namespace {

constexpr int kBins = mapping::kRadialProfileBins;

int BinOf(double bearing_rad) {
  double a = std::fmod(bearing_rad, 2.0 * std::numbers::pi);
  if (a < 0.0) a += 2.0 * std::numbers::pi;
  return std::clamp(static_cast<int>(std::floor(core::RadToDeg(a) * kBins / 360.0)), 0, kBins - 1);
}

}  // namespace

ObservedPlace ObservePlace(const std::vector<PirouetteFrame>& frames) {
  std::vector<mapping::HeadedProfile> views;
  std::vector<std::array<int, core::kColourClasses>> votes(kBins);
  for (const PirouetteFrame& frame : frames) {
    const std::vector<core::RangeReading>& readings = frame.profile.readings;
    for (std::size_t u = 0; u < readings.size() && u < frame.column_colours.size(); ++u) {
      const core::RangeReading& r = readings[u];
      const core::ColourClass c = frame.column_colours[u];
      if (r.kind == core::ReadingKind::kClear || c == core::ColourClass::kNone) continue;
      ++votes[static_cast<std::size_t>(BinOf(r.bearing_rad + frame.heading_rad))]
             [static_cast<std::size_t>(c)];
    }
    views.push_back({frame.heading_rad, frame.profile});
  }
  const mapping::RadialProfile rop = mapping::MergePirouette(views);
  ObservedPlace out;
  out.view.ranges_m = rop.Ranges();
  for (int b = 0; b < kBins; ++b) {
    const mapping::RadialBin& bin = rop.bins[static_cast<std::size_t>(b)];
    out.kinds.push_back(bin.kind);
    const auto& v = votes[static_cast<std::size_t>(b)];
    const auto best = std::max_element(v.begin(), v.end());
    out.view.colours.push_back(bin.kind != core::ReadingKind::kClear && *best > 0
                                   ? static_cast<core::ColourClass>(best - v.begin())
                                   : core::ColourClass::kNone);
  }
  return out;
}

}  // namespace pirouette::localize
