#include "pirouette/robot/ros2/ros2_robot.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <numbers>
#include <optional>
#include <string>
#include <thread>
#include <vector>

#include "pirouette/robot/robot_error.h"
#include "pirouette/robot/ros2/dds_qos.h"
#include "pirouette/robot/ros2/dds_reader.h"
#include "pirouette/robot/ros2/dds_writer.h"
#include "pirouette/robot/ros2/ros2_sample.h"

// Ros2Robot against a fake ROS 2 base: every way a robot, its driver or its
// camera can fail ends in a RobotError naming the topic, with a zero Twist the
// last thing sent on cmd_vel.
namespace pirouette::robot::ros2::ros2_robot_test {
namespace {

using ::testing::HasSubstr;
using ::testing::Not;
using TwistMessage = geometry_msgs_msg_dds__Twist_;

// Each test its own DDS domain (180–199), so that tests running at once
// never meet.
constexpr int kDomainNoRobot = 180;
constexpr int kDomainOdometryStops = 181;
constexpr int kDomainFrozen = 182;
constexpr int kDomainEncoding = 183;
constexpr int kDomainSize = 184;
constexpr int kDomainDisobeys = 185;
constexpr int kDomainContact = 186;
constexpr int kDomainGone = 187;
constexpr int kDomainBgr = 188;
constexpr int kDomainStop = 189;
constexpr int kDomainMoves = 190;

constexpr const char* kNamespace = "base";
constexpr double kNoLimit = std::numeric_limits<double>::infinity();
// The fake base's step (50 Hz odometry), its frames every kFrameSteps steps
// (10 Hz) and the start of its clock (a robot's clock does not start at 0).
constexpr std::chrono::milliseconds kStep{20};
constexpr double kStepS = 0.02;
constexpr int kFrameSteps = 5;
constexpr double kClockStartS = 1000.0;
constexpr int kImageWidth = 8;
constexpr int kImageHeight = 6;
// How far into a move the fake's faults begin (metres of path).
constexpr double kFaultAfterM = 0.05;

struct FakeBaseOptions {
  int domain_id = 0;
  bool publish_odometry = true;
  bool obeys = true;                 // integrates cmd_vel; else stays put
  double wall_after_m = kNoLimit;    // stopped (by a wall) after this path
  double silent_after_m = kNoLimit;  // odometry stops after this path
  double gone_after_m = kNoLimit;    // its participant goes after this path
  std::string encoding = "rgb8";     // rgb8 or bgr8 are written as such
  int image_width = kImageWidth;
  int image_height = kImageHeight;
  int row_padding = 0;  // bytes after each row (step > 3·width)
  bool frozen = false;  // every frame carries the first stamp
};

// The colour of pixel (u, v) of the fake's frames.
core::Rgb PixelColour(int u, int v) {
  return {static_cast<std::uint8_t>(10 * u), static_cast<std::uint8_t>(10 * v), 200};
}

// A ROS 2 base on a thread: its own participant publishing odom at 50 Hz
// (and image_raw, camera_info at 10 Hz), integrating cmd_vel (unicycle, no
// inertia) and failing as its options say.
class FakeBase {
 public:
  explicit FakeBase(const FakeBaseOptions& options) : options_(options) {
    node_ = std::make_unique<Node>(options.domain_id);
    thread_ = std::thread([this] { Run(); });
  }
  ~FakeBase() {
    stop_ = true;
    thread_.join();
  }
  FakeBase(const FakeBase&) = delete;
  FakeBase& operator=(const FakeBase&) = delete;

  double path_m() const { return path_m_.load(); }
  bool gone() const { return gone_.load(); }

 private:
  struct Node {
    explicit Node(int domain)
        : participant(domain, {}, kNamespace),
          commands(participant, "cmd_vel", kReliableQos),
          odometry(participant, "odom", kReliableQos),
          images(participant, "image_raw", kImageWriterQos),
          info(participant, "camera_info", kReliableQos) {}
    DdsParticipant participant;
    DdsReader<TwistMessage> commands;
    DdsWriter<nav_msgs_msg_dds__Odometry_> odometry;
    DdsWriter<sensor_msgs_msg_dds__Image_> images;
    DdsWriter<sensor_msgs_msg_dds__CameraInfo_> info;
  };

  void Run() {
    auto next = std::chrono::steady_clock::now();
    for (int step = 0; !stop_; ++step) {
      next += kStep;
      std::this_thread::sleep_until(next);
      if (!node_) continue;
      while (auto command = node_->commands.Take()) {
        linear_ = (*command)->linear.x;
        angular_ = (*command)->angular.z;
      }
      Move();
      const double t = kClockStartS + step * kStepS;
      if (path_m_ > options_.gone_after_m) {
        node_.reset();
        gone_ = true;
        continue;
      }
      if (options_.publish_odometry && path_m_ <= options_.silent_after_m) PublishOdometry(t);
      if (step % kFrameSteps == 0) PublishFrame(frame_stamp_s_.value_or(t));
      if (options_.frozen && !frame_stamp_s_) frame_stamp_s_ = t;
    }
  }

  void Move() {
    if (!options_.obeys) return;
    const double ds = std::abs(linear_) * kStepS;
    heading_ += angular_ * kStepS;
    if (path_m_ + ds > options_.wall_after_m) return;
    x_ += std::copysign(ds, linear_) * std::cos(heading_);
    y_ += std::copysign(ds, linear_) * std::sin(heading_);
    path_m_ = path_m_ + ds;
  }

  void PublishOdometry(double t) {
    Sample<nav_msgs_msg_dds__Odometry_> odometry;
    odometry->header.stamp = RosTimeOfSeconds(t);
    SetString(odometry->header.frame_id, "odom");
    SetString(odometry->child_frame_id, "base_link");
    SetPose(odometry->pose.pose, core::Pose2(x_, y_, heading_));
    odometry->twist.twist.linear.x = options_.obeys ? linear_ : 0.0;
    odometry->twist.twist.angular.z = options_.obeys ? angular_ : 0.0;
    node_->odometry.Write(*odometry);
  }

  void PublishFrame(double t) {
    const int w = options_.image_width;
    const int h = options_.image_height;
    const bool bgr = options_.encoding == "bgr8";
    const int step = 3 * w + options_.row_padding;
    std::vector<std::uint8_t> data(static_cast<std::size_t>(step) * h, 0);
    for (int v = 0; v < h; ++v) {
      for (int u = 0; u < w; ++u) {
        const core::Rgb c = PixelColour(u, v);
        std::uint8_t* p =
            data.data() + static_cast<std::size_t>(v) * step + static_cast<std::size_t>(3 * u);
        p[0] = bgr ? c.b : c.r;
        p[1] = c.g;
        p[2] = bgr ? c.r : c.b;
      }
    }
    Sample<sensor_msgs_msg_dds__Image_> image;
    image->header.stamp = RosTimeOfSeconds(t);
    SetString(image->header.frame_id, "camera");
    image->width = static_cast<std::uint32_t>(w);
    image->height = static_cast<std::uint32_t>(h);
    SetString(image->encoding, options_.encoding);
    image->step = static_cast<std::uint32_t>(step);
    SetSequence(image->data, std::span<const std::uint8_t>(data));
    node_->images.Write(*image);

    Sample<sensor_msgs_msg_dds__CameraInfo_> info;
    info->header.stamp = RosTimeOfSeconds(t);
    info->width = static_cast<std::uint32_t>(w);
    info->height = static_cast<std::uint32_t>(h);
    SetString(info->distortion_model, "plumb_bob");
    const std::array<double, 5> d = {0.1, -0.01, 0.0, 0.0, 0.0};
    SetSequence(info->d, std::span<const double>(d));
    const std::array<double, 9> k = {10.0, 0.0, 4.0, 0.0, 10.0, 3.0, 0.0, 0.0, 1.0};
    std::copy(k.begin(), k.end(), std::begin(info->k));
    node_->info.Write(*info);
  }

  FakeBaseOptions options_;
  std::unique_ptr<Node> node_;  // null once gone
  std::thread thread_;
  std::atomic<bool> stop_{false};
  std::atomic<bool> gone_{false};
  std::atomic<double> path_m_{0.0};
  double x_ = 0.0;
  double y_ = 0.0;
  double heading_ = 0.0;
  double linear_ = 0.0;
  double angular_ = 0.0;
  std::optional<double> frame_stamp_s_;
};

// A listener on cmd_vel that outlives any base: what the robot sent last.
class CommandRecorder {
 public:
  explicit CommandRecorder(int domain)
      : participant_(domain, {}, kNamespace), reader_(participant_, "cmd_vel", kReliableQos) {}

  // The newest command received, if any (Ros2Robot waits for its zero Twist
  // to be acknowledged before it throws, so it is here by then).
  std::optional<TwistMessage> Last() {
    while (auto command = reader_.Take()) last_ = **command;
    return last_;
  }

 private:
  DdsParticipant participant_;
  DdsReader<TwistMessage> reader_;
  std::optional<TwistMessage> last_;
};

bool IsZero(const TwistMessage& t) {
  return t.linear.x == 0.0 && t.linear.y == 0.0 && t.linear.z == 0.0 && t.angular.x == 0.0 &&
         t.angular.y == 0.0 && t.angular.z == 0.0;
}

void ExpectLastCommandZero(CommandRecorder& recorder) {
  const std::optional<TwistMessage> last = recorder.Last();
  ASSERT_TRUE(last.has_value()) << "nothing was sent on cmd_vel";
  EXPECT_TRUE(IsZero(*last)) << "the last Twist was " << last->linear.x << " m/s, "
                             << last->angular.z << " rad/s";
}

// Short limits, so that each failure shows within a second or so, and a
// brisk motion profile; generous enough for a loaded machine.
Ros2RobotOptions Options(int domain) {
  Ros2RobotOptions o;
  o.domain_id = domain;
  o.ros_namespace = kNamespace;
  o.frame_width = kImageWidth;
  o.frame_height = kImageHeight;
  o.limits.max_linear_mps = 0.5;
  o.limits.linear_accel_mps2 = 2.0;
  o.limits.max_angular_rps = 2.0;
  o.limits.angular_accel_rps2 = 8.0;
  o.settle_s = 0.1;
  o.stall_s = 0.3;
  o.connect_timeout = std::chrono::milliseconds(1500);
  o.odometry_timeout = std::chrono::milliseconds(500);
  o.frame_timeout = std::chrono::milliseconds(800);
  o.rest_timeout = std::chrono::milliseconds(2000);
  return o;
}

// The message of the RobotError `f` throws (fails the test if none).
template <class F>
std::string RobotErrorOf(F f) {
  try {
    f();
  } catch (const RobotError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no RobotError";
  return "";
}

TEST(Ros2Robot, TurnsAndDrivesOnOdometryAndReadsCameraInfo) {
  CommandRecorder recorder(kDomainMoves);
  FakeBaseOptions base;
  base.domain_id = kDomainMoves;
  FakeBase fake(base);
  Ros2Robot robot(Options(kDomainMoves));
  const core::MoveOutcome turn = robot.Execute(core::Move::Turn(std::numbers::pi / 2));
  EXPECT_NEAR(turn.achieved, std::numbers::pi / 2, 0.01);
  const core::MoveOutcome drive = robot.Execute(core::Move::Straight(0.2));
  EXPECT_NEAR(drive.achieved, 0.2, 0.01);
  EXPECT_FALSE(drive.stopped_at_contact);
  EXPECT_NEAR(drive.odometry.y(), 0.2, 0.01);
  const Frame frame = robot.Capture();
  EXPECT_EQ(frame.image.width(), kImageWidth);
  EXPECT_GT(frame.time_s, 0.0);
  ASSERT_TRUE(robot.camera_info().has_value());
  EXPECT_EQ(robot.camera_info()->width, kImageWidth);
  EXPECT_EQ(robot.camera_info()->distortion_model, "plumb_bob");
  EXPECT_DOUBLE_EQ(robot.camera_info()->k[2], 4.0);
  EXPECT_EQ(robot.camera_info()->d.size(), 5U);
  ExpectLastCommandZero(recorder);
}

TEST(Ros2Robot, NoRobotAtTheStartNamesOdom) {
  CommandRecorder recorder(kDomainNoRobot);  // something listens, nothing talks
  Ros2RobotOptions options = Options(kDomainNoRobot);
  options.connect_timeout = std::chrono::milliseconds(500);
  const std::string what = RobotErrorOf([&] { Ros2Robot robot(options); });
  EXPECT_THAT(what, HasSubstr("no odometry on rt/base/odom within 0.5 s"));
  EXPECT_THAT(what, HasSubstr("DDS domain 180, namespace base"));
  ExpectLastCommandZero(recorder);
}

TEST(Ros2Robot, OdometryThatStopsMidMoveNamesOdom) {
  CommandRecorder recorder(kDomainOdometryStops);
  FakeBaseOptions base;
  base.domain_id = kDomainOdometryStops;
  base.silent_after_m = kFaultAfterM;
  FakeBase fake(base);
  Ros2Robot robot(Options(kDomainOdometryStops));
  const std::string what = RobotErrorOf([&] { robot.Execute(core::Move::Straight(0.3)); });
  EXPECT_THAT(what, HasSubstr("no odometry on rt/base/odom for 0.5 s"));
  EXPECT_THAT(what, Not(HasSubstr("publisher is gone")));  // it is there, silent
  ExpectLastCommandZero(recorder);
}

TEST(Ros2Robot, APublisherThatGoesIsNamed) {
  CommandRecorder recorder(kDomainGone);
  FakeBaseOptions base;
  base.domain_id = kDomainGone;
  base.gone_after_m = kFaultAfterM;
  FakeBase fake(base);
  Ros2Robot robot(Options(kDomainGone));
  const std::string what = RobotErrorOf([&] { robot.Execute(core::Move::Straight(0.3)); });
  EXPECT_TRUE(fake.gone());
  EXPECT_THAT(what, HasSubstr("no odometry on rt/base/odom"));
  EXPECT_THAT(what, HasSubstr("its publisher is gone"));
  ExpectLastCommandZero(recorder);
}

TEST(Ros2Robot, AFrozenCameraIsNamed) {
  CommandRecorder recorder(kDomainFrozen);
  FakeBaseOptions base;
  base.domain_id = kDomainFrozen;
  base.frozen = true;
  FakeBase fake(base);
  Ros2Robot robot(Options(kDomainFrozen));
  const std::string what = RobotErrorOf([&] { robot.Capture(); });
  EXPECT_THAT(what, HasSubstr("no new frame on rt/base/image_raw"));
  EXPECT_THAT(what, HasSubstr("frozen"));
  ExpectLastCommandZero(recorder);
}

TEST(Ros2Robot, AnotherEncodingIsNamed) {
  CommandRecorder recorder(kDomainEncoding);
  FakeBaseOptions base;
  base.domain_id = kDomainEncoding;
  base.encoding = "mono8";
  FakeBase fake(base);
  Ros2Robot robot(Options(kDomainEncoding));
  const std::string what = RobotErrorOf([&] { robot.Capture(); });
  EXPECT_THAT(what, HasSubstr("rt/base/image_raw"));
  EXPECT_THAT(what, HasSubstr("'mono8'"));
  ExpectLastCommandZero(recorder);
}

TEST(Ros2Robot, AnotherSizeNamesBothSizes) {
  CommandRecorder recorder(kDomainSize);
  FakeBaseOptions base;
  base.domain_id = kDomainSize;
  base.image_width = 2 * kImageWidth;
  base.image_height = 2 * kImageHeight;
  FakeBase fake(base);
  Ros2Robot robot(Options(kDomainSize));
  const std::string what = RobotErrorOf([&] { robot.Capture(); });
  EXPECT_THAT(what, HasSubstr("rt/base/image_raw"));
  EXPECT_THAT(what, HasSubstr("the image is 16×12 but the camera file says 8×6"));
  ExpectLastCommandZero(recorder);
}

TEST(Ros2Robot, ARobotThatDoesNotMoveIsNamed) {
  CommandRecorder recorder(kDomainDisobeys);
  FakeBaseOptions base;
  base.domain_id = kDomainDisobeys;
  base.obeys = false;
  FakeBase fake(base);
  Ros2Robot robot(Options(kDomainDisobeys));
  const std::string what = RobotErrorOf([&] { robot.Execute(core::Move::Straight(0.2)); });
  EXPECT_THAT(what, HasSubstr("does not move"));
  EXPECT_THAT(what, HasSubstr("rt/base/cmd_vel asked to drive 0.200 m"));
  EXPECT_THAT(what, HasSubstr("rt/base/odom has not changed"));
  ExpectLastCommandZero(recorder);
}

TEST(Ros2Robot, ADriveThatStallsAfterProgressEndsAtContact) {
  CommandRecorder recorder(kDomainContact);
  FakeBaseOptions base;
  base.domain_id = kDomainContact;
  base.wall_after_m = kFaultAfterM;
  FakeBase fake(base);
  Ros2Robot robot(Options(kDomainContact));
  const core::MoveOutcome drive = robot.Execute(core::Move::Straight(0.3));
  EXPECT_TRUE(drive.stopped_at_contact);
  EXPECT_GT(drive.achieved, kFaultAfterM / 2);
  EXPECT_LE(drive.achieved, kFaultAfterM + 1e-9);
  ExpectLastCommandZero(recorder);
}

TEST(Ros2Robot, Bgr8FramesAreReadAsRgb) {
  CommandRecorder recorder(kDomainBgr);
  FakeBaseOptions base;
  base.domain_id = kDomainBgr;
  base.encoding = "bgr8";
  base.row_padding = 4;
  FakeBase fake(base);
  Ros2Robot robot(Options(kDomainBgr));
  const Frame frame = robot.Capture();
  ASSERT_EQ(frame.image.width(), kImageWidth);
  ASSERT_EQ(frame.image.height(), kImageHeight);
  for (const auto& [u, v] : {std::pair{0, 0}, std::pair{3, 2}, std::pair{7, 5}}) {
    const core::Rgb got = frame.image.At(u, v);
    const core::Rgb want = PixelColour(u, v);
    EXPECT_EQ(got.r, want.r) << u << "," << v;
    EXPECT_EQ(got.g, want.g) << u << "," << v;
    EXPECT_EQ(got.b, want.b) << u << "," << v;
  }
}

TEST(Ros2Robot, AStopRequestEndsALongMoveEarly) {
  CommandRecorder recorder(kDomainStop);
  FakeBaseOptions base;
  base.domain_id = kDomainStop;
  FakeBase fake(base);
  std::atomic<bool> stop{false};
  Ros2RobotOptions options = Options(kDomainStop);
  options.stop_requested = &stop;
  Ros2Robot robot(options);
  // Ctrl-C once the robot is on its way.
  std::atomic<bool> done{false};
  std::thread interrupter([&] {
    while (!done && fake.path_m() < kFaultAfterM) {
      std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    stop = true;
  });
  constexpr double kFar = 5.0;
  const core::MoveOutcome drive = robot.Execute(core::Move::Straight(kFar));
  done = true;
  interrupter.join();
  EXPECT_GE(drive.achieved, kFaultAfterM);
  EXPECT_LT(drive.achieved, kFar / 2);
  EXPECT_FALSE(drive.stopped_at_contact);
  ExpectLastCommandZero(recorder);
}

}  // namespace
}  // namespace pirouette::robot::ros2::ros2_robot_test
