#include "pirouette/tools/ros2_sim_server.h"

#include <fmt/format.h>

#include <algorithm>
#include <deque>
#include <numbers>
#include <optional>
#include <utility>

#include "pirouette/robot/ros2/dds_qos.h"
#include "pirouette/robot/ros2/dds_reader.h"
#include "pirouette/robot/ros2/dds_writer.h"
#include "pirouette/robot/ros2/ros2_image.h"
#include "pirouette/robot/ros2/ros2_sample.h"
#include "pirouette/sim/renderer.h"

namespace pirouette::tools {
namespace {

namespace ros2 = robot::ros2;

using TwistMessage = geometry_msgs_msg_dds__Twist_;

// camera_info: reliable and transient-local, so that a late subscriber gets
// the calibration at once, as camera drivers publish it.
constexpr ros2::TopicQos kCameraInfoQos{true, true, 1};
constexpr ros2::TopicQos kOdometryQos{true, false, 10};
constexpr ros2::TopicQos kClockQos{true, false, 1};

// REP-105's frames, and the camera's.
constexpr const char* kOdomFrame = "odom";
constexpr const char* kBaseFrame = "base_link";
constexpr const char* kCameraFrame = "camera_optical_frame";

using FaultKind = sim::RobotFault::Kind;
// The fault `late`: frames published this long (simulated seconds) after
// they were taken.
constexpr double kLateS = 0.5;

// The camera model as ROS's camera_info has it (its distortion model and
// coefficients in ROS's order, no rectification).
void SetCameraInfo(sensor_msgs_msg_dds__CameraInfo_& info, const camera::CameraModel& camera) {
  info.width = static_cast<std::uint32_t>(camera.width());
  info.height = static_cast<std::uint32_t>(camera.height());
  ros2::SetString(info.distortion_model, camera::ModelName(camera.distortion().model));
  const std::vector<double> coefficients = camera.distortion().Coefficients();
  ros2::SetSequence(info.d, std::span<const double>(coefficients));
  const camera::Intrinsics& k = camera.intrinsics();
  const std::array<double, 9> matrix = {k.fx, 0.0, k.cx, 0.0, k.fy, k.cy, 0.0, 0.0, 1.0};
  std::copy(matrix.begin(), matrix.end(), std::begin(info.k));
  const std::array<double, 9> identity = {1, 0, 0, 0, 1, 0, 0, 0, 1};
  std::copy(identity.begin(), identity.end(), std::begin(info.r));
  const std::array<double, 12> projection = {k.fx, 0, k.cx, 0, 0, k.fy, k.cy, 0, 0, 0, 1, 0};
  std::copy(projection.begin(), projection.end(), std::begin(info.p));
}

sim::RenderOptions RenderOptionsFor(std::uint64_t seed) {
  sim::RenderOptions options;
  options.seed = seed;
  return options;
}

}  // namespace

struct Ros2SimServer::Impl {
  Impl(const sim::World& w, std::uint64_t seed, const core::OdometryNoise& noise,
       const Ros2SimServerOptions& o)
      : world(w),
        options(o),
        robot(w, seed, noise, o.limits),
        renderer(w, w.robot().camera, RenderOptionsFor(seed)),
        participant(o.domain_id, o.network, o.ros_namespace),
        command_reader(participant, "cmd_vel", ros2::kReliableQos),
        odometry_writer(participant, "odom", kOdometryQos),
        tf_writer(participant, "tf", ros2::kTfQos),
        clock_writer(participant, "clock", kClockQos),
        image_writer(participant, "image_raw", ros2::kImageWriterQos),
        info_writer(participant, "camera_info", kCameraInfoQos) {
    ros2::Sample<sensor_msgs_msg_dds__CameraInfo_> info;
    ros2::SetHeader(info->header, ros2::RosTimeOfSeconds(0.0), kCameraFrame);
    SetCameraInfo(*info, w.robot().camera);
    info_writer.Write(*info);
    PublishMotion();
  }

  void Step(std::chrono::milliseconds wait) {
    if (command_reader.WaitForData(DDS_MSECS(wait.count()))) {
      while (auto command = command_reader.Take()) {
        linear = (*command)->linear.x;
        angular = (*command)->angular.z;
        if (!std::isfinite(linear) || !std::isfinite(angular)) linear = angular = 0.0;
        last_command_s = robot.time_s();
        if (!first_command_s) first_command_s = robot.time_s();
      }
    }
    if (robot.time_s() - last_command_s > options.command_timeout_s) linear = angular = 0.0;
    double scale = 1.0;
    if (Faulty(FaultKind::kShortMoves)) scale = sim::RobotFault::kShortFraction;
    if (Faulty(FaultKind::kStalled)) scale = 0.0;
    robot.Step(scale * linear, scale * angular, options.step_s);
    ++steps;
    PublishMotion();
    if (robot.still_s() >= options.step_s &&
        (!last_frame_s || robot.time_s() - *last_frame_s >= options.frame_period_s - 1e-9)) {
      PublishFrame();
    }
    PublishLateFrames();
  }

  bool Faulty(FaultKind kind) const {
    return options.fault.kind == kind && first_command_s &&
           robot.time_s() - *first_command_s >= options.fault.from;
  }

  // The stamp of what happens at simulated time `t`.
  double Stamp(double t) const {
    return Faulty(FaultKind::kClockBack) ? t - sim::RobotFault::kClockBackS : t;
  }

  // The odometry as published.
  core::Pose2 Odometry() const {
    if (Faulty(FaultKind::kTeleport)) {
      return core::Pose2(sim::RobotFault::kTeleportM, 0.0, 0.0) * robot.odometry();
    }
    if (Faulty(FaultKind::kFlip)) return robot.odometry() * core::Pose2(0.0, 0.0, std::numbers::pi);
    return robot.odometry();
  }

  void WriteImage(const core::ImageRgb8& frame, double stamp) {
    ros2::Sample<sensor_msgs_msg_dds__Image_> message;
    ros2::SetHeader(message->header, ros2::RosTimeOfSeconds(stamp), kCameraFrame);
    ros2::SetImage(*message, frame);
    image_writer.Write(*message);
  }

  // late: what was taken kLateS ago.
  void PublishLateFrames() {
    while (!late.empty() && robot.time_s() - late.front().first >= kLateS - 1e-9) {
      WriteImage(late.front().second, late.front().first);
      late.pop_front();
    }
  }

  void PublishMotion() {
    const double t = robot.time_s();
    ros2::Sample<nav_msgs_msg_dds__Odometry_> odometry;
    ros2::SetHeader(odometry->header, ros2::RosTimeOfSeconds(Stamp(t)), kOdomFrame);
    ros2::SetString(odometry->child_frame_id, kBaseFrame);
    ros2::SetPose(odometry->pose.pose, Odometry());
    odometry->twist.twist.linear.x = robot.linear_mps();
    odometry->twist.twist.angular.z = robot.angular_rps();
    odometry_writer.Write(*odometry);

    ros2::Sample<tf2_msgs_msg_dds__TFMessage_> tf;
    ros2::ResizeSequence(tf->transforms, 1);
    ros2::SetHeader(tf->transforms._buffer[0].header, ros2::RosTimeOfSeconds(Stamp(t)), kOdomFrame);
    ros2::SetString(tf->transforms._buffer[0].child_frame_id, kBaseFrame);
    ros2::SetTransform(tf->transforms._buffer[0].transform, Odometry());
    tf_writer.Write(*tf);

    rosgraph_msgs_msg_dds__Clock_ clock{};
    clock.clock = ros2::RosTimeOfSeconds(Stamp(t));
    clock_writer.Write(clock);
  }

  // The frame at the true pose: rendered again only when the robot moved,
  // so that a robot at rest is rendered once.
  void PublishFrame() {
    const core::Pose2& pose = robot.true_pose();
    if (!rendered_at || rendered_at->x() != pose.x() || rendered_at->y() != pose.y() ||
        rendered_at->heading() != pose.heading()) {
      image = renderer.Render(pose);
      rendered_at = pose;
      if (options.on_render) options.on_render(image, pose);
    }
    const double t = robot.time_s();
    if (Faulty(FaultKind::kSameFrame)) {
      if (!held) held = image;
      WriteImage(*held, Stamp(t));
    } else if (Faulty(FaultKind::kLate)) {
      late.emplace_back(t, image);
    } else if (Faulty(FaultKind::kOutOfOrder)) {
      if (held) {
        WriteImage(image, t);
        WriteImage(*held, held_s);  // the earlier of the pair, after the later one
        held.reset();
      } else {
        held = image;
        held_s = t;
      }
    } else {
      WriteImage(image, Stamp(t));
    }
    ros2::Sample<sensor_msgs_msg_dds__CameraInfo_> info;
    ros2::SetHeader(info->header, ros2::RosTimeOfSeconds(t), kCameraFrame);
    SetCameraInfo(*info, world.robot().camera);
    info_writer.Write(*info);
    last_frame_s = t;
    ++frames;
  }

  const sim::World& world;
  Ros2SimServerOptions options;
  sim::VelocityRobot robot;
  sim::Renderer renderer;
  ros2::DdsParticipant participant;
  ros2::DdsReader<TwistMessage> command_reader;
  ros2::DdsWriter<nav_msgs_msg_dds__Odometry_> odometry_writer;
  ros2::DdsWriter<tf2_msgs_msg_dds__TFMessage_> tf_writer;
  ros2::DdsWriter<rosgraph_msgs_msg_dds__Clock_> clock_writer;
  ros2::DdsWriter<sensor_msgs_msg_dds__Image_> image_writer;
  ros2::DdsWriter<sensor_msgs_msg_dds__CameraInfo_> info_writer;
  double linear = 0.0;
  double angular = 0.0;
  double last_command_s = 0.0;
  std::optional<double> first_command_s;  // when the first cmd_vel came
  std::optional<double> last_frame_s;
  std::optional<core::Pose2> rendered_at;
  core::ImageRgb8 image;
  std::optional<core::ImageRgb8> held;  // same-frame, out-of-order: a frame kept back
  double held_s = 0.0;
  std::deque<std::pair<double, core::ImageRgb8>> late;  // late: frames not yet published
  int frames = 0;
  long steps = 0;
};

Ros2SimServer::Ros2SimServer(const sim::World& world, std::uint64_t seed,
                             const core::OdometryNoise& noise, const Ros2SimServerOptions& options)
    : impl_(std::make_unique<Impl>(world, seed, noise, options)) {}

Ros2SimServer::~Ros2SimServer() = default;

void Ros2SimServer::Serve() {
  const auto wait = std::chrono::milliseconds(
      std::max<long long>(1, std::llround(impl_->options.step_s * 1000.0)));
  while (impl_->options.stop_requested == nullptr || !impl_->options.stop_requested->load()) {
    Step(wait);
  }
}

void Ros2SimServer::Step(std::chrono::milliseconds wait) { impl_->Step(wait); }

const sim::VelocityRobot& Ros2SimServer::robot() const { return impl_->robot; }
int Ros2SimServer::frames_published() const { return impl_->frames; }
long Ros2SimServer::steps() const { return impl_->steps; }

std::string Ros2SimServer::Describe() const {
  const ros2::DdsParticipant& p = impl_->participant;
  return fmt::format("DDS domain {}: obeys {}; publishes {}, {}, {}, {}, {}", p.domain_id(),
                     p.TopicName("cmd_vel"), p.TopicName("odom"), p.TopicName("tf"),
                     p.TopicName("clock"), p.TopicName("image_raw"), p.TopicName("camera_info"));
}

}  // namespace pirouette::tools
