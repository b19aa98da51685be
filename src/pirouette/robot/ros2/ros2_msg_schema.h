#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace pirouette::robot::ros2 {

// The `ros2msg` definition of a ROS 2 message type as ROS 2's tools hand it
// on (rosbag2's MCAP schemas, foxglove_bridge's channels): the type's own
// fields, then every type it uses, each after a line of 80 '=' and
// "MSG: package/Type". Field names, types and order are those of ros2_messages.idl
// (ROS 2's .msg files of builtin_interfaces, std_msgs, geometry_msgs,
// nav_msgs, sensor_msgs, tf2_msgs); type names are written in full.
// `type` is the ROS name: "nav_msgs/msg/OccupancyGrid". None: not one of ours.
std::optional<std::string> Ros2MsgSchema(std::string_view type);

}  // namespace pirouette::robot::ros2
