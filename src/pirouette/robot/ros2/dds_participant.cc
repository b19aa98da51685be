#include "pirouette/robot/ros2/dds_participant.h"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <cstdlib>
#include <map>
#include <memory>
#include <mutex>

namespace pirouette::robot::ros2 {

dds_return_t CheckDds(dds_return_t rc, std::string_view what) {
  if (rc < 0) throw DdsError(fmt::format("{}: {}", what, dds_strretcode(rc)));
  return rc;
}

std::string CycloneConfigFor(const DdsNetwork& network) {
  if (network.interface == "auto") return "";
  for (const char c : network.interface) {
    if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '.' && c != '-' && c != '_' &&
        c != ':') {
      throw std::invalid_argument(fmt::format(
          "network interface \"{}\": only letters, digits and . - _ :", network.interface));
    }
  }
  if (!network.interface.empty()) {
    const bool is_address = network.interface.find_first_of(".:") != std::string::npos;
    return fmt::format(
        "<CycloneDDS><Domain Id=\"any\"><General><Interfaces><NetworkInterface {}=\"{}\"/>"
        "</Interfaces></General></Domain></CycloneDDS>",
        is_address ? "address" : "name", network.interface);
  }
  return fmt::format(
      "<CycloneDDS><Domain Id=\"any\">"
      "<General><Interfaces><NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
      "<AllowMulticast>false</AllowMulticast></General>"
      "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
      "<MaxAutoParticipantIndex>{}</MaxAutoParticipantIndex>"
      "<Peers><Peer address=\"127.0.0.1\"/></Peers>"
      "<SPDPInterval>1s</SPDPInterval></Discovery>"
      "</Domain></CycloneDDS>",
      kMaxParticipantIndex);
}

int RosDomainIdFromEnvironment() {
  const char* text = std::getenv("ROS_DOMAIN_ID");
  if (text == nullptr || *text == '\0') return 0;
  // ROS 2 accepts 0..232 (0..101 keep clear of Linux's ephemeral ports).
  constexpr int kMaxDomainId = 232;
  const std::string_view value(text);
  int id = -1;
  const auto [end, error] = std::from_chars(value.data(), value.data() + value.size(), id);
  if (error != std::errc() || end != value.data() + value.size() || id < 0 || id > kMaxDomainId) {
    throw std::invalid_argument(
        fmt::format("ROS_DOMAIN_ID \"{}\": must be a whole number 0..{}", value, kMaxDomainId));
  }
  return id;
}

namespace {

// The tokens of a ROS 2 name, checked as rcl checks a topic name.
void CheckRosName(std::string_view name, std::string_view what) {
  if (name.empty()) throw std::invalid_argument(fmt::format("{}: empty", what));
  std::size_t start = 0;
  while (start <= name.size()) {
    const std::size_t end = std::min(name.find('/', start), name.size());
    const std::string_view token = name.substr(start, end - start);
    if (token.empty()) {
      throw std::invalid_argument(fmt::format(R"({} "{}": an empty token ("//"))", what, name));
    }
    if (std::isdigit(static_cast<unsigned char>(token.front())) != 0) {
      throw std::invalid_argument(
          fmt::format("{} \"{}\": a token may not start with a digit", what, name));
    }
    for (const char c : token) {
      if (std::isalnum(static_cast<unsigned char>(c)) == 0 && c != '_') {
        throw std::invalid_argument(
            fmt::format("{} \"{}\": only letters, digits, '_' and '/' are allowed", what, name));
      }
    }
    start = end + 1;
  }
}

std::string_view TrimSlashes(std::string_view text) {
  while (!text.empty() && text.front() == '/') text.remove_prefix(1);
  while (!text.empty() && text.back() == '/') text.remove_suffix(1);
  return text;
}

// The domains this process created, with how many participants use each.
struct DomainTable {
  std::mutex mutex;
  std::map<int, std::pair<dds_entity_t, int>> domains;
};

DomainTable& Domains() {
  static DomainTable table;
  return table;
}

}  // namespace

std::string RosTopicName(std::string_view ros_namespace, std::string_view relative) {
  const std::string_view ns = TrimSlashes(ros_namespace);
  if (!ns.empty()) CheckRosName(ns, "ROS namespace");
  CheckRosName(relative, "topic name");
  return ns.empty() ? fmt::format("rt/{}", relative) : fmt::format("rt/{}/{}", ns, relative);
}

DdsParticipant::DdsParticipant(int domain_id, const DdsNetwork& network, std::string ros_namespace)
    : domain_id_(domain_id), ros_namespace_(std::move(ros_namespace)) {
  if (!ros_namespace_.empty()) CheckRosName(TrimSlashes(ros_namespace_), "ROS namespace");
  // Cyclone's errors only: it warns on standard error for every sample that
  // does not decode (junk under a ROS 2 name floods the terminal with one
  // line per sample); such samples are dropped whatever the log says.
  dds_set_log_mask(DDS_LC_FATAL | DDS_LC_ERROR);
  const std::string config = CycloneConfigFor(network);
  if (!config.empty()) {
    DomainTable& table = Domains();
    const std::lock_guard lock(table.mutex);
    auto found = table.domains.find(domain_id);
    if (found == table.domains.end()) {
      const dds_entity_t domain =
          CheckDds(dds_create_domain(static_cast<dds_domainid_t>(domain_id), config.c_str()),
                   fmt::format("creating DDS domain {} on the loopback interface", domain_id));
      found = table.domains.emplace(domain_id, std::make_pair(domain, 0)).first;
    }
    ++found->second.second;
    owns_domain_reference_ = true;
  }
  std::unique_ptr<dds_qos_t, decltype(&dds_delete_qos)> qos(dds_create_qos(), &dds_delete_qos);
  static constexpr std::string_view kEnclave = "enclave=/;";
  dds_qset_userdata(qos.get(), kEnclave.data(), kEnclave.size());
  const dds_entity_t participant =
      dds_create_participant(static_cast<dds_domainid_t>(domain_id), qos.get(), nullptr);
  if (participant < 0) {
    ReleaseDomain();
    CheckDds(participant, fmt::format("creating a DDS participant in domain {}", domain_id));
  }
  participant_ = participant;
}

DdsParticipant::~DdsParticipant() {
  if (participant_ > 0) dds_delete(participant_);
  ReleaseDomain();
}

void DdsParticipant::ReleaseDomain() {
  if (!owns_domain_reference_) return;
  owns_domain_reference_ = false;
  DomainTable& table = Domains();
  const std::lock_guard lock(table.mutex);
  const auto found = table.domains.find(domain_id_);
  if (found != table.domains.end() && --found->second.second == 0) {
    dds_delete(found->second.first);
    table.domains.erase(found);
  }
}

std::string DdsParticipant::TopicName(std::string_view relative) const {
  return RosTopicName(ros_namespace_, relative);
}

}  // namespace pirouette::robot::ros2
