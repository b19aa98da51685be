#include "pirouette/robot/ros2/ros2_robot.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <thread>

#include "pirouette/core/angle.h"
#include "pirouette/robot/robot_error.h"
#include "pirouette/robot/ros2/dds_qos.h"
#include "pirouette/robot/ros2/dds_reader.h"
#include "pirouette/robot/ros2/dds_writer.h"
#include "pirouette/robot/ros2/ros2_image.h"

namespace pirouette::robot::ros2 {
namespace {

using Clock = std::chrono::steady_clock;
using OdometryMessage = nav_msgs_msg_dds__Odometry_;
using ImageMessage = sensor_msgs_msg_dds__Image_;
using InfoMessage = sensor_msgs_msg_dds__CameraInfo_;
using Twist = geometry_msgs_msg_dds__Twist_;

// The longest a wait for odometry blocks before the loop looks at its clocks.
constexpr dds_duration_t kPoll = DDS_MSECS(50);
// The wall time a move may take: this many times its profile's time, plus
// kMoveSlackS, so that a slow base is not failed by its first turn.
constexpr double kMoveTimeFactor = 4.0;
constexpr double kMoveSlackS = 10.0;
// Odometry farther than this from its origin (metres) is not a robot's.
constexpr double kMaxOdometryM = 1e4;
// Odometry may move between two readings by this much plus kJumpSpeedFactor
// times the cruising speed times the time between them: more is a jump no
// wheel made. Far above any real robot's (the factor covers a base that
// overshoots the speed it is told).
constexpr double kJumpM = 0.25;
constexpr double kJumpRad = 0.7853981633974483;  // 45°
constexpr double kJumpSpeedFactor = 3.0;
// A loop that could not run for this long (wall time: this process starved
// of the CPU) sent no commands meanwhile, and the base may have stopped on
// its command timeout: the stall window starts again rather than blame the
// robot.
constexpr auto kStarvedWall = std::chrono::milliseconds(200);
// How long the start waits for discovery to show another driver on cmd_vel.
constexpr auto kOtherDriverWait = std::chrono::milliseconds(500);
// How long Halt waits for the robot to acknowledge the zero Twist.
constexpr dds_duration_t kHaltAckWait = DDS_MSECS(200);

double Seconds(Clock::duration d) { return std::chrono::duration<double>(d).count(); }

// A reading of odometry: the pose, the robot's clock and its velocity.
struct Reading {
  core::Pose2 pose;
  double time_s = 0.0;
  double linear_mps = 0.0;
  double angular_rps = 0.0;
};

}  // namespace

struct Ros2Robot::Impl {
  explicit Impl(const Ros2RobotOptions& o)
      : options(o),
        participant(o.domain_id, o.network, o.ros_namespace),
        odometry_reader(participant, "odom", kSensorReaderQos),
        image_reader(participant, "image_raw", kSensorReaderQos),
        info_reader(participant, "camera_info", kSensorReaderQos),
        command_writer(participant, "cmd_vel", kReliableQos),
        other_commands(participant, "cmd_vel", kOtherWritersQos) {}

  // ---- what has arrived ----

  // Takes the odometry that has arrived (waiting up to kPoll for some) and
  // answers it with a command: the move controller's, if a move is under
  // way, else zero. Throws when odometry has been silent longer than the
  // timeout.
  bool Spin() {
    bool got = false;
    if (odometry_reader.WaitForData(kPoll)) {
      while (auto sample = odometry_reader.Take()) {
        got = true;
        Accept(*sample);
      }
    }
    TakeCameraInfo();
    if (other_commands.Take()) {
      Fail(
          fmt::format("another node publishes on {} while this run drives the robot: two "
                      "drivers would fight over it",
                      command_writer.topic_name()));
    }
    if (got) {
      last_odometry_wall = Clock::now();
      command = controller != nullptr ? controller->Update(latest.pose, latest.time_s) : Velocity{};
      Send(command);
    } else if (Clock::now() - last_odometry_wall > options.odometry_timeout) {
      Fail(fmt::format("no odometry on {} for {:g} s{}", odometry_reader.topic_name(),
                       Seconds(options.odometry_timeout),
                       odometry_reader.MatchedWriters() == 0 ? ": its publisher is gone" : ""));
    }
    return got;
  }

  void Accept(const Sample<OdometryMessage>& sample) {
    const auto& p = sample->pose.pose.position;
    const auto& twist = sample->twist.twist;
    const double t = ros2::Seconds(sample->header.stamp);
    if (!std::isfinite(p.x) || !std::isfinite(p.y) || std::hypot(p.x, p.y) > kMaxOdometryM ||
        !std::isfinite(t)) {
      Fail(fmt::format("{} sent a pose or stamp that is not a robot's ({}, {} at {} s)",
                       odometry_reader.topic_name(), p.x, p.y, t));
    }
    Reading r{PoseOf(sample->pose.pose), t, twist.linear.x, twist.angular.z};
    if (!std::isfinite(r.linear_mps) || !std::isfinite(r.angular_rps)) {
      r.linear_mps = r.angular_rps = 0.0;
    }
    if (have_odometry) CheckContinuous(r);
    if (!have_odometry) {
      start_time_s = t;
      rest_pose = r.pose;
      rest_since_s = t;
    }
    have_odometry = true;
    latest = r;
    // At rest: odometry within the rest thresholds of where it came to rest.
    const double moved = (r.pose.translation() - rest_pose.translation()).norm();
    const double turned = std::abs(core::NormalizeAngle(r.pose.heading() - rest_pose.heading()));
    if (moved > options.rest_distance_m || turned > options.rest_angle_rad) {
      rest_pose = r.pose;
      rest_since_s = t;
    }
  }

  // Odometry is a robot's integrated motion: its clock never goes back and
  // its pose moves no faster than the robot. A reading that breaks either
  // (a clock reset, a teleport, a heading that flips) cannot be trusted, nor
  // anything the map would build on it after; the run stops (Fail halts the
  // robot first).
  void CheckContinuous(const Reading& r) {
    const double dt = r.time_s - latest.time_s;
    if (dt < 0.0) {
      Fail(fmt::format(
          "the clock of {} went backwards: a reading stamped {:.3f} s after one "
          "stamped {:.3f} s",
          odometry_reader.topic_name(), r.time_s - start_time_s, latest.time_s - start_time_s));
    }
    const MotionLimits& l = options.limits;
    const double most_m = kJumpM + kJumpSpeedFactor * l.max_linear_mps * dt;
    const double most_rad = kJumpRad + kJumpSpeedFactor * l.max_angular_rps * dt;
    const double moved_m = (r.pose.translation() - latest.pose.translation()).norm();
    const double turned_rad =
        std::abs(core::NormalizeAngle(r.pose.heading() - latest.pose.heading()));
    if (moved_m > most_m || turned_rad > most_rad) {
      Fail(
          fmt::format("odometry on {} jumped {:.2f} m and {:.0f}° in {:.3f} s (at most {:.2f} m "
                      "and {:.0f}° are possible): its odometry cannot be trusted",
                      odometry_reader.topic_name(), moved_m, core::RadToDeg(turned_rad), dt, most_m,
                      core::RadToDeg(most_rad)));
    }
  }

  void TakeCameraInfo() {
    while (auto taken = info_reader.Take()) {
      const InfoMessage& sample = **taken;
      CameraInfo info;
      info.width = static_cast<int>(sample.width);
      info.height = static_cast<int>(sample.height);
      info.distortion_model = sample.distortion_model ? sample.distortion_model : "";
      std::copy(std::begin(sample.k), std::end(sample.k), info.k.begin());
      info.d.assign(sample.d._buffer, sample.d._buffer + sample.d._length);
      camera_info = std::move(info);
    }
  }

  bool AtRest() const { return have_odometry && latest.time_s - rest_since_s >= options.settle_s; }

  // ---- commands ----

  void Send(const Velocity& v) {
    Twist twist{};
    twist.linear.x = v.linear_mps;
    twist.angular.z = v.angular_rps;
    try {
      command_writer.Write(twist);
    } catch (const DdsError& e) {
      throw RobotError(e.what());
    }
  }

  void Halt() {
    command = {};
    try {
      Send(command);
      dds_wait_for_acks(command_writer.entity(), kHaltAckWait);
    } catch (const std::exception&) {
      // Nothing more can be done for a robot that cannot be reached.
    }
  }

  [[noreturn]] void Fail(const std::string& what) {
    Halt();
    throw RobotError(fmt::format("the ROS 2 robot ({}): {}", Describe(), what));
  }

  std::string Describe() const {
    return fmt::format("DDS domain {}{}", options.domain_id,
                       options.ros_namespace.empty() ? "" : ", namespace " + options.ros_namespace);
  }

  // ---- waiting ----

  void WaitForStart() {
    const auto deadline = Clock::now() + options.connect_timeout;
    last_odometry_wall = Clock::now();
    while (!have_odometry || command_writer.MatchedReaders() == 0) {
      if (odometry_reader.WaitForData(kPoll)) {
        while (auto sample = odometry_reader.Take()) Accept(*sample);
      }
      if (Clock::now() > deadline) {
        Fail(have_odometry
                 ? fmt::format("nothing subscribes to {}: the robot cannot be driven",
                               command_writer.topic_name())
                 : fmt::format("no odometry on {} within {:g} s: is the robot's driver "
                               "running, on this ROS_DOMAIN_ID and namespace, and reachable "
                               "(--ros-network)?",
                               odometry_reader.topic_name(), Seconds(options.connect_timeout)));
      }
    }
    // Another driver on cmd_vel (a second run mid-run): refused before a
    // command is sent, so that the first drives on undisturbed. Discovery
    // of it may lag the robot's by a moment.
    const auto discovered = Clock::now() + kOtherDriverWait;
    while (Clock::now() < discovered) {
      if (other_commands.MatchedWriters() > 0) {
        throw RobotError(fmt::format(
            "the ROS 2 robot ({}): another node already publishes on {}: the robot is driven "
            "by someone else (a second run? give each robot its own --ros-namespace)",
            Describe(), command_writer.topic_name()));
      }
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    last_odometry_wall = Clock::now();
  }

  // Keeps sending zero until the robot is at rest.
  void WaitForRest() {
    const auto deadline = Clock::now() + options.rest_timeout;
    while (!AtRest()) {
      Spin();
      if (Clock::now() > deadline) {
        Fail(
            fmt::format("the robot does not come to rest: {} still changes {:g} s after a "
                        "zero Twist on {}",
                        odometry_reader.topic_name(), Seconds(options.rest_timeout),
                        command_writer.topic_name()));
      }
    }
  }

  // The wall time a move may take.
  Clock::duration MoveTimeLimit(const core::Move& move) const {
    const bool turn = move.kind == core::Move::Kind::kTurn;
    const MotionLimits& l = options.limits;
    const double speed = turn ? l.max_angular_rps : l.max_linear_mps;
    const double accel = turn ? l.angular_accel_rps2 : l.linear_accel_mps2;
    const double profile_s = std::abs(move.amount) / speed + speed / accel;
    return std::chrono::duration_cast<Clock::duration>(
        std::chrono::duration<double>(kMoveTimeFactor * profile_s + kMoveSlackS));
  }

  core::MoveOutcome Execute(const core::Move& move) {
    WaitForRest();
    const bool turn = move.kind == core::Move::Kind::kTurn;
    MoveController move_controller(move, latest.pose, latest.time_s, options.limits);
    controller = &move_controller;
    struct Release {
      MoveController*& pointer;
      ~Release() { pointer = nullptr; }
    } release{controller};
    const auto deadline = Clock::now() + MoveTimeLimit(move);
    double stall_progress = 0.0;
    double stall_since_s = latest.time_s;
    core::MoveOutcome outcome;
    outcome.requested = move;
    command = move_controller.Update(latest.pose, latest.time_s);
    Send(command);
    Clock::time_point last_spin = Clock::now();
    while (!move_controller.reached()) {
      if (options.stop_requested != nullptr && options.stop_requested->load()) break;
      Spin();
      const double threshold = turn ? options.stall_progress_rad : options.stall_progress_m;
      const Clock::time_point now = Clock::now();
      const bool starved = now - last_spin > kStarvedWall;
      last_spin = now;
      if (starved || std::abs(move_controller.progress() - stall_progress) > threshold) {
        stall_progress = move_controller.progress();
        stall_since_s = latest.time_s;
      } else if (latest.time_s - stall_since_s > options.stall_s) {
        if (!turn && std::abs(move_controller.progress()) > options.stall_progress_m) {
          outcome.stopped_at_contact = true;  // it got somewhere and was stopped
          break;
        }
        Fail(
            fmt::format("the robot does not move: {} asked to {} {} but {} has not changed "
                        "for {:.1f} s",
                        command_writer.topic_name(), turn ? "turn" : "drive",
                        turn ? fmt::format("{:.1f}°", core::RadToDeg(move.amount))
                             : fmt::format("{:.3f} m", move.amount),
                        odometry_reader.topic_name(), options.stall_s));
      }
      if (Clock::now() > deadline) {
        Fail(fmt::format("a move did not end in time: {} of {} made after {:.0f} s",
                         move_controller.progress(), move.amount, Seconds(MoveTimeLimit(move))));
      }
    }
    // Zero at once, whatever ended the move: a robot stopped by a wall (or
    // a Ctrl-C at rest) is already at rest, so WaitForRest may send nothing,
    // and the base would keep pushing with the last command.
    controller = nullptr;
    command = {};
    Send(command);
    WaitForRest();
    move_controller.Update(latest.pose, latest.time_s);
    outcome.achieved = move_controller.progress();
    outcome.odometry = latest.pose;
    return outcome;
  }

  Frame Capture() {
    WaitForRest();
    const double not_before_s = rest_since_s + options.settle_s;
    const auto deadline = Clock::now() + options.frame_timeout;
    std::optional<double> stale_stamp;
    for (;;) {
      while (auto taken = image_reader.Take()) {
        const ImageMessage& sample = **taken;
        const double stamp = ros2::Seconds(sample.header.stamp);
        if (!(stamp >= not_before_s)) {
          stale_stamp = stamp;
          continue;
        }
        Frame frame;
        try {
          frame.image = ImageOf(sample, options.frame_width, options.frame_height);
        } catch (const std::invalid_argument& e) {
          Fail(fmt::format("{}: {}", image_reader.topic_name(), e.what()));
        }
        frame.odometry = latest.pose;
        frame.time_s = stamp - start_time_s;
        return frame;
      }
      Spin();
      if (Clock::now() > deadline) {
        Fail(stale_stamp
                 ? fmt::format("no new frame on {} within {:g} s of coming to rest: the "
                               "last one was stamped {:.3f} s, before the robot came to rest "
                               "at {:.3f} s (a frozen camera?)",
                               image_reader.topic_name(), Seconds(options.frame_timeout),
                               *stale_stamp - start_time_s, not_before_s - start_time_s)
                 : fmt::format("no frame on {} within {:g} s{}", image_reader.topic_name(),
                               Seconds(options.frame_timeout),
                               image_reader.MatchedWriters() == 0 ? " (no publisher)" : ""));
      }
    }
  }

  Ros2RobotOptions options;
  DdsParticipant participant;
  DdsReader<OdometryMessage> odometry_reader;
  DdsReader<ImageMessage> image_reader;
  DdsReader<InfoMessage> info_reader;
  DdsWriter<Twist> command_writer;
  DdsReader<Twist> other_commands;  // cmd_vel of other processes: a second driver
  Velocity command;
  MoveController* controller = nullptr;  // the move under way, if any
  bool have_odometry = false;
  Reading latest;
  double start_time_s = 0.0;
  core::Pose2 rest_pose;
  double rest_since_s = 0.0;
  Clock::time_point last_odometry_wall = Clock::now();
  std::optional<CameraInfo> camera_info;
};

Ros2Robot::Ros2Robot(const Ros2RobotOptions& options) {
  try {
    impl_ = std::make_unique<Impl>(options);
  } catch (const DdsError& e) {
    throw RobotError(
        fmt::format("the ROS 2 robot (DDS domain {}): {}", options.domain_id, e.what()));
  }
  impl_->WaitForStart();
}

Ros2Robot::~Ros2Robot() {
  if (impl_) impl_->Halt();
}

core::MoveOutcome Ros2Robot::Execute(const core::Move& move) { return impl_->Execute(move); }
Frame Ros2Robot::Capture() { return impl_->Capture(); }
core::Pose2 Ros2Robot::Odometry() const { return impl_->latest.pose; }
void Ros2Robot::Halt() { impl_->Halt(); }
std::optional<CameraInfo> Ros2Robot::camera_info() const { return impl_->camera_info; }
std::string Ros2Robot::Describe() const { return impl_->Describe(); }

std::optional<CameraInfo> Ros2Robot::WaitForCameraInfo(std::chrono::milliseconds timeout) {
  const auto deadline = Clock::now() + timeout;
  impl_->TakeCameraInfo();
  while (!impl_->camera_info && Clock::now() < deadline) impl_->Spin();
  return impl_->camera_info;
}

void Ros2Robot::SetFrameSize(int width, int height) {
  impl_->options.frame_width = width;
  impl_->options.frame_height = height;
}

std::string Ros2Robot::TopicName(std::string_view relative) const {
  return impl_->participant.TopicName(relative);
}

}  // namespace pirouette::robot::ros2
