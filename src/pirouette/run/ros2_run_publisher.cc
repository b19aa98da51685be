#include "pirouette/run/ros2_run_publisher.h"

#include <nlohmann/json.hpp>
#include <opencv2/core.hpp>

#include <chrono>
#include <span>

#include "pirouette/draw/floor_overlay.h"
#include "pirouette/robot/ros2/dds_writer.h"
#include "pirouette/robot/ros2/ros2_sample.h"
#include "pirouette/run/explore_job.h"

namespace pirouette::run {

namespace ros2 = robot::ros2;

struct Ros2RunPublisher::Writers {
  explicit Writers(const ros2::DdsParticipant& p)
      : map(p, "map", ros2::kMapQos),
        tf(p, "tf", ros2::kTfQos),
        path(p, "pirouette/path", ros2::kLatchedQos),
        plan(p, "pirouette/plan", ros2::kReliableQos),
        floor(p, "pirouette/floor", ros2::kImageWriterQos),
        status(p, "pirouette/status", ros2::kLatchedQos) {}

  ros2::DdsWriter<nav_msgs_msg_dds__OccupancyGrid_> map;
  ros2::DdsWriter<tf2_msgs_msg_dds__TFMessage_> tf;
  ros2::DdsWriter<nav_msgs_msg_dds__Path_> path;
  ros2::DdsWriter<nav_msgs_msg_dds__Path_> plan;
  ros2::DdsWriter<sensor_msgs_msg_dds__Image_> floor;
  ros2::DdsWriter<std_msgs_msg_dds__String_> status;
};

namespace {

constexpr const char* kMapFrame = "map";

void SetHeader(std_msgs_msg_dds__Header_& header, const builtin_interfaces_msg_dds__Time_& stamp,
               const char* frame) {
  header.stamp = stamp;
  ros2::SetString(header.frame_id, frame);
}

// The map's cells as OccupancyGrid's data: row-major from the bottom row, as
// TrinaryMap keeps them.
ros2::Sample<nav_msgs_msg_dds__OccupancyGrid_> MapMessage(
    const mapping::TrinaryMap& map, const builtin_interfaces_msg_dds__Time_& stamp) {
  ros2::Sample<nav_msgs_msg_dds__OccupancyGrid_> message;
  SetHeader(message->header, stamp, kMapFrame);
  message->info.map_load_time = stamp;
  message->info.resolution = static_cast<float>(map.geometry.resolution());
  message->info.width = static_cast<std::uint32_t>(map.geometry.width());
  message->info.height = static_cast<std::uint32_t>(map.geometry.height());
  ros2::SetPose(message->info.origin,
                core::Pose2(map.geometry.origin().x(), map.geometry.origin().y(), 0.0));
  std::vector<std::int8_t> cells(map.cells.size());
  for (std::size_t i = 0; i < cells.size(); ++i) {
    switch (map.cells[i]) {
      case mapping::CellState::kFree:
        cells[i] = 0;
        break;
      case mapping::CellState::kOccupied:
        cells[i] = 100;
        break;
      case mapping::CellState::kUnknown:
        cells[i] = -1;
        break;
    }
  }
  ros2::SetSequence(message->data, std::span<const std::int8_t>(cells));
  return message;
}

ros2::Sample<nav_msgs_msg_dds__Path_> PathMessage(const std::vector<core::Pose2>& poses,
                                                  const builtin_interfaces_msg_dds__Time_& stamp) {
  ros2::Sample<nav_msgs_msg_dds__Path_> message;
  SetHeader(message->header, stamp, kMapFrame);
  ros2::ResizeSequence(message->poses, poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    SetHeader(message->poses._buffer[i].header, stamp, kMapFrame);
    ros2::SetPose(message->poses._buffer[i].pose, poses[i]);
  }
  return message;
}

// A plan's waypoints from where the robot stands, each facing the next.
std::vector<core::Pose2> PlanPoses(const core::Pose2& from,
                                   const std::vector<Eigen::Vector2d>& waypoints) {
  std::vector<core::Pose2> poses;
  if (waypoints.empty()) return poses;
  Eigen::Vector2d at = from.translation();
  poses.push_back(from);
  for (const Eigen::Vector2d& next : waypoints) {
    const Eigen::Vector2d d = next - at;
    const double heading = d.norm() > 0.0 ? std::atan2(d.y(), d.x()) : poses.back().heading();
    poses.back() = core::Pose2(at.x(), at.y(), heading);
    poses.emplace_back(next.x(), next.y(), heading);
    at = next;
  }
  return poses;
}

void SetStatus(ros2::Sample<std_msgs_msg_dds__String_>& message, const std::string& json) {
  ros2::SetString(message->data, json);
}

}  // namespace

Ros2RunPublisher::Ros2RunPublisher(const Ros2PublishOptions& options)
    : participant_(std::make_unique<ros2::DdsParticipant>(options.domain_id, options.network,
                                                          options.ros_namespace)),
      writers_(std::make_unique<Writers>(*participant_)) {}

Ros2RunPublisher::~Ros2RunPublisher() = default;

void Ros2RunPublisher::Watch(ExplorationObserver& observer) {
  auto before = observer.on_snapshot;
  observer.on_snapshot = [this, before](const RunSnapshot& snapshot) {
    if (before) before(snapshot);
    Publish(snapshot);
  };
}

std::string Ros2RunPublisher::StatusJson(const std::string& status, int stops, double known_area_m2,
                                         const std::string& reason) {
  constexpr double kPerSquareMetre = 1e4;  // rounded to cm²
  return nlohmann::json{
      {"status", status},
      {"stops", stops},
      {"known_area_m2", std::round(known_area_m2 * kPerSquareMetre) / kPerSquareMetre},
      {"reason", reason}}
      .dump();
}

void Ros2RunPublisher::Publish(const RunSnapshot& snapshot) {
  const auto stamp = ros2::RosTime(std::chrono::system_clock::now());
  if (snapshot.frames != published_frames_) {
    published_frames_ = snapshot.frames;
    writers_->map.Write(*MapMessage(SeenPart(snapshot.grid).ToTrinary(), stamp));
    if (!snapshot.bgr.empty()) {
      const cv::Mat3b overlay = draw::DrawFloorOverlay(snapshot.bgr, snapshot.floor_mask);
      ros2::Sample<sensor_msgs_msg_dds__Image_> image;
      SetHeader(image->header, stamp, "camera");
      image->height = static_cast<std::uint32_t>(overlay.rows);
      image->width = static_cast<std::uint32_t>(overlay.cols);
      ros2::SetString(image->encoding, "bgr8");
      image->step = static_cast<std::uint32_t>(overlay.cols * 3);
      const cv::Mat3b packed = overlay.isContinuous() ? overlay : overlay.clone();
      ros2::SetSequence(image->data,
                        std::span<const std::uint8_t>(packed.data, packed.total() * 3));
      writers_->floor.Write(*image);
    }
  }
  ros2::Sample<tf2_msgs_msg_dds__TFMessage_> tf;
  ros2::ResizeSequence(tf->transforms, 1);
  SetHeader(tf->transforms._buffer[0].header, stamp, kMapFrame);
  ros2::SetString(tf->transforms._buffer[0].child_frame_id, "odom");
  ros2::SetTransform(tf->transforms._buffer[0].transform, snapshot.map_T_odom);
  writers_->tf.Write(*tf);
  writers_->path.Write(*PathMessage(snapshot.path, stamp));
  writers_->plan.Write(*PathMessage(PlanPoses(snapshot.map_T_robot, snapshot.plan), stamp));
  ros2::Sample<std_msgs_msg_dds__String_> status;
  SetStatus(status, StatusJson("running", snapshot.progress.pirouettes,
                               snapshot.progress.known_area_m2, ""));
  writers_->status.Write(*status);
}

void Ros2RunPublisher::PublishFinal(const mapping::TrinaryMap& map, const ExplorationResult& result,
                                    double linger_s) {
  const auto stamp = ros2::RosTime(std::chrono::system_clock::now());
  writers_->map.Write(*MapMessage(map, stamp));
  writers_->path.Write(*PathMessage(result.path, stamp));
  writers_->plan.Write(*PathMessage({}, stamp));
  std::size_t known = 0;
  for (const mapping::CellState c : map.cells) known += c != mapping::CellState::kUnknown ? 1 : 0;
  const double cell = map.geometry.resolution();
  ros2::Sample<std_msgs_msg_dds__String_> status;
  SetStatus(status, StatusJson(result.status, result.pirouettes,
                               static_cast<double>(known) * cell * cell, result.reason));
  writers_->status.Write(*status);
  const auto linger = static_cast<dds_duration_t>(linger_s * 1e9);
  for (const dds_entity_t writer :
       {writers_->map.entity(), writers_->path.entity(), writers_->status.entity()}) {
    dds_wait_for_acks(writer, linger);  // a reader that does not answer is not waited for longer
  }
}

}  // namespace pirouette::run
