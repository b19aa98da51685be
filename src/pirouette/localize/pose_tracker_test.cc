#include "pirouette/localize/pose_tracker.h"

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "pirouette/localize/test_room.h"
#include "pirouette/mapping/range_sensor_model.h"

namespace pirouette::localize {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kCell = 0.01;

using test_room::Frame;

mapping::OccupancyGrid EmptyGrid() {
  return mapping::OccupancyGrid(
      core::GridGeometry(kCell, Eigen::Vector2d(-0.1043, -0.1057), 220, 170),
      mapping::OccupancyOptions{.hit_probability = 0.8, .miss_probability = 0.18});
}

// Explores like FrameMapper: each frame tracked, then the stop's frames put
// in the map before the stop at the poses the tracker gives. `odometry`
// maps the true poses to what the wheels say. Returns the largest heading
// error (degrees) and position error (metres) over the frames.
std::pair<double, double> Track(const std::vector<core::Pose2>& truth,
                                const std::vector<core::Pose2>& odometry) {
  PoseTracker tracker;
  mapping::OccupancyGrid grid = EmptyGrid();
  mapping::OccupancyGrid before = grid;
  std::vector<core::ObstacleProfile> stop;
  double worst_deg = 0.0;
  double worst_m = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    const core::ObstacleProfile profile = Frame(truth[i]);
    if (tracker.StartsStop(odometry[i])) {
      before = grid;
      stop.clear();
    }
    const std::vector<core::Pose2> poses = tracker.Track(before, profile, odometry[i]);
    stop.push_back(profile);
    grid = before;
    for (std::size_t k = 0; k < stop.size(); ++k) mapping::InsertProfile(grid, stop[k], poses[k]);
    worst_deg = std::max(
        worst_deg,
        std::abs(core::NormalizeAngle(poses.back().heading() - truth[i].heading())) * 180.0 / kPi);
    worst_m = std::max(worst_m, (poses.back().translation() - truth[i].translation()).norm());
  }
  return {worst_deg, worst_m};
}

// Two pirouettes of 12 frames, 0.4 m apart.
std::vector<core::Pose2> TwoPirouettes() {
  std::vector<core::Pose2> poses;
  for (const Eigen::Vector2d& at : {Eigen::Vector2d(0.6, 0.7), Eigen::Vector2d(0.95, 0.5)}) {
    for (int k = 0; k < 12; ++k) poses.emplace_back(at.x(), at.y(), 0.1 + k * kPi / 6.0);
  }
  return poses;
}

TEST(PoseTrackerTest, ExactOdometryStaysExact) {
  const std::vector<core::Pose2> truth = TwoPirouettes();
  const auto [deg, m] = Track(truth, truth);
  EXPECT_LT(deg, 0.3);
  EXPECT_LT(m, 0.006);
}

// What the tracker can do in a plain room: most of a turn error that grows
// with every turn is taken out (the frames of a pirouette overlap), and so
// the drive between two pirouettes goes less astray; the drive's own error
// is not corrected (see PoseTracker).
TEST(PoseTrackerTest, CorrectsTurnErrors) {
  const std::vector<core::Pose2> truth = TwoPirouettes();
  // Every 30° turn reads 4% long, and the drive between the stops 6% short.
  std::vector<core::Pose2> odometry;
  double heading = truth[0].heading();
  Eigen::Vector2d at = truth[0].translation();
  for (std::size_t i = 0; i < truth.size(); ++i) {
    if (i > 0) {
      const Eigen::Vector2d step = truth[i].translation() - truth[i - 1].translation();
      if (step.norm() > 0.0) {
        at +=
            0.94 * step.norm() * Eigen::Vector2d(std::cos(heading), std::sin(heading)).normalized();
      }
      heading += 1.04 * core::NormalizeAngle(truth[i].heading() - truth[i - 1].heading());
    }
    odometry.emplace_back(at.x(), at.y(), heading);
  }
  const auto [deg, m] = Track(truth, odometry);
  // The odometry alone ends 27.6° and about 10 cm off.
  double odometry_deg = 0.0;
  double odometry_m = 0.0;
  for (std::size_t i = 0; i < truth.size(); ++i) {
    odometry_deg = std::max(
        odometry_deg,
        std::abs(core::NormalizeAngle(odometry[i].heading() - truth[i].heading())) * 180.0 / kPi);
    odometry_m = std::max(odometry_m, (odometry[i].translation() - truth[i].translation()).norm());
  }
  EXPECT_GT(odometry_deg, 25.0);
  EXPECT_LT(deg, 0.2 * odometry_deg);
  EXPECT_LT(m, 0.7 * odometry_m);
}

}  // namespace
}  // namespace pirouette::localize
