#pragma once

#include <opencv2/core.hpp>

#include <string>
#include <vector>

#include "pirouette/core/pose2.h"
#include "pirouette/mapping/trinary_map.h"
#include "pirouette/robot/ros2/ros2_sample.h"
#include "pirouette/run/exploration_result.h"

namespace pirouette::run {

// The ROS 2 messages a run is shown by (SPEC.md, "ROS 2 over DDS" and "Live
// view"), built once and sent both over DDS (Ros2RunPublisher) and, as their
// CDR bytes, to the live view (LiveViewPublisher). Frames after REP-105: the
// map and paths in `map`, the floor picture in `camera`.
using RosTime = builtin_interfaces_msg_dds__Time_;

// The map's cells as OccupancyGrid's data (row-major from the bottom row, as
// TrinaryMap keeps them): 0 free, 100 occupied, -1 unknown.
robot::ros2::Sample<nav_msgs_msg_dds__OccupancyGrid_> MapMessage(const mapping::TrinaryMap& map,
                                                                 const RosTime& stamp);

robot::ros2::Sample<nav_msgs_msg_dds__Path_> PathMessage(const std::vector<core::Pose2>& poses,
                                                         const RosTime& stamp);

// Where the robot went, ending where it stands now (`map_T_robot` appended
// when the path does not already end there).
std::vector<core::Pose2> PathPoses(const std::vector<core::Pose2>& path,
                                   const core::Pose2& map_T_robot);

// A plan's waypoints from where the robot stands, each facing the next; empty
// without waypoints.
std::vector<core::Pose2> PlanPoses(const core::Pose2& from,
                                   const std::vector<Eigen::Vector2d>& waypoints);

// tf: map → odom.
robot::ros2::Sample<tf2_msgs_msg_dds__TFMessage_> MapToOdomMessage(const core::Pose2& map_T_odom,
                                                                   const RosTime& stamp);

// The frame with its floor drawn (draw::DrawFloorOverlay), raw bgr8 and as
// JPEG (CompressedImage, format "jpeg").
cv::Mat3b FloorPicture(const cv::Mat3b& bgr, const cv::Mat1b& floor_mask);
robot::ros2::Sample<sensor_msgs_msg_dds__Image_> FloorImageMessage(const cv::Mat3b& picture,
                                                                   const RosTime& stamp);
robot::ros2::Sample<sensor_msgs_msg_dds__CompressedImage_> FloorJpegMessage(
    const cv::Mat3b& picture, const RosTime& stamp);

// The status JSON (one line): {"status", "stops", "known_area_m2" (to cm²),
// "reason"}, and "elapsed_s" (to 0.1 s) when given (>= 0).
std::string StatusJson(const std::string& status, int stops, double known_area_m2,
                       const std::string& reason, double elapsed_s = -1.0);
robot::ros2::Sample<std_msgs_msg_dds__String_> StatusMessage(const std::string& json);

// The known area of a map, m².
double KnownAreaM2(const mapping::TrinaryMap& map);

}  // namespace pirouette::run
