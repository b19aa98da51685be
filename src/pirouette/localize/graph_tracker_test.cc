#include "pirouette/localize/graph_tracker.h"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/testing/test_room.h"
#include "pirouette/testing/units.h"

namespace pirouette::localize {
namespace {

using testing::kPi;

mapping::OccupancyGrid EmptyGrid() {
  return mapping::OccupancyGrid(
      core::GridGeometry(testing::kRoomCellM, Eigen::Vector2d(-0.1, -0.1), 220, 170),
      mapping::OccupancyOptions{.hit_probability = 0.8, .miss_probability = 0.18});
}

// A walk through the test room: a pirouette of 12 frames at each stop, then
// a turn to face the next stop and a straight drive to it. The truth of every
// frame, and what the wheels say of it: each turn `turn_gain` times what it
// was, each drive `drive_gain` times.
struct Walk {
  std::vector<core::Pose2> truth;
  std::vector<core::Pose2> odometry;
};

Walk WalkThrough(const std::vector<Eigen::Vector2d>& stops, double turn_gain, double drive_gain) {
  Walk walk;
  double heading = 0.0;
  core::Pose2 odom(stops.front().x(), stops.front().y(), 0.0);
  double odom_heading = 0.0;
  Eigen::Vector2d odom_at = stops.front();
  const auto add = [&](const Eigen::Vector2d& at) {
    walk.truth.emplace_back(at.x(), at.y(), heading);
    walk.odometry.emplace_back(odom_at.x(), odom_at.y(), odom_heading);
  };
  const auto turn = [&](double by) {
    heading += by;
    odom_heading += turn_gain * by;
  };
  for (std::size_t s = 0; s < stops.size(); ++s) {
    for (int k = 0; k < 12; ++k) {
      add(stops[s]);
      turn(2.0 * kPi / 12.0);
    }
    if (s + 1 == stops.size()) break;
    const Eigen::Vector2d to = stops[s + 1] - stops[s];
    turn(core::NormalizeAngle(std::atan2(to.y(), to.x()) - heading));
    odom_at +=
        drive_gain * to.norm() * Eigen::Vector2d(std::cos(odom_heading), std::sin(odom_heading));
  }
  return walk;
}

// Feeds a walk to the tracker (the frames read out to 1.2 m, the map's range
// 0.6 m) and returns the largest position and heading error of the frames
// where the graph puts them at the end.
struct Errors {
  double m = 0.0;
  double deg = 0.0;
};

Errors Follow(GraphTracker& tracker, const Walk& walk) {
  const mapping::OccupancyGrid grid = EmptyGrid();
  for (std::size_t i = 0; i < walk.truth.size(); ++i) {
    tracker.Track(grid, testing::Frame(walk.truth[i]), 0.6, walk.odometry[i]);
  }
  tracker.Finish();
  Errors e;
  for (std::size_t i = 0; i < walk.truth.size(); ++i) {
    const core::Pose2 p = tracker.FramePose(i);
    e.m = std::max(e.m, (p.translation() - walk.truth[i].translation()).norm());
    e.deg = std::max(
        e.deg, std::abs(core::NormalizeAngle(p.heading() - walk.truth[i].heading())) * 180.0 / kPi);
  }
  return e;
}

// Round the box in the middle of the room and back to the start.
const std::vector<Eigen::Vector2d> kLoop = {{0.5, 0.35}, {0.9, 0.3},  {1.7, 0.3}, {1.7, 1.15},
                                            {1.0, 1.2},  {0.45, 1.0}, {0.5, 0.4}};

TEST(GraphTrackerTest, ExactOdometryStaysExact) {
  GraphTrackerOptions options;
  options.odometry.translation_fraction = 0.0;
  options.odometry.rotation_fraction = 0.0;
  GraphTracker tracker(options);
  const Errors e = Follow(tracker, WalkThrough(kLoop, 1.0, 1.0));
  EXPECT_EQ(tracker.graph().NodeCount(), kLoop.size());
  EXPECT_LT(e.m, 0.005);
  EXPECT_LT(e.deg, 0.3);
}

// Turns 4% long and drives 6% short: the odometry ends the loop 20 cm and
// more off; the graph, matching each stop against the stops its view
// overlaps, keeps every frame within a third of that and closes the loop at
// the start. (What limits it: the stop's frames keep about 1° a turn of the
// odometry's error between them, the heading match within a stop being soft,
// so a stop's hits are slightly bent and its rigid match is off by 1-2°.)
TEST(GraphTrackerTest, DriftingOdometryIsHeldByTheMatches) {
  const Walk walk = WalkThrough(kLoop, 1.04, 0.94);
  double odometry_m = 0.0;
  for (std::size_t i = 0; i < walk.truth.size(); ++i) {
    odometry_m =
        std::max(odometry_m, (walk.odometry[i].translation() - walk.truth[i].translation()).norm());
  }
  ASSERT_GT(odometry_m, 0.2);
  GraphTracker tracker;  // the default odometry model: 8% of each move and turn
  const Errors e = Follow(tracker, walk);
  EXPECT_LT(e.m, 0.3 * odometry_m);
  EXPECT_LT(e.deg, 4.0);
  EXPECT_GT(tracker.scan_matches(), 0);
  // The last stop, back at the start, is a loop closure: far along the graph
  // from the first.
  EXPECT_GE(tracker.loop_closures_accepted(), 1);
  bool closed = false;
  for (const PoseGraphEdge& edge : tracker.graph().edges()) {
    closed |= edge.kind == EdgeKind::kLoopClosure;
  }
  EXPECT_TRUE(closed);
}

// A match edge goes from a stop whose hits the match aligned, so what it
// measures is the pose relative to that stop (booked from the nearest stop
// far back along the graph while the hits aligned were the last stops', it
// would tell the graph that the drift between the two is true:
// docs/measurements.md, "Pose graph"). The loop closure at the walk's end
// is true to the 2 cm and 1°; the scan matches between stops to
// within what their bent hits allow (the synthetic stops lie up to 0.8 m
// apart; the worst is about 6 cm and 2.3° off).
TEST(GraphTrackerTest, EachMatchEdgeMeasuresItsStopsRelativePose) {
  const Walk walk = WalkThrough(kLoop, 1.04, 0.94);
  GraphTracker tracker;
  Follow(tracker, walk);
  std::vector<core::Pose2> stop_truth(tracker.graph().NodeCount());
  std::vector<bool> seen(stop_truth.size(), false);
  for (std::size_t i = 0; i < walk.truth.size(); ++i) {
    const auto s = static_cast<std::size_t>(tracker.StopOf(i));
    if (!seen[s]) stop_truth[s] = walk.truth[i];
    seen[s] = true;
  }
  int loops = 0;
  for (const PoseGraphEdge& edge : tracker.graph().edges()) {
    if (edge.kind == EdgeKind::kOdometry) continue;
    const core::Pose2 truth = stop_truth[static_cast<std::size_t>(edge.from)].Inverse() *
                              stop_truth[static_cast<std::size_t>(edge.to)];
    const core::Pose2 error = truth.Inverse() * edge.from_T_to;
    const bool loop = edge.kind == EdgeKind::kLoopClosure;
    loops += loop ? 1 : 0;
    EXPECT_LT(error.translation().norm(), loop ? 0.02 : 0.08) << edge.from << " -> " << edge.to;
    EXPECT_LT(std::abs(error.heading()) * 180.0 / kPi, loop ? 1.0 : 3.0)
        << edge.from << " -> " << edge.to;
  }
  EXPECT_GE(loops, 1);
}

// The map frame follows the latest stop: an odometry pose taken where the
// last frame was is where the graph put that frame.
TEST(GraphTrackerTest, ToMapAgreesWithTheLastFrame) {
  const Walk walk = WalkThrough(kLoop, 1.04, 0.94);
  GraphTracker tracker;
  Follow(tracker, walk);
  const core::Pose2 last = tracker.FramePose(tracker.FrameCount() - 1);
  const core::Pose2 mapped = tracker.ToMap(walk.odometry.back());
  EXPECT_LT((last.translation() - mapped.translation()).norm(), 1e-6);
  EXPECT_LT(std::abs(core::NormalizeAngle(last.heading() - mapped.heading())), 1e-6);
}

TEST(GraphTrackerTest, RefusesBadOptions) {
  GraphTrackerOptions options;
  options.min_response = 1.5;
  EXPECT_THROW(GraphTracker{options}, std::invalid_argument);
  options = {};
  options.odometry.min_translation_m = 0.0;
  EXPECT_THROW(GraphTracker{options}, std::invalid_argument);
  options = {};
  options.edge_floor_m = -1.0;
  EXPECT_THROW(GraphTracker{options}, std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::localize
