#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "pirouette/robot/ros2/ros2_message_type.h"

namespace pirouette::robot::ros2 {

// The bytes of `ops` (a Cyclone topic descriptor's program) applied to
// `message`: plain little-endian CDR (XCDR1) after the 4-byte encapsulation
// header {0x00, 0x01, 0x00, 0x00}, exactly what a DDS writer of the type puts
// in a sample and what ROS 2 tools (ros2 bag, Foxglove's `cdr` encoding)
// expect. Serialised by Cyclone's own encoder, so they are the wire bytes.
std::vector<std::uint8_t> SerializeCdr(const void* message, const dds_topic_descriptor_t& type);

// Decodes CDR bytes (with their encapsulation header) into `message`, which
// must be zeroed and is then owned by the caller (free with dds_sample_free).
// Returns false when the header is not little-endian plain CDR or the bytes
// do not hold a whole message of the type.
bool DeserializeCdr(std::span<const std::uint8_t> bytes, const dds_topic_descriptor_t& type,
                    void* message);

template <class T>
std::vector<std::uint8_t> SerializeCdr(const T& message) {
  return SerializeCdr(&message, *MessageType<T>::Descriptor());
}

}  // namespace pirouette::robot::ros2
