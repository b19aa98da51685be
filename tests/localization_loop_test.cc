// Pose tracking in whole explorations of the default world (Explore with
// LocalizeKind::kScan). What it asserts is what the tracker measurably does
// (docs/measurements.md, "Pose tracking"): it costs little where there is
// nothing to correct, and it takes out most of the pose error 5% odometry
// noise makes, and most of the false free cells with it. That table's goal
// under noise (complete, false_free <= 0.01, wall error within 1.5x the
// noise-free figure) is not met in every world, so not asserted. Each map is
// judged as map.pgm holds it (OccupancyGrid::ToMapOfRecord), as explore-eval
// judges it.

#include <gtest/gtest.h>

#include <cstdint>

#include <algorithm>
#include <memory>

#include "pirouette/camera/range_resolution.h"
#include "pirouette/eval/map_evaluation.h"
#include "pirouette/io/world_file.h"
#include "pirouette/run/explorer.h"
#include "pirouette/run/frame_mapper.h"
#include "pirouette/run/simulated_exploration.h"
#include "pirouette/sim/simulated_robot.h"
#include "pirouette/vision/floor_segmenter.h"

namespace pirouette::run {
namespace {

ExplorationResult ExploreWith(const sim::World& world, LocalizeKind localize, double noise,
                              std::uint64_t seed = 1) {
  ExplorationOptions options;
  options.seed = seed;
  options.localize = localize;
  options.odometry_noise = core::OdometryNoise{noise, noise};
  return Explore(world, options);
}

TEST(LocalizationLoopTest, TrackingWithoutOdometryNoiseKeepsTheMapTrue) {
  const sim::World world = io::LoadWorldFile(PIROUETTE_WORLDS_DIR "/soccer_field.yaml");
  const ExplorationResult result = ExploreWith(world, LocalizeKind::kScan, 0.0);
  EXPECT_EQ(result.status, "complete");
  const eval::MapEvaluation eval = eval::EvaluateMap(result.grid.ToMapOfRecord(), world);
  EXPECT_GE(eval.coverage, 0.95);
  EXPECT_LE(eval.false_free, 0.05);
  EXPECT_LE(eval.wall_error_m, 0.02);
  ASSERT_TRUE(result.pose_error.has_value());
  EXPECT_LE(result.pose_error->mean_m, 0.05);
  EXPECT_LE(result.pose_error->mean_deg, 5.0);
  EXPECT_GT(result.matches, 0);
  EXPECT_GT(result.corrections, 0);
}

TEST(LocalizationLoopTest, TrackingTakesOutMostOfThePoseErrorOfNoisyOdometry) {
  const sim::World world = io::LoadWorldFile(PIROUETTE_WORLDS_DIR "/soccer_field.yaml");
  const ExplorationResult none = ExploreWith(world, LocalizeKind::kNone, 0.05);
  const ExplorationResult scan = ExploreWith(world, LocalizeKind::kScan, 0.05);
  ASSERT_TRUE(none.pose_error.has_value());
  ASSERT_TRUE(scan.pose_error.has_value());
  EXPECT_LT(scan.pose_error->mean_deg, 0.6 * none.pose_error->mean_deg);
  // The scan match between stops takes out the straight moves' error.
  EXPECT_LT(scan.pose_error->mean_m, 0.5 * none.pose_error->mean_m);
  EXPECT_GT(scan.scan_matches, 0);
  EXPECT_EQ(scan.status, "complete");
  const eval::MapEvaluation none_eval = eval::EvaluateMap(none.grid.ToMapOfRecord(), world);
  const eval::MapEvaluation scan_eval = eval::EvaluateMap(scan.grid.ToMapOfRecord(), world);
  EXPECT_LE(scan_eval.false_free, 0.03);
  EXPECT_LT(scan_eval.false_free, 0.25 * none_eval.false_free);
  // Without tracking nothing is matched.
  EXPECT_EQ(none.matches, 0);
}

// The pose graph (LocalizeKind::kGraph, docs/measurements.md, "Pose
// graph"): without noise it keeps the map within the noise-free bounds (its
// odometry model is the simulator's noise, so a perfect odometry outweighs
// the matches), and under 5% noise it takes out most of the pose error and of
// the false free cells.
TEST(LocalizationLoopTest, TheGraphWithoutOdometryNoiseKeepsTheMapTrue) {
  const sim::World world = io::LoadWorldFile(PIROUETTE_WORLDS_DIR "/soccer_field.yaml");
  const ExplorationResult result = ExploreWith(world, LocalizeKind::kGraph, 0.0);
  EXPECT_EQ(result.status, "complete");
  const eval::MapEvaluation eval = eval::EvaluateMap(result.grid.ToMapOfRecord(), world);
  EXPECT_GE(eval.coverage, 0.98);
  EXPECT_LE(eval.false_free, 0.0005);
  EXPECT_LE(eval.wall_error_m, 0.01);
  ASSERT_TRUE(result.pose_error.has_value());
  EXPECT_LE(result.pose_error->ate_rms_m, 0.01);
  ASSERT_TRUE(result.graph.has_value());
  EXPECT_GT(result.graph->NodeCount(), 10U);
  EXPECT_EQ(result.final_frame_poses.size(), static_cast<std::size_t>(result.frames));
}

TEST(LocalizationLoopTest, TheGraphTakesOutMostOfThePoseErrorOfNoisyOdometry) {
  const sim::World world = io::LoadWorldFile(PIROUETTE_WORLDS_DIR "/soccer_field.yaml");
  const ExplorationResult none = ExploreWith(world, LocalizeKind::kNone, 0.05);
  const ExplorationResult graph = ExploreWith(world, LocalizeKind::kGraph, 0.05);
  ASSERT_TRUE(none.pose_error.has_value());
  ASSERT_TRUE(graph.pose_error.has_value());
  EXPECT_EQ(graph.status, "complete");
  EXPECT_LT(graph.pose_error->ate_rms_m, 0.2 * none.pose_error->ate_rms_m);
  EXPECT_GT(graph.scan_matches, 0);
  const eval::MapEvaluation none_eval = eval::EvaluateMap(none.grid.ToMapOfRecord(), world);
  const eval::MapEvaluation graph_eval = eval::EvaluateMap(graph.grid.ToMapOfRecord(), world);
  EXPECT_LE(graph_eval.false_free, 0.03);
  EXPECT_LT(graph_eval.false_free, 0.1 * none_eval.false_free);
}

// The map follows the graph incrementally (FrameMapper: a rebuild starts
// from a map kept from before a recent stop, and waits until a frame moved a
// quarter cell): made again with every move, it is after every frame the map
// made from nothing at the graph's poses, cell for cell; with the quarter
// cell it stays close to it, and after Finish it is that map. Two laps of a
// 15 cm square in the soccer field under 5% odometry noise, a pirouette at
// every corner: the second lap's stops match the first's, and the graph moves
// earlier stops.
struct SquareLaps {
  std::size_t worst_differing = 0;  // trinary cells, the worst frame
  std::size_t known = 0;
  int rebuilds = 0;
  int scan_matches = 0;
  std::size_t differing_after_finish = 0;
};

std::size_t Differing(const mapping::OccupancyGrid& a, const mapping::OccupancyGrid& b) {
  const mapping::TrinaryMap x = a.ToTrinary();
  const mapping::TrinaryMap y = b.ToTrinary();
  if (!(x.geometry.origin() == y.geometry.origin()) || x.cells.size() != y.cells.size()) {
    return x.cells.size() + y.cells.size();
  }
  std::size_t n = 0;
  for (std::size_t i = 0; i < x.cells.size(); ++i) n += x.cells[i] != y.cells[i] ? 1 : 0;
  return n;
}

SquareLaps MapSquareLaps(double remap_cells) {
  const sim::World world = io::LoadWorldFile(PIROUETTE_WORLDS_DIR "/soccer_field.yaml");
  const core::OdometryNoise noise{0.05, 0.05};
  sim::SimulatedRobot simulated(world, 1, noise);
  robot::Robot& robot = simulated.robot();
  const camera::CameraModel& camera = world.robot().camera;
  const double cell_m = mapping::DefaultCellSize(world.robot().radius);
  ExplorationOptions options;
  options.odometry_noise = noise;
  localize::GraphTrackerOptions graph = options.graph;
  graph.odometry = GraphOdometryModel(options, nullptr);
  MapperSetup setup{camera,
                    world.robot().radius,
                    cell_m,
                    camera::MaxRange(camera, cell_m),
                    kExplorationOccupancy,
                    std::nullopt,
                    graph,
                    0.0};
  setup.remap_cells = remap_cells;
  std::unique_ptr<vision::FloorSegmenter> segmenter =
      vision::MakeFloorSegmenter(vision::SegmentationMethod::kDefault, camera);
  FrameMapper mapper(setup, MasksOf(*segmenter), robot.Odometry());
  SquareLaps laps;
  robot.Execute(core::Move::Turn(core::DegToRad(-45.0)));  // facing +x
  constexpr int kCorners = 9;
  for (int corner = 0; corner < kCorners; ++corner) {
    for (int k = 0; k < core::kPirouetteTurns; ++k) {
      mapper.AddFrame(robot.Capture());
      laps.worst_differing =
          std::max(laps.worst_differing, Differing(mapper.grid(), mapper.MapAgain()));
      robot.Execute(core::Move::Turn(core::DegToRad(360.0 / core::kPirouetteTurns)));
    }
    if (corner + 1 == kCorners) break;
    const core::MoveOutcome drive = robot.Execute(core::Move::Straight(0.15));
    if (drive.stopped_at_contact) mapper.AddContact(drive.odometry);
    robot.Execute(core::Move::Turn(core::DegToRad(90.0)));
  }
  laps.known = mapper.grid().KnownCellCount();
  laps.rebuilds = mapper.rebuilds();
  laps.scan_matches = mapper.graph() ? mapper.graph()->scan_matches() : 0;
  mapper.Finish();
  laps.differing_after_finish = Differing(mapper.grid(), mapper.MapAgain());
  return laps;
}

TEST(LocalizationLoopTest, TheMapFollowsTheGraphAsIfMadeAgainFromNothing) {
  const SquareLaps every_move = MapSquareLaps(0.0);
  EXPECT_GT(every_move.scan_matches, 0);
  EXPECT_GT(every_move.rebuilds, 0);
  EXPECT_EQ(every_move.worst_differing, 0U);
  EXPECT_EQ(every_move.differing_after_finish, 0U);

  const SquareLaps quarter_cell = MapSquareLaps(0.25);
  EXPECT_LE(quarter_cell.rebuilds, every_move.rebuilds);
  EXPECT_LE(quarter_cell.worst_differing, quarter_cell.known / 50)
      << "cells the kept map had otherwise than the map made again";
  EXPECT_EQ(quarter_cell.differing_after_finish, 0U);
}

// Under odometry error the robot can end a move touching a wall it mapped a
// few centimetres off, beside its front: every move that way then stops at
// once, and without backing off such a contact a run was seen to repeat it
// 40 times in a row. In this run (the maze, seed 2, 5% noise) the explorer
// backs off such a contact once, and the run completes. (Seeds 3, 1, then
// 13 were this run before; since plans end where their goal is in view
// (docs/worlds.md, fix 16), of seeds 1-7 and 13 seeds 2, 4 and 6 back off,
// and all complete.)
TEST(LocalizationLoopTest, ARobotStuckAgainstAWallBacksOffAndGoesOn) {
  const sim::World world = io::LoadWorldFile(PIROUETTE_WORLDS_DIR "/maze.yaml");
  const ExplorationResult result = ExploreWith(world, LocalizeKind::kScan, 0.05, 2);
  EXPECT_EQ(result.status, "complete") << result.reason;
  EXPECT_GT(result.contact_backoffs, 0);
}

}  // namespace
}  // namespace pirouette::run
