#pragma once

#include <dds/dds.h>

#include <stdexcept>
#include <string>
#include <string_view>

namespace pirouette::robot::ros2 {

// A call into Cyclone DDS failed: what was asked and Cyclone's reason.
class DdsError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

// Throws DdsError "<what>: <Cyclone's reason>" when `rc` is a DDS error (< 0);
// returns it otherwise (an entity, or DDS_RETCODE_OK).
dds_return_t CheckDds(dds_return_t rc, std::string_view what);

// Where the participant may talk. The default keeps every packet on the
// loopback interface: 127.0.0.1 only, no multicast, discovery by unicast to
// the local participant indices (ports 7400 + 250·domain + 10 + 2·index, for
// index 0..kMaxParticipantIndex), a participant announcement every second.
struct DdsNetwork {
  // "": loopback only (above). "auto": Cyclone's own defaults (the first
  // multicast-capable interface, multicast discovery), or the configuration
  // CYCLONEDDS_URI names when it is set. Anything else: that interface (a
  // name such as eth0 or an IPv4 address), with Cyclone's multicast defaults.
  std::string interface;
};

inline constexpr int kMaxParticipantIndex = 32;

// The Cyclone configuration (XML) for a network, or "" for Cyclone's own
// defaults (and CYCLONEDDS_URI). Throws std::invalid_argument for an
// interface name that could break out of its XML attribute.
std::string CycloneConfigFor(const DdsNetwork& network);

// The ROS 2 domain: ROS_DOMAIN_ID when set (0..232, as ROS 2 allows), else 0.
// Throws std::invalid_argument naming the variable for a bad value.
int RosDomainIdFromEnvironment();

// The name of topic `relative` (e.g. "map", "pirouette/status") in ROS 2's
// DDS naming: "rt/" + namespace + "/" + relative, the namespace without
// leading or trailing slashes ("" for none). Throws std::invalid_argument for
// a namespace or name that ROS 2 would refuse (empty tokens, characters other
// than letters, digits, '_' and '/', a token starting with a digit).
std::string RosTopicName(std::string_view ros_namespace, std::string_view relative);

// One DDS domain participant, as a ROS 2 node's: its user data
// "enclave=/;" (what rmw_cyclonedds and rmw_fastrtps write, and what ROS 2's
// tools read to call it a node's). Several participants in one process may
// share a domain: the domain is created with the configuration of the first
// and deleted with the last. Not copyable; deletes all it created.
class DdsParticipant {
 public:
  // Throws DdsError when Cyclone refuses the configuration or the domain.
  DdsParticipant(int domain_id, const DdsNetwork& network, std::string ros_namespace = "");
  ~DdsParticipant();
  DdsParticipant(const DdsParticipant&) = delete;
  DdsParticipant& operator=(const DdsParticipant&) = delete;

  dds_entity_t entity() const { return participant_; }
  int domain_id() const { return domain_id_; }
  // RosTopicName with this participant's namespace.
  std::string TopicName(std::string_view relative) const;

 private:
  void ReleaseDomain();  // the domain goes with its last participant

  int domain_id_;
  std::string ros_namespace_;
  bool owns_domain_reference_ = false;
  dds_entity_t participant_ = 0;
};

}  // namespace pirouette::robot::ros2
