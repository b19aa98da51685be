#include "pirouette/run/live_view_publisher.h"

#include <chrono>
#include <thread>

#include "pirouette/robot/ros2/ros2_cdr.h"
#include "pirouette/robot/ros2/ros2_message_type.h"
#include "pirouette/robot/ros2/ros2_msg_schema.h"
#include "pirouette/run/explore_job.h"
#include "pirouette/run/run_messages.h"

namespace pirouette::run {

namespace ros2 = robot::ros2;

namespace {

// After the linger, how long clients get to take what was sent last.
constexpr double kFlushS = 2.0;
constexpr auto kLingerPoll = std::chrono::milliseconds(50);

std::string TopicOf(const std::string& ros_namespace, const std::string& name) {
  std::string ns = ros_namespace;
  while (!ns.empty() && ns.front() == '/') ns.erase(ns.begin());
  while (!ns.empty() && ns.back() == '/') ns.pop_back();
  return ns.empty() ? "/" + name : "/" + ns + "/" + name;
}

template <class T>
view::Channel ChannelOf(std::uint32_t id, const std::string& topic) {
  const std::string type(ros2::MessageType<T>::kRosName);
  return {id, topic, "cdr", type, ros2::Ros2MsgSchema(type).value(), "ros2msg"};
}

std::vector<view::Channel> Channels(const std::string& ns) {
  using L = LiveViewPublisher;
  return {
      ChannelOf<nav_msgs_msg_dds__OccupancyGrid_>(L::kMap, TopicOf(ns, "map")),
      ChannelOf<tf2_msgs_msg_dds__TFMessage_>(L::kTf, TopicOf(ns, "tf")),
      ChannelOf<nav_msgs_msg_dds__Path_>(L::kPath, TopicOf(ns, "pirouette/path")),
      ChannelOf<nav_msgs_msg_dds__Path_>(L::kPlan, TopicOf(ns, "pirouette/plan")),
      ChannelOf<sensor_msgs_msg_dds__CompressedImage_>(L::kFloor, TopicOf(ns, "pirouette/floor")),
      ChannelOf<std_msgs_msg_dds__String_>(L::kStatus, TopicOf(ns, "pirouette/status")),
      ChannelOf<nav_msgs_msg_dds__Path_>(L::kStops, TopicOf(ns, "pirouette/stops"))};
}

std::uint64_t NowNs() {
  return static_cast<std::uint64_t>(std::chrono::duration_cast<std::chrono::nanoseconds>(
                                        std::chrono::system_clock::now().time_since_epoch())
                                        .count());
}

template <class T>
std::shared_ptr<const std::vector<std::uint8_t>> Cdr(const ros2::Sample<T>& message) {
  return std::make_shared<const std::vector<std::uint8_t>>(ros2::SerializeCdr(*message));
}

}  // namespace

LiveViewPublisher::LiveViewPublisher(const LiveViewOptions& options) : options_(options) {
  view::LiveServerOptions server;
  server.endpoint = options.endpoint;
  server.control = options.control;
  server.on_control = [this](view::ControlCommand command) { return OnControl(command); };
  server_ = std::make_unique<view::LiveServer>(server, Channels(options.ros_namespace));
}

LiveViewPublisher::~LiveViewPublisher() { server_.reset(); }

std::string LiveViewPublisher::OnControl(view::ControlCommand command) {
  switch (command) {
    case view::ControlCommand::kPause: {
      control_.pause = true;
      std::lock_guard lock(status_mutex_);
      SendStatus(
          StatusJson("paused", stops_, known_area_m2_, "paused from the live view", elapsed_s_));
      return "paused: the robot stops after its current step";
    }
    case view::ControlCommand::kResume: {
      control_.pause = false;
      std::lock_guard lock(status_mutex_);
      SendStatus(StatusJson("running", stops_, known_area_m2_, "", elapsed_s_));
      return "resumed";
    }
    case view::ControlCommand::kStop:
      control_.stop = true;
      return "stopping: the map so far is written";
    case view::ControlCommand::kHome:
      control_.home = true;
      return "going home: the robot drives back to its start, then stops";
  }
  return "";
}

void LiveViewPublisher::SendStatus(const std::string& json) {
  server_->Publish(kStatus, Cdr(StatusMessage(json)), NowNs());
}

void LiveViewPublisher::Publish(const RunSnapshot& snapshot) {
  const auto stamp = ros2::RosTime(std::chrono::system_clock::now());
  const std::uint64_t now = NowNs();
  if (snapshot.frames != published_frames_) {
    published_frames_ = snapshot.frames;
    server_->Publish(kMap, Cdr(MapMessage(SeenPart(snapshot.grid).ToMapOfRecord(), stamp)), now);
    if (!snapshot.bgr.empty()) {
      server_->Publish(
          kFloor, Cdr(FloorJpegMessage(FloorPicture(snapshot.bgr, snapshot.floor_mask), stamp)),
          now);
    }
  }
  if (snapshot.stops.size() != published_stops_ || published_stops_ == 0) {
    published_stops_ = snapshot.stops.size();
    server_->Publish(kStops, Cdr(PathMessage(snapshot.stops, stamp)), now);
  }
  server_->Publish(kTf, Cdr(MapToOdomMessage(snapshot.map_T_odom, stamp)), now);
  server_->Publish(kPath, Cdr(PathMessage(PathPoses(snapshot.path, snapshot.map_T_robot), stamp)),
                   now);
  server_->Publish(kPlan, Cdr(PathMessage(PlanPoses(snapshot.map_T_robot, snapshot.plan), stamp)),
                   now);
  std::lock_guard lock(status_mutex_);
  stops_ = snapshot.progress.pirouettes;
  known_area_m2_ = snapshot.progress.known_area_m2;
  elapsed_s_ = snapshot.progress.elapsed_s;
  const bool paused = control_.pause.load();
  SendStatus(StatusJson(paused ? "paused" : "running", stops_, known_area_m2_,
                        paused ? "paused from the live view" : "", elapsed_s_));
}

void LiveViewPublisher::PublishFinal(const mapping::TrinaryMap& map,
                                     const ExplorationResult& result) {
  const auto stamp = ros2::RosTime(std::chrono::system_clock::now());
  const std::uint64_t now = NowNs();
  server_->Publish(kMap, Cdr(MapMessage(map, stamp)), now);
  server_->Publish(kPath, Cdr(PathMessage(result.path, stamp)), now);
  server_->Publish(kStops, Cdr(PathMessage(result.stops, stamp)), now);
  server_->Publish(kPlan, Cdr(PathMessage({}, stamp)), now);
  SendStatus(StatusJson(result.status, result.pirouettes, KnownAreaM2(map), result.reason,
                        result.wall_time_s));
}

void LiveViewPublisher::PublishMap(const mapping::TrinaryMap& map) {
  server_->Publish(kMap, Cdr(MapMessage(map, ros2::RosTime(std::chrono::system_clock::now()))),
                   NowNs());
}

void LiveViewPublisher::PublishPicture(const cv::Mat3b& bgr) {
  server_->Publish(
      kFloor, Cdr(FloorJpegMessage(bgr, ros2::RosTime(std::chrono::system_clock::now()))), NowNs());
}

void LiveViewPublisher::PublishPath(const std::vector<core::Pose2>& poses) {
  server_->Publish(kPath, Cdr(PathMessage(poses, ros2::RosTime(std::chrono::system_clock::now()))),
                   NowNs());
}

void LiveViewPublisher::Linger(const std::atomic<bool>* stop_requested) const {
  const auto deadline = std::chrono::steady_clock::now() +
                        std::chrono::duration<double>(std::max(0.0, options_.linger_s));
  while (std::chrono::steady_clock::now() < deadline) {
    if (stop_requested != nullptr && stop_requested->load()) break;
    const view::LiveServerStats stats = server_->Stats();
    if (stats.clients_ever > 0 && stats.clients == 0) break;  // all who came have gone
    std::this_thread::sleep_for(kLingerPoll);
  }
  server_->WaitFlushed(kFlushS);
}

}  // namespace pirouette::run
