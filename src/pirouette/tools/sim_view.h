#pragma once

#include <memory>
#include <vector>

#include "pirouette/core/image.h"
#include "pirouette/core/pose2.h"
#include "pirouette/robot/robot.h"
#include "pirouette/run/live_view_publisher.h"
#include "pirouette/sim/world.h"

namespace pirouette::tools {

// The live view of `sim-serve --view`: what the simulator knows and a robot's
// client does not. `/map` is the world's truth (free floor, occupied solids
// and walls, at TruthCellM), `/pirouette/path` the robot's true path,
// `/pirouette/floor` the camera's last frame as rendered (no floor drawn:
// nothing is segmented here), `/pirouette/status` {"status": "serving",
// "stops": frames served, ...}. Not thread-safe: call from the server's thread.
class SimView {
 public:
  // The truth map's cell: half the robot's radius, within 1 to 5 cm, so a
  // small robot's world is drawn as finely as its map.
  static double TruthCellM(const sim::World& world);

  // Listens at once; throws view::ViewError when it cannot.
  SimView(const sim::World& world, const run::LiveViewOptions& options);

  const view::Endpoint& endpoint() const { return publisher_.endpoint(); }

  // A frame rendered with the robot truly at world_T_robot.
  void OnFrame(const core::ImageRgb8& image, const core::Pose2& world_T_robot);

 private:
  run::LiveViewPublisher publisher_;
  std::vector<core::Pose2> path_;
  int frames_ = 0;
};

// The world's truth as a map: free where the floor is clear, occupied in
// solids and walls (and a cell's width beyond the floor), unknown outside.
mapping::TrinaryMap TruthMap(const sim::World& world, double cell_m);

// A robot that tells `on_capture` of every frame it gives, with its true pose.
class WatchedRobot : public robot::Robot {
 public:
  using OnCapture = std::function<void(const robot::Frame&)>;
  WatchedRobot(robot::Robot& robot, OnCapture on_capture)
      : robot_(robot), on_capture_(std::move(on_capture)) {}
  core::MoveOutcome Execute(const core::Move& move) override { return robot_.Execute(move); }
  robot::Frame Capture() override {
    robot::Frame frame = robot_.Capture();
    on_capture_(frame);
    return frame;
  }
  core::Pose2 Odometry() const override { return robot_.Odometry(); }

 private:
  robot::Robot& robot_;
  OnCapture on_capture_;
};

}  // namespace pirouette::tools
