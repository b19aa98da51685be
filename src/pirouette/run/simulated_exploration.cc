#include "pirouette/run/simulated_exploration.h"

#include <vector>

#include "pirouette/eval/floor_masker.h"
#include "pirouette/eval/loop_closure_check.h"
#include "pirouette/eval/pose_error.h"
#include "pirouette/run/explorer.h"
#include "pirouette/sim/sim_robot.h"
#include "pirouette/sim/simulated_robot.h"
#include "pirouette/sim/world.h"

namespace pirouette::run {

ExplorationResult Explore(const sim::World& world, const ExplorationOptions& options,
                          const ExplorationObserver& observer) {
  CheckExplorationOptions(options);
  const camera::CameraModel& camera = world.robot().camera;
  ExplorationOptions explore_options = options;
  explore_options.graph.odometry = GraphOdometryModel(options, &world.robot().odometry_noise);
  if (explore_options.max_steps == 0) {
    explore_options.max_steps =
        DefaultMaxSteps(world.floor().size.x() * world.floor().size.y(), world.robot().radius);
  }
  sim::SimulatedRobot simulated(world, options.seed, options.odometry_noise);
  sim::SimRobot& robot = simulated.robot();
  eval::FloorMasker masker(options.method, world, camera);
  // The truth at every frame, for the pose error.
  std::vector<core::Pose2> truth;
  ExplorationObserver watching = observer;
  watching.on_capture = [&](const robot::Frame& frame,
                            const std::vector<core::MoveOutcome>& motions) {
    truth.push_back(robot.TruePose());
    if (observer.on_capture) observer.on_capture(frame, motions);
  };
  ExplorationResult result = ExploreWithRobot(
      robot, RobotDescription{camera, world.robot().radius}, explore_options,
      {[&](const cv::Mat3b& bgr) { return masker.Mask(bgr, robot.TruePose()); },
       masker.SettlingFrames(), [&]() -> const cv::Mat1b& { return masker.Unresolved(); }},
      watching);
  result.final_true_pose = robot.TruePose();
  result.pose_error = eval::PoseErrorOf(result.final_frame_poses, truth);
  if (result.graph) {
    result.loop_closure_check = eval::CheckLoopClosures(*result.graph, result.frame_stops, truth);
    result.loop_closure_recall =
        eval::CheckLoopClosureRecall(*result.graph, result.frame_stops, truth, result.loop_reach_m,
                                     explore_options.graph.loop_path_m);
  }
  if (result.pose_error && result.final_pose) {
    eval::SetFinalError(*result.pose_error, *result.final_pose, robot.TruePose());
  }
  result.times.render_s = simulated.render_s();
  return result;
}

}  // namespace pirouette::run
