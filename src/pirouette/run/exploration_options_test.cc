#include "pirouette/run/exploration_options.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "pirouette/core/input_error.h"

namespace pirouette::run {
namespace {

TEST(GraphOdometryModelTest, TheSimulatorsNoiseWithItsBiasInQuadrature) {
  const ExplorationOptions options;
  const core::OdometryNoise world{0.03, 0.04, 0.04, -0.03};
  const localize::OdometryModel model = GraphOdometryModel(options, &world);
  EXPECT_DOUBLE_EQ(model.translation_fraction, 0.05);
  EXPECT_DOUBLE_EQ(model.rotation_fraction, 0.05);
  // The run's own noise, where given, over the world file's.
  ExplorationOptions noisier;
  noisier.odometry_noise = core::OdometryNoise{0.1, 0.0, 0.0, 0.0};
  EXPECT_DOUBLE_EQ(GraphOdometryModel(noisier, &world).translation_fraction, 0.1);
  EXPECT_DOUBLE_EQ(GraphOdometryModel(noisier, &world).rotation_fraction, 0.0);
}

TEST(GraphOdometryModelTest, AGivenModelWinsInTheSimulatorAndOnARealRobot) {
  ExplorationOptions options;
  options.odometry_model = {0.02, 0.07};
  const core::OdometryNoise world{0.05, 0.05, 0.0, 0.0};
  for (const core::OdometryNoise* noise :
       {&world, static_cast<const core::OdometryNoise*>(nullptr)}) {
    const localize::OdometryModel model = GraphOdometryModel(options, noise);
    EXPECT_DOUBLE_EQ(model.translation_fraction, 0.02);
    EXPECT_DOUBLE_EQ(model.rotation_fraction, 0.07);
    EXPECT_DOUBLE_EQ(model.min_translation_m, options.graph.odometry.min_translation_m);
  }
}

TEST(GraphOdometryModelTest, ARealRobotWithoutAModelKeepsTheDefault) {
  const ExplorationOptions options;
  const localize::OdometryModel model = GraphOdometryModel(options, nullptr);
  EXPECT_DOUBLE_EQ(model.translation_fraction, options.graph.odometry.translation_fraction);
  EXPECT_DOUBLE_EQ(model.rotation_fraction, options.graph.odometry.rotation_fraction);
}

TEST(GraphOdometryModelTest, ABadModelIsRefusedNamingTheOption) {
  ExplorationOptions options;
  options.odometry_model = {0.05, -1.0};
  try {
    CheckExplorationOptions(options);
    FAIL() << "a negative fraction was accepted";
  } catch (const core::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("--odometry-model"), std::string::npos) << e.what();
  }
  options.odometry_model = {0.05, 0.05};
  EXPECT_NO_THROW(CheckExplorationOptions(options));
}

TEST(DefaultMaxStepsTest, GrowsWithTheFloorsAreaInRobotDiscs) {
  // The paper's robot (radius 4 cm) in a 2.77 x 2.59 m maze: 4 a disc.
  const double disc = std::numbers::pi * 0.04 * 0.04;
  EXPECT_EQ(DefaultMaxSteps(2.77 * 2.59, 0.04),
            static_cast<int>(std::ceil(kDefaultStepsPerDisc * 2.77 * 2.59 / disc)));
  EXPECT_GT(DefaultMaxSteps(2.77 * 2.59, 0.04), kDefaultMaxSteps);
  // Twice the floor, twice the moves; a robot twice as wide, a quarter.
  EXPECT_NEAR(DefaultMaxSteps(400.0, 0.15), 2.0 * DefaultMaxSteps(200.0, 0.15), 1.0);
  EXPECT_NEAR(DefaultMaxSteps(200.0, 0.3), 0.25 * DefaultMaxSteps(200.0, 0.15), 1.0);
  // Never under the robot default; nonsense sizes give it.
  EXPECT_EQ(DefaultMaxSteps(1.0, 0.15), kDefaultMaxSteps);
  EXPECT_EQ(DefaultMaxSteps(0.0, 0.15), kDefaultMaxSteps);
  EXPECT_EQ(DefaultMaxSteps(10.0, 0.0), kDefaultMaxSteps);
  EXPECT_EQ(DefaultMaxSteps(std::nan(""), 0.1), kDefaultMaxSteps);
}

TEST(DefaultMaxStepsTest, ZeroMeansTheDefaultANegativeLimitIsRefused) {
  ExplorationOptions options;
  EXPECT_EQ(options.max_steps, 0);
  EXPECT_NO_THROW(CheckExplorationOptions(options));
  options.max_steps = -1;
  EXPECT_THROW(CheckExplorationOptions(options), core::InputError);
}

}  // namespace
}  // namespace pirouette::run
