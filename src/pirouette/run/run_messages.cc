#include "pirouette/run/run_messages.h"

#include <nlohmann/json.hpp>
#include <opencv2/imgcodecs.hpp>

#include <cmath>
#include <span>

#include "pirouette/draw/floor_overlay.h"

namespace pirouette::run {

namespace ros2 = robot::ros2;

namespace {

constexpr const char* kMapFrame = "map";
constexpr const char* kCameraFrame = "camera";
// JPEG quality of the live view's floor picture: 80 keeps a 640×480 frame
// near 40 kB with the floor's edge still sharp.
constexpr int kJpegQuality = 80;

}  // namespace

ros2::Sample<nav_msgs_msg_dds__OccupancyGrid_> MapMessage(const mapping::TrinaryMap& map,
                                                          const RosTime& stamp) {
  ros2::Sample<nav_msgs_msg_dds__OccupancyGrid_> message;
  ros2::SetHeader(message->header, stamp, kMapFrame);
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
                                                  const RosTime& stamp) {
  ros2::Sample<nav_msgs_msg_dds__Path_> message;
  ros2::SetHeader(message->header, stamp, kMapFrame);
  ros2::ResizeSequence(message->poses, poses.size());
  for (std::size_t i = 0; i < poses.size(); ++i) {
    ros2::SetHeader(message->poses._buffer[i].header, stamp, kMapFrame);
    ros2::SetPose(message->poses._buffer[i].pose, poses[i]);
  }
  return message;
}

std::vector<core::Pose2> PathPoses(const std::vector<core::Pose2>& path,
                                   const core::Pose2& map_T_robot) {
  std::vector<core::Pose2> poses = path;
  const bool ends_here = !poses.empty() &&
                         (poses.back().translation() - map_T_robot.translation()).norm() == 0.0 &&
                         poses.back().heading() == map_T_robot.heading();
  if (!ends_here) poses.push_back(map_T_robot);
  return poses;
}

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

ros2::Sample<tf2_msgs_msg_dds__TFMessage_> MapToOdomMessage(const core::Pose2& map_T_odom,
                                                            const RosTime& stamp) {
  ros2::Sample<tf2_msgs_msg_dds__TFMessage_> tf;
  ros2::ResizeSequence(tf->transforms, 1);
  ros2::SetHeader(tf->transforms._buffer[0].header, stamp, kMapFrame);
  ros2::SetString(tf->transforms._buffer[0].child_frame_id, "odom");
  ros2::SetTransform(tf->transforms._buffer[0].transform, map_T_odom);
  return tf;
}

cv::Mat3b FloorPicture(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask) {
  const cv::Mat3b overlay = draw::DrawFloorOverlay(bgr, floor_mask);
  return overlay.isContinuous() ? overlay : cv::Mat3b(overlay.clone());
}

ros2::Sample<sensor_msgs_msg_dds__Image_> FloorImageMessage(const cv::Mat3b& picture,
                                                            const RosTime& stamp) {
  ros2::Sample<sensor_msgs_msg_dds__Image_> image;
  ros2::SetHeader(image->header, stamp, kCameraFrame);
  image->height = static_cast<std::uint32_t>(picture.rows);
  image->width = static_cast<std::uint32_t>(picture.cols);
  ros2::SetString(image->encoding, "bgr8");
  image->step = static_cast<std::uint32_t>(picture.cols * 3);
  const cv::Mat3b packed = picture.isContinuous() ? picture : cv::Mat3b(picture.clone());
  ros2::SetSequence(image->data, std::span<const std::uint8_t>(packed.data, packed.total() * 3));
  return image;
}

ros2::Sample<sensor_msgs_msg_dds__CompressedImage_> FloorJpegMessage(const cv::Mat3b& picture,
                                                                     const RosTime& stamp) {
  std::vector<std::uint8_t> jpeg;
  cv::imencode(".jpg", picture, jpeg, {cv::IMWRITE_JPEG_QUALITY, kJpegQuality});
  ros2::Sample<sensor_msgs_msg_dds__CompressedImage_> image;
  ros2::SetHeader(image->header, stamp, kCameraFrame);
  ros2::SetString(image->format, "jpeg");
  ros2::SetSequence(image->data, std::span<const std::uint8_t>(jpeg));
  return image;
}

std::string StatusJson(const std::string& status, int stops, double known_area_m2,
                       const std::string& reason, double elapsed_s) {
  constexpr double kPerSquareMetre = 1e4;  // rounded to cm²
  constexpr double kPerSecond = 10.0;      // rounded to 0.1 s
  nlohmann::json json{
      {"status", status},
      {"stops", stops},
      {"known_area_m2", std::round(known_area_m2 * kPerSquareMetre) / kPerSquareMetre},
      {"reason", reason}};
  if (elapsed_s >= 0.0) json["elapsed_s"] = std::round(elapsed_s * kPerSecond) / kPerSecond;
  return json.dump();
}

ros2::Sample<std_msgs_msg_dds__String_> StatusMessage(const std::string& json) {
  ros2::Sample<std_msgs_msg_dds__String_> message;
  ros2::SetString(message->data, json);
  return message;
}

double KnownAreaM2(const mapping::TrinaryMap& map) {
  std::size_t known = 0;
  for (const mapping::CellState c : map.cells) known += c != mapping::CellState::kUnknown ? 1 : 0;
  const double cell = map.geometry.resolution();
  return static_cast<double>(known) * cell * cell;
}

}  // namespace pirouette::run
