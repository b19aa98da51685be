#include "pirouette/robot/ros2/ros2_cdr.h"

#include <dds/ddsi/ddsi_cdrstream.h>
#include <dds/ddsi/q_protocol.h>

namespace pirouette::robot::ros2 {

namespace {

// The encapsulation header of little-endian plain CDR (RTPS 9.4.2.13,
// CDR_LE), then two bytes of options.
constexpr std::uint8_t kCdrLe[4] = {0x00, 0x01, 0x00, 0x00};
constexpr std::size_t kHeaderBytes = 4;
constexpr std::uint32_t kInitialBytes = 256;

}  // namespace

std::vector<std::uint8_t> SerializeCdr(const void* message, const dds_topic_descriptor_t& type) {
  dds_ostreamLE_t os;
  dds_ostreamLE_init(&os, kInitialBytes, CDR_ENC_VERSION_1);
  dds_stream_writeLE(&os, static_cast<const char*>(message), type.m_ops);
  std::vector<std::uint8_t> bytes(kHeaderBytes + os.x.m_index);
  std::copy(std::begin(kCdrLe), std::end(kCdrLe), bytes.begin());
  std::copy(os.x.m_buffer, os.x.m_buffer + os.x.m_index, bytes.begin() + kHeaderBytes);
  dds_ostreamLE_fini(&os);
  return bytes;
}

bool DeserializeCdr(std::span<const std::uint8_t> bytes, const dds_topic_descriptor_t& type,
                    void* message) {
  if (bytes.size() < kHeaderBytes || bytes[0] != kCdrLe[0] || bytes[1] != kCdrLe[1]) return false;
  const std::span<const std::uint8_t> body = bytes.subspan(kHeaderBytes);
  // No message of a ROS 2 type is empty (and Cyclone's checks take no null buffer).
  if (body.empty()) return false;
  // Cyclone's reader trusts its input: check it first, as Cyclone does with
  // what arrives from the network.
  std::vector<std::uint8_t> copy(body.begin(), body.end());
  std::uint32_t offset = 0;
  if (dds_stream_normalize_data(reinterpret_cast<char*>(copy.data()), &offset,
                                static_cast<std::uint32_t>(copy.size()), false, CDR_ENC_VERSION_1,
                                type.m_ops) == nullptr) {
    return false;
  }
  dds_istream_t is;
  dds_istream_init(&is, static_cast<std::uint32_t>(copy.size()), copy.data(), CDR_ENC_VERSION_1);
  dds_stream_read(&is, static_cast<char*>(message), type.m_ops);
  dds_istream_fini(&is);
  return true;
}

}  // namespace pirouette::robot::ros2
