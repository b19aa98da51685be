#include "pirouette/sim/drifted_odometry.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "pirouette/core/angle.h"

namespace pirouette::sim {
namespace {

constexpr double kPi = std::numbers::pi;

// A pirouette of 12 turns of 30° at (1, 2), a 0.5 m drive north, and a
// quarter turn there.
std::vector<core::Pose2> PirouetteAndDrive() {
  std::vector<core::Pose2> truth;
  truth.reserve(15);
  for (int k = 0; k < 12; ++k) truth.emplace_back(1.0, 2.0, k * kPi / 6.0);
  truth.emplace_back(1.0, 2.0, kPi / 2.0);
  truth.emplace_back(1.0, 2.5, kPi / 2.0);
  truth.emplace_back(1.0, 2.5, kPi);
  return truth;
}

TEST(DriftedOdometryTest, WithoutNoiseItIsTheTruth) {
  const std::vector<core::Pose2> truth = PirouetteAndDrive();
  const std::vector<core::Pose2> odometry = DriftedOdometry(truth, {}, 7);
  ASSERT_EQ(odometry.size(), truth.size());
  for (std::size_t k = 0; k < truth.size(); ++k) {
    EXPECT_NEAR(odometry[k].x(), truth[k].x(), 1e-12) << k;
    EXPECT_NEAR(odometry[k].y(), truth[k].y(), 1e-12) << k;
    EXPECT_NEAR(core::NormalizeAngle(odometry[k].heading() - truth[k].heading()), 0.0, 1e-12) << k;
  }
}

// A bias alone: every turn the robot made is reported over 1 + b, every
// drive the same: the robot that turns 10% too far believes it turned less.
TEST(DriftedOdometryTest, ABiasScalesEachPartAsTheSimulatedRobotMakesIt) {
  const std::vector<core::Pose2> truth = PirouetteAndDrive();
  core::OdometryNoise noise;
  noise.rotation_bias = 0.1;
  noise.translation_bias = 0.25;
  const std::vector<core::Pose2> odometry = DriftedOdometry(truth, noise, 1);
  for (int k = 1; k < 12; ++k) {
    const double turn = core::NormalizeAngle(odometry[k].heading() - odometry[k - 1].heading());
    EXPECT_NEAR(turn, (kPi / 6.0) / 1.1, 1e-12) << k;
  }
  // The drive: reported 0.5 / 1.25 along the heading odometry believes.
  const core::Pose2 drive = odometry[12].Inverse() * odometry[13];
  EXPECT_NEAR(drive.translation().norm(), 0.4, 1e-12);
  EXPECT_NEAR(drive.heading(), 0.0, 1e-12);
  EXPECT_EQ(odometry.front().x(), truth.front().x());
}

TEST(DriftedOdometryTest, ASeedGivesTheSameOdometryAndAnotherSeedAnother) {
  const std::vector<core::Pose2> truth = PirouetteAndDrive();
  core::OdometryNoise noise;
  noise.rotation = 0.05;
  noise.translation = 0.05;
  const std::vector<core::Pose2> a = DriftedOdometry(truth, noise, 3);
  const std::vector<core::Pose2> b = DriftedOdometry(truth, noise, 3);
  const std::vector<core::Pose2> c = DriftedOdometry(truth, noise, 4);
  ASSERT_EQ(a.size(), truth.size());
  double differs = 0.0;
  for (std::size_t k = 0; k < a.size(); ++k) {
    EXPECT_EQ(a[k].x(), b[k].x());
    EXPECT_EQ(a[k].heading(), b[k].heading());
    differs = std::max(differs, std::abs(core::NormalizeAngle(a[k].heading() - c[k].heading())));
  }
  EXPECT_GT(differs, 1e-4);
  // 5% of a 30° turn is 1.5°: the drift stays of that order a turn.
  for (int k = 1; k < 12; ++k) {
    const double turn = core::NormalizeAngle(a[k].heading() - a[k - 1].heading());
    EXPECT_NEAR(turn, kPi / 6.0, 0.25 * kPi / 6.0) << k;
  }
}

TEST(DriftedOdometryTest, NoTruthNoOdometry) { EXPECT_TRUE(DriftedOdometry({}, {}, 1).empty()); }

}  // namespace
}  // namespace pirouette::sim
