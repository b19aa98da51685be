#include "pirouette/mapping/radial_profile.h"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <numbers>

#include "pirouette/core/angle.h"

namespace pirouette::mapping {
namespace {

// The bin of a bearing (radians, any turn).
int BinOf(double bearing_rad) {
  double degrees = core::RadToDeg(bearing_rad);
  degrees -= 360.0 * std::floor(degrees / 360.0);
  const int bin = static_cast<int>(std::floor(degrees * kRadialProfileBins / 360.0));
  return std::clamp(bin, 0, kRadialProfileBins - 1);
}

int KindIndex(core::ReadingKind kind) { return static_cast<int>(kind); }

}  // namespace

std::vector<double> RadialProfile::Ranges() const {
  std::vector<double> ranges;
  ranges.reserve(bins.size());
  for (const RadialBin& bin : bins) ranges.push_back(bin.range_m);
  return ranges;
}

RadialProfile MergePirouette(const std::vector<HeadedProfile>& views) {
  RadialProfile rop;
  for (const HeadedProfile& view : views) {
    rop.max_range_m = std::max(rop.max_range_m, view.profile.max_range_m);
  }
  struct Tally {
    std::array<int, 3> count = {0, 0, 0};
    std::array<double, 3> nearest = {0.0, 0.0, 0.0};
  };
  std::vector<Tally> tallies(kRadialProfileBins);
  for (const HeadedProfile& view : views) {
    for (const core::RangeReading& reading : view.profile.readings) {
      Tally& tally =
          tallies[static_cast<std::size_t>(BinOf(view.heading_rad + reading.bearing_rad))];
      const int k = KindIndex(reading.kind);
      tally.nearest[k] =
          tally.count[k] == 0 ? reading.range_m : std::min(tally.nearest[k], reading.range_m);
      ++tally.count[k];
    }
  }
  rop.bins.resize(kRadialProfileBins);
  for (int b = 0; b < kRadialProfileBins; ++b) {
    const Tally& tally = tallies[static_cast<std::size_t>(b)];
    RadialBin& bin = rop.bins[static_cast<std::size_t>(b)];
    bin.readings = tally.count[0] + tally.count[1] + tally.count[2];
    bin.range_m = rop.max_range_m;
    bin.kind = core::ReadingKind::kClear;
    if (bin.readings == 0) continue;
    // A tie goes to the more cautious kind: hit, then blind, then clear.
    const int hits = tally.count[KindIndex(core::ReadingKind::kHit)];
    const int blinds = tally.count[KindIndex(core::ReadingKind::kBlind)];
    const int clears = tally.count[KindIndex(core::ReadingKind::kClear)];
    if (hits >= blinds && hits >= clears) {
      bin.kind = core::ReadingKind::kHit;
    } else if (blinds >= clears) {
      bin.kind = core::ReadingKind::kBlind;
    }
    if (bin.kind != core::ReadingKind::kClear) bin.range_m = tally.nearest[KindIndex(bin.kind)];
  }
  return rop;
}

std::vector<double> Dct(const std::vector<double>& x) {
  const std::size_t n = x.size();
  std::vector<double> coefficients(n, 0.0);
  if (n == 0) return coefficients;
  for (std::size_t k = 0; k < n; ++k) {
    double sum = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      sum += x[i] * std::cos(std::numbers::pi * static_cast<double>(k) *
                             (2.0 * static_cast<double>(i) + 1.0) / (2.0 * static_cast<double>(n)));
    }
    coefficients[k] = sum * std::sqrt((k == 0 ? 1.0 : 2.0) / static_cast<double>(n));
  }
  return coefficients;
}

std::vector<double> InverseDct(const std::vector<double>& coefficients) {
  const std::size_t n = coefficients.size();
  std::vector<double> x(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    double sum = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      sum += coefficients[k] * std::sqrt((k == 0 ? 1.0 : 2.0) / static_cast<double>(n)) *
             std::cos(std::numbers::pi * static_cast<double>(k) *
                      (2.0 * static_cast<double>(i) + 1.0) / (2.0 * static_cast<double>(n)));
    }
    x[i] = sum;
  }
  return x;
}

std::vector<double> DctLowPass(const std::vector<double>& x, int keep) {
  assert(keep >= 1);
  std::vector<double> coefficients = Dct(x);
  for (auto k = static_cast<std::size_t>(keep); k < coefficients.size(); ++k) {
    coefficients[k] = 0.0;
  }
  return InverseDct(coefficients);
}

}  // namespace pirouette::mapping
