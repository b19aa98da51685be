#pragma once

#include <dds/dds.h>

#include <chrono>
#include <cstring>
#include <span>
#include <string_view>
#include <utility>

#include "pirouette/core/pose2.h"
#include "pirouette/robot/ros2/ros2_message_type.h"

namespace pirouette::robot::ros2 {

// A message of type T that owns its strings and sequences as Cyclone
// allocates them (dds_string_dup, dds_alloc), and frees them with
// dds_sample_free when it goes: what a reader takes into, and what a writer
// is given. Movable, not copyable.
template <class T>
class Sample {
 public:
  Sample() { std::memset(&value_, 0, sizeof value_); }
  ~Sample() { dds_sample_free(&value_, MessageType<T>::Descriptor(), DDS_FREE_CONTENTS); }
  Sample(Sample&& other) noexcept : Sample() { std::swap(value_, other.value_); }
  Sample& operator=(Sample&& other) noexcept {
    std::swap(value_, other.value_);
    return *this;
  }
  Sample(const Sample&) = delete;
  Sample& operator=(const Sample&) = delete;

  T& operator*() { return value_; }
  const T& operator*() const { return value_; }
  T* operator->() { return &value_; }
  const T* operator->() const { return &value_; }

 private:
  T value_;
};

// Sets a message's string field (freeing what it held) to a copy of `text`.
void SetString(char*& field, std::string_view text);

// A message's header: its stamp and frame_id (a REP-105 frame name).
void SetHeader(std_msgs_msg_dds__Header_& header, const builtin_interfaces_msg_dds__Time_& stamp,
               std::string_view frame);

// Sets a message's sequence field (freeing what it held) to a copy of
// `values`; Seq is one of idlc's dds_sequence_* structs.
template <class Seq, class V>
void SetSequence(Seq& seq, std::span<const V> values) {
  static_assert(sizeof(*seq._buffer) == sizeof(V));
  if (seq._release) dds_free(seq._buffer);
  seq._buffer = nullptr;
  seq._length = seq._maximum = 0;
  seq._release = false;
  if (values.empty()) return;
  seq._buffer = static_cast<decltype(seq._buffer)>(dds_alloc(values.size_bytes()));
  std::memcpy(seq._buffer, values.data(), values.size_bytes());
  seq._length = seq._maximum = static_cast<std::uint32_t>(values.size());
  seq._release = true;
}

// A sequence field of `count` zeroed elements (freeing what it held), to
// fill in place: for sequences of structs (a Path's poses). Element strings
// are freed with the message.
template <class Seq>
void ResizeSequence(Seq& seq, std::size_t count) {
  if (seq._release) dds_free(seq._buffer);
  seq._buffer = nullptr;
  seq._length = seq._maximum = 0;
  seq._release = false;
  if (count == 0) return;
  const std::size_t bytes = count * sizeof(*seq._buffer);
  seq._buffer = static_cast<decltype(seq._buffer)>(dds_alloc(bytes));
  std::memset(seq._buffer, 0, bytes);
  seq._length = seq._maximum = static_cast<std::uint32_t>(count);
  seq._release = true;
}

// builtin_interfaces/Time of a moment of the system clock (ROS 2's time
// since the Unix epoch).
builtin_interfaces_msg_dds__Time_ RosTime(std::chrono::system_clock::time_point when);

// builtin_interfaces/Time of a number of seconds (≥ 0) on some clock (a
// simulator's, since it started).
builtin_interfaces_msg_dds__Time_ RosTimeOfSeconds(double seconds);

// Seconds since the epoch of a builtin_interfaces/Time.
double Seconds(const builtin_interfaces_msg_dds__Time_& time);

// A planar pose as geometry_msgs/Pose (z 0, rotation about z) and back (the
// yaw of the quaternion's rotation; an unnormalised quaternion is read as
// its normalised one, a zero one as no rotation).
void SetPose(geometry_msgs_msg_dds__Pose_& pose, const core::Pose2& pose2);
core::Pose2 PoseOf(const geometry_msgs_msg_dds__Pose_& pose);

// The same for geometry_msgs/Transform.
void SetTransform(geometry_msgs_msg_dds__Transform_& transform, const core::Pose2& pose2);

}  // namespace pirouette::robot::ros2
