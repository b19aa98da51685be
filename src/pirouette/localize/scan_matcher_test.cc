#include "pirouette/localize/scan_matcher.h"
#include "pirouette/testing/units.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <vector>

namespace pirouette::localize {
namespace {

using testing::kDeg;

// Points every `step` metres along the segment from a to b, the first
// `phase` of a step in.
void Segment(const Eigen::Vector2d& a, const Eigen::Vector2d& b, double step, double phase,
             std::vector<Eigen::Vector2d>* out) {
  const double length = (b - a).norm();
  for (double s = phase * step; s <= length; s += step) out->push_back(a + (b - a) * (s / length));
}

// A 3 m × 2 m room with a box in it, its walls sampled every `step`.
std::vector<Eigen::Vector2d> Room(double step, double phase) {
  std::vector<Eigen::Vector2d> p;
  const Eigen::Vector2d c[] = {{0, 0}, {3, 0}, {3, 2}, {0, 2}};
  for (int i = 0; i < 4; ++i) Segment(c[i], c[(i + 1) % 4], step, phase, &p);
  const Eigen::Vector2d b[] = {{1.8, 0.6}, {2.2, 0.6}, {2.2, 1.1}, {1.8, 1.1}};
  for (int i = 0; i < 4; ++i) Segment(b[i], b[(i + 1) % 4], step, phase, &p);
  return p;
}

// Two walls along x, 1 m apart, 6 m long.
std::vector<Eigen::Vector2d> Corridor(double step, double phase) {
  std::vector<Eigen::Vector2d> p;
  Segment({-3, 0}, {3, 0}, step, phase, &p);
  Segment({-3, 1}, {3, 1}, step, phase, &p);
  return p;
}

HitStore Store(const std::vector<Eigen::Vector2d>& points) {
  HitStore store;
  for (const Eigen::Vector2d& p : points) store.Add(p);
  return store;
}

// The points as a robot truly at `position` sees them, as offsets in the
// map's orientation when the heading it believes needs `heading_error`
// added to be true, out to `range`.
std::vector<Eigen::Vector2d> Offsets(const std::vector<Eigen::Vector2d>& points,
                                     const Eigen::Vector2d& position, double heading_error,
                                     double range) {
  const Eigen::Rotation2Dd turn(-heading_error);
  std::vector<Eigen::Vector2d> out;
  for (const Eigen::Vector2d& p : points) {
    if ((p - position).norm() <= range) out.push_back(turn * (p - position));
  }
  return out;
}

Eigen::Matrix3d Prior(double sigma_m, double sigma_rad) {
  return Eigen::Vector3d(sigma_m * sigma_m, sigma_m * sigma_m, sigma_rad * sigma_rad).asDiagonal();
}

TEST(ScanMatcherTest, RecoversAKnownOffset) {
  const HitStore reference = Store(Room(0.005, 0.0));
  // The robot is at (1.0, 0.9) but believes (1.04, 0.87), 1.5° off.
  const Eigen::Vector2d truth(1.0, 0.9);
  const Eigen::Vector2d believed(1.04, 0.87);
  const double heading_error = -1.5 * kDeg;
  const ScanMatch match =
      MatchScan(reference, believed, Offsets(Room(0.007, 0.5), truth, heading_error, 2.5),
                Prior(0.05, 3.0 * kDeg));
  ASSERT_TRUE(match.accepted);
  EXPECT_NEAR(match.offset.x(), -0.04, 0.01);
  EXPECT_NEAR(match.offset.y(), 0.03, 0.01);
  EXPECT_NEAR(match.offset.z(), heading_error, 0.5 * kDeg);
  // Sure of it: far less spread than the prior's 5 cm and 3°.
  EXPECT_LT(std::sqrt(match.covariance(0, 0)), 0.01);
  EXPECT_LT(std::sqrt(match.covariance(1, 1)), 0.01);
  EXPECT_LT(std::sqrt(match.covariance(2, 2)), 1.0 * kDeg);
  EXPECT_GT(match.overlap, 20);
}

TEST(ScanMatcherTest, AtTheTruthStaysThere) {
  const HitStore reference = Store(Room(0.005, 0.0));
  const Eigen::Vector2d truth(0.7, 1.3);
  const ScanMatch match = MatchScan(reference, truth, Offsets(Room(0.006, 0.3), truth, 0.0, 2.5),
                                    Prior(0.05, 3.0 * kDeg));
  ASSERT_TRUE(match.accepted);
  EXPECT_NEAR(match.offset.head<2>().norm(), 0.0, 0.01);  // within a cell, the search's step
  EXPECT_NEAR(match.offset.z(), 0.0, 0.3 * kDeg);
}

TEST(ScanMatcherTest, ACorridorKeepsThePriorAlongItsLength) {
  const HitStore reference = Store(Corridor(0.005, 0.0));
  // Believed 6 cm along the corridor and 3 cm across from the truth.
  const Eigen::Vector2d truth(0.0, 0.5);
  const Eigen::Vector2d believed(0.06, 0.53);
  const ScanMatch match = MatchScan(
      reference, believed, Offsets(Corridor(0.007, 0.5), truth, 0.0, 1.5), Prior(0.05, 2.0 * kDeg));
  ASSERT_TRUE(match.accepted);
  // Across: found. Along: the walls say nothing, so the mean stays near the
  // prior's and the spread near the prior's 5 cm.
  EXPECT_NEAR(match.offset.y(), -0.03, 0.01);
  EXPECT_LT(std::abs(match.offset.x()), 0.02);
  EXPECT_GT(std::sqrt(match.covariance(0, 0)), 0.03);
  EXPECT_LT(std::sqrt(match.covariance(1, 1)), 0.01);
  // The likelihood alone (a pose graph's edge): as sure across, and along
  // spread over the whole search window (±15 cm: about 8.7 cm), far more
  // than the prior's, so the edge says nothing along the corridor.
  EXPECT_NEAR(match.likelihood_offset.y(), -0.03, 0.01);
  EXPECT_LT(std::sqrt(match.likelihood_covariance(1, 1)), 0.01);
  EXPECT_GT(std::sqrt(match.likelihood_covariance(0, 0)), 0.07);
  EXPECT_GT(match.likelihood_covariance(0, 0), 10.0 * match.likelihood_covariance(1, 1));
  // Every hit lies on a wall at the best correction.
  EXPECT_GT(match.response, 0.95);
}

TEST(ScanMatcherTest, TheResponseIsTheShareOfHitsOnTheReference) {
  // Half the scan is ground the reference never saw (a patch 2 m beyond the
  // corridor's wall, 1.2 m wide, a point every 1 cm along x and 5 cm along
  // y): about half respond.
  const HitStore reference = Store(Corridor(0.005, 0.0));
  std::vector<Eigen::Vector2d> offsets = Offsets(Corridor(0.007, 0.5), {0.0, 0.5}, 0.0, 1.5);
  const std::size_t seen = offsets.size();
  constexpr std::size_t kAcross = 120;
  for (std::size_t i = 0; i < seen; ++i) {
    offsets.emplace_back(0.3 + 0.01 * static_cast<double>(i % kAcross),
                         2.0 + 0.05 * static_cast<double>(i / kAcross));
  }
  const ScanMatch match = MatchScan(reference, {0.0, 0.5}, offsets, Prior(0.02, 1.0 * kDeg));
  ASSERT_TRUE(match.accepted);
  EXPECT_NEAR(match.response, 0.5, 0.05);
}

TEST(ScanMatcherTest, WithNothingToMatchAgainstDoesNotMove) {
  const Eigen::Matrix3d prior = Prior(0.05, 2.0 * kDeg);
  const std::vector<Eigen::Vector2d> scan = Offsets(Room(0.007, 0.0), {1.0, 1.0}, 0.0, 2.5);
  const ScanMatch empty = MatchScan(HitStore(), {1.0, 1.0}, scan, prior);
  EXPECT_FALSE(empty.accepted);
  EXPECT_EQ(empty.offset, Eigen::Vector3d::Zero());
  EXPECT_EQ(empty.covariance, prior);
  // A reference elsewhere (the same room 20 m away): nothing overlaps.
  std::vector<Eigen::Vector2d> far = Room(0.005, 0.0);
  for (Eigen::Vector2d& p : far) p += Eigen::Vector2d(20.0, 0.0);
  const ScanMatch elsewhere = MatchScan(Store(far), {1.0, 1.0}, scan, prior);
  EXPECT_FALSE(elsewhere.accepted);
  EXPECT_EQ(elsewhere.overlap, 0);
  EXPECT_FALSE(MatchScan(Store(Room(0.005, 0.0)), {1.0, 1.0}, {}, prior).accepted);
}

TEST(ScanMatcherTest, HitStoreKeepsOnePointACell) {
  HitStore store(0.01);
  store.Add({0.101, 0.202});
  store.Add({0.104, 0.207});  // the same cell
  store.Add({-0.5, 0.3});
  EXPECT_EQ(store.size(), 2U);
  const std::vector<Eigen::Vector2d> near = store.Within({0.0, 0.0}, {1.0, 1.0});
  ASSERT_EQ(near.size(), 1U);
  EXPECT_NEAR(near[0].x(), 0.105, 1e-9);
  EXPECT_NEAR(near[0].y(), 0.205, 1e-9);
  EXPECT_THROW(HitStore(0.0), std::invalid_argument);
}

TEST(ScanMatcherTest, RejectsBadOptions) {
  ScanMatchOptions options;
  options.correlation = 0.5;
  EXPECT_THROW(options.Check(), std::invalid_argument);
  options = {};
  options.max_window_m = 0.01;  // below min_window_m
  EXPECT_THROW(options.Check(), std::invalid_argument);
  options = {};
  options.sigma_m = 0.0;
  EXPECT_THROW(MatchScan(HitStore(), {0, 0}, {}, Prior(0.05, 0.05), options),
               std::invalid_argument);
  // A prior that is not a covariance, or a reference on other cells.
  EXPECT_THROW(MatchScan(HitStore(), {0, 0}, {}, Prior(0.0, 0.05)), std::invalid_argument);
  Eigen::Matrix3d nan = Prior(0.05, 0.05);
  nan(2, 2) = std::nan("");
  EXPECT_THROW(MatchScan(HitStore(), {0, 0}, {}, nan), std::invalid_argument);
  EXPECT_THROW(MatchScan(HitStore(0.02), {0, 0}, {}, Prior(0.05, 0.05)), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::localize
