#include "pirouette/mapping/radial_profile.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pirouette/core/angle.h"

namespace pirouette::mapping {
namespace {

using core::DegToRad;
using core::ReadingKind;

// A frame 60° across with 120 columns, left to right, each column's bearing at
// the centre of a half-degree, reading `range(bearing_in_odometry_deg)`.
template <typename RangeFunction>
HeadedProfile View(double heading_deg, RangeFunction range) {
  HeadedProfile view;
  view.heading_rad = DegToRad(heading_deg);
  view.profile.max_range_m = 0.4;
  for (int c = 0; c < 120; ++c) {
    const double bearing_deg = 29.75 - 0.5 * c;
    const double r = range(heading_deg + bearing_deg);
    view.profile.readings.push_back({DegToRad(bearing_deg), std::min(r, 0.4),
                                     r < 0.4 ? ReadingKind::kHit : ReadingKind::kClear});
  }
  return view;
}

// A pirouette of 12 turns of 30° from `start_deg`.
template <typename RangeFunction>
std::vector<HeadedProfile> Pirouette(double start_deg, RangeFunction range) {
  std::vector<HeadedProfile> views;
  views.reserve(12);
  for (int i = 0; i < 12; ++i) views.push_back(View(start_deg + 30.0 * i, range));
  return views;
}

// A world seen from the robot: an obstacle 0.2 m away between 40° and 80°.
double Scene(double bearing_deg) {
  double b = std::fmod(bearing_deg, 360.0);
  if (b < 0) b += 360.0;
  if (b >= 40.0 && b < 80.0) return 0.2;
  return 0.3 + 0.05 * std::cos(DegToRad(2.0 * b));
}

TEST(RadialProfileTest, MergesAPirouetteIntoEveryBin) {
  const RadialProfile rop = MergePirouette(Pirouette(0.0, Scene));
  ASSERT_EQ(rop.bins.size(), 360u);
  EXPECT_EQ(rop.max_range_m, 0.4);
  for (int b = 0; b < 360; ++b) {
    const RadialBin& bin = rop.bins[static_cast<std::size_t>(b)];
    EXPECT_EQ(bin.readings, 4) << b;  // two frames overlap everywhere, two columns a degree each
    EXPECT_EQ(bin.kind, ReadingKind::kHit);
    // The nearest of the bin's two half-degree readings.
    EXPECT_NEAR(bin.range_m, std::min(Scene(b + 0.25), Scene(b + 0.75)), 1e-12) << b;
  }
}

TEST(RadialProfileTest, RotatedPirouetteGivesRotatedProfile) {
  const RadialProfile rop = MergePirouette(Pirouette(0.0, Scene));
  // The world turned by 47° and the robot with it: the same views, headings 47° on.
  const auto turned = [](double bearing_deg) { return Scene(bearing_deg - 47.0); };
  const RadialProfile rotated = MergePirouette(Pirouette(47.0, turned));
  for (int b = 0; b < 360; ++b) {
    const RadialBin& expected = rop.bins[static_cast<std::size_t>(b)];
    const RadialBin& got = rotated.bins[static_cast<std::size_t>((b + 47) % 360)];
    EXPECT_EQ(got.kind, expected.kind) << b;
    EXPECT_NEAR(got.range_m, expected.range_m, 1e-12) << b;
  }
}

TEST(RadialProfileTest, OverlapsVoteAndTiesAreCautious) {
  HeadedProfile a;
  a.profile.max_range_m = 0.4;
  a.profile.readings = {
      {DegToRad(10.5), 0.4, ReadingKind::kClear}, {DegToRad(10.6), 0.4, ReadingKind::kClear},
      {DegToRad(10.7), 0.25, ReadingKind::kHit},  {DegToRad(20.5), 0.4, ReadingKind::kClear},
      {DegToRad(20.6), 0.3, ReadingKind::kHit},   {DegToRad(30.5), 0.1, ReadingKind::kBlind},
      {DegToRad(30.6), 0.4, ReadingKind::kClear}};
  HeadedProfile b = a;
  b.heading_rad = DegToRad(-90.0);  // the same readings, 90° clockwise
  const RadialProfile rop = MergePirouette({a, b});
  EXPECT_EQ(rop.bins[10].kind, ReadingKind::kClear);  // 2 clear against 1 hit
  EXPECT_EQ(rop.bins[10].range_m, 0.4);
  EXPECT_EQ(rop.bins[20].kind, ReadingKind::kHit);  // a tie
  EXPECT_EQ(rop.bins[20].range_m, 0.3);
  EXPECT_EQ(rop.bins[30].kind, ReadingKind::kBlind);
  EXPECT_EQ(rop.bins[30].range_m, 0.1);
  EXPECT_EQ(rop.bins[290].kind, ReadingKind::kHit);  // 20.6° - 90° = -69.4° = 290.6°
  EXPECT_EQ(rop.bins[0].readings, 0);
  EXPECT_EQ(rop.bins[0].range_m, 0.4);
}

TEST(RadialProfileTest, DctOfAConstantIsOneCoefficient) {
  const std::vector<double> constant(360, 0.3);
  const std::vector<double> coefficients = Dct(constant);
  EXPECT_NEAR(coefficients[0], 0.3 * std::sqrt(360.0), 1e-9);
  for (std::size_t k = 1; k < coefficients.size(); ++k) EXPECT_NEAR(coefficients[k], 0.0, 1e-9);
  for (const double x : DctLowPass(constant)) EXPECT_NEAR(x, 0.3, 1e-12);
}

TEST(RadialProfileTest, DctInvertsAndKeepsEnergy) {
  std::vector<double> x;
  x.reserve(37);
  for (int i = 0; i < 37; ++i) x.push_back(std::sin(0.3 * i) + 0.01 * i * i);
  const std::vector<double> coefficients = Dct(x);
  double energy_x = 0.0;
  double energy_c = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    energy_x += x[i] * x[i];
    energy_c += coefficients[i] * coefficients[i];
  }
  EXPECT_NEAR(energy_x, energy_c, 1e-9 * energy_x);
  const std::vector<double> back = InverseDct(coefficients);
  for (std::size_t i = 0; i < x.size(); ++i) EXPECT_NEAR(back[i], x[i], 1e-12);
  // A cosine of a low DCT frequency passes the low-pass untouched; a high one is removed.
  std::vector<double> low(360);
  std::vector<double> high(360);
  for (int i = 0; i < 360; ++i) {
    low[static_cast<std::size_t>(i)] = std::cos(std::numbers::pi * 5 * (2 * i + 1) / 720.0);
    high[static_cast<std::size_t>(i)] = std::cos(std::numbers::pi * 100 * (2 * i + 1) / 720.0);
  }
  const std::vector<double> low_passed = DctLowPass(low);
  const std::vector<double> high_passed = DctLowPass(high);
  for (std::size_t i = 0; i < 360; ++i) {
    EXPECT_NEAR(low_passed[i], low[i], 1e-9);
    EXPECT_NEAR(high_passed[i], 0.0, 1e-9);
  }
}

}  // namespace
}  // namespace pirouette::mapping
