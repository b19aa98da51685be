#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>

#include "pirouette/robot/robot.h"

namespace pirouette::testing {

// For tests: a robot with exact odometry (turns and drives as commanded, a
// straight move longer than `contact_after_m` stops there at contact) and
// frames whose every byte depends on the pixel and the frame's number, so
// that a frame that crossed a wire can be compared byte for byte. Capture
// throws when `fail_capture` is set.
class FakeRobot : public robot::Robot {
 public:
  FakeRobot(int width, int height) : width_(width), height_(height) {}

  core::MoveOutcome Execute(const core::Move& move) override {
    core::MoveOutcome outcome;
    outcome.requested = move;
    outcome.achieved = move.amount;
    if (move.kind == core::Move::Kind::kTurn) {
      odometry_ = core::Pose2(odometry_.x(), odometry_.y(), odometry_.heading() + move.amount);
    } else {
      if (move.amount > contact_after_m) {
        outcome.achieved = contact_after_m;
        outcome.stopped_at_contact = true;
      }
      odometry_ = odometry_ * core::Pose2(outcome.achieved, 0.0, 0.0);
    }
    time_s_ += 0.75;
    outcome.odometry = odometry_;
    return outcome;
  }

  robot::Frame Capture() override {
    if (fail_capture) throw std::runtime_error("the camera is unplugged");
    robot::Frame frame;
    frame.image = core::ImageRgb8(width_, height_);
    for (std::size_t i = 0; i < frame.image.size_bytes(); ++i) {
      frame.image.data()[i] = static_cast<std::uint8_t>(i * 7 + frames_ * 13 + (i >> 8));
    }
    ++frames_;
    frame.odometry = odometry_;
    frame.time_s = time_s_;
    time_s_ += 0.05;
    return frame;
  }

  core::Pose2 Odometry() const override { return odometry_; }

  double contact_after_m = 1e9;
  bool fail_capture = false;

 private:
  int width_;
  int height_;
  std::size_t frames_ = 0;
  double time_s_ = 0.0;
  core::Pose2 odometry_{0.2, 0.2, 0.7853981633974483};
};

}  // namespace pirouette::testing
