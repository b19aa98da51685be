#pragma once

#include <dds/dds.h>

#include <memory>

namespace pirouette::robot::ros2 {

// The QoS of a topic, as ROS 2 names its parts (REP-2003): reliable or best
// effort; transient local (a late reader gets the last `depth` samples) or
// volatile; keep the last `depth` samples. `ignore_local`: a reader that
// matches no writer of its own process (to see only other nodes').
struct TopicQos {
  bool reliable = true;
  bool transient_local = false;
  int depth = 10;
  bool ignore_local = false;
};

// SPEC.md's table, by topic.
inline constexpr TopicQos kMapQos{true, true, 1};              // map
inline constexpr TopicQos kLatchedQos{true, true, 1};          // pirouette/path, pirouette/status
inline constexpr TopicQos kReliableQos{true, false, 10};       // cmd_vel, pirouette/plan
inline constexpr TopicQos kTfQos{true, false, 100};            // tf
inline constexpr TopicQos kImageWriterQos{true, false, 1};     // pirouette/floor
inline constexpr TopicQos kSensorReaderQos{false, false, 10};  // image_raw, camera_info, odom
// Other nodes' commands on cmd_vel (a second driver of the robot).
inline constexpr TopicQos kOtherWritersQos{true, false, 10, true};

using QosPointer = std::unique_ptr<dds_qos_t, decltype(&dds_delete_qos)>;

// A Cyclone QoS object for `qos` (a reliable writer blocks at most 100 ms when
// its history is full, then drops the sample rather than stall the loop).
QosPointer MakeQos(const TopicQos& qos);

}  // namespace pirouette::robot::ros2
