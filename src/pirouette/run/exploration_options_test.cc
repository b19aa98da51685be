#include "pirouette/run/exploration_options.h"

#include <gtest/gtest.h>

#include <cmath>
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

}  // namespace
}  // namespace pirouette::run
