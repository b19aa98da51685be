// An independent ROS 2 subscriber for pirouette's tests, on eProsima Fast DDS
// (ROS 2's default middleware) with types fastddsgen generated from ROS 2's
// message definitions (ros2_msgs.idl): it shares no code with pirouette.
//
// ros2_map_listener DOMAIN NAMESPACE OUT_DIR TIMEOUT_S
// subscribes to NAMESPACE/map (reliable, transient local) and
// NAMESPACE/pirouette/status (reliable, transient local), as RViz2 would, and
// when a status other than "running" has arrived and no map for 3 s (or at
// the timeout) writes OUT_DIR/received.pgm (the last map, as map_server's
// map_saver writes a trinary map: 0 occupied, 254 free, 205 unknown, the top
// row first), OUT_DIR/received.txt ("RESOLUTION ORIGIN_X ORIGIN_Y MAPS",
// then the last status's JSON on its own line, then the maps' latency from
// their stamp to their arrival) and exits 0; 1 when no map or
// no final status came.
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <string>
#include <thread>
#include <vector>

#include "ros2_msgsPubSubTypes.h"

using namespace eprosima::fastdds::dds;  // NOLINT(google-build-using-namespace): a test client

namespace {

// A participant that finds peers on 127.0.0.1 by unicast (the test's
// loopback-only setting: no multicast, no shared memory).
DomainParticipant* MakeParticipant(int domain) {
  DomainParticipantQos qos;
  qos.name("ros2_map_listener");
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.emplace_back("127.0.0.1");
  qos.transport().user_transports.push_back(udp);
  qos.transport().use_builtin_transports = false;
  eprosima::fastrtps::rtps::Locator_t peer;
  eprosima::fastrtps::rtps::IPLocator::setIPv4(peer, 127, 0, 0, 1);
  qos.wire_protocol().builtin.initialPeersList.push_back(peer);
  qos.wire_protocol().builtin.discovery_config.leaseDuration_announcementperiod = {1, 0};
  return DomainParticipantFactory::get_instance()->create_participant(domain, qos);
}

DataReaderQos LatchedReaderQos() {
  DataReaderQos qos = DATAREADER_QOS_DEFAULT;
  qos.reliability().kind = RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = TRANSIENT_LOCAL_DURABILITY_QOS;
  qos.history().kind = KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 1;
  return qos;
}

std::string TopicName(const std::string& ns, const std::string& name) {
  return ns.empty() ? "rt/" + name : "rt/" + ns + "/" + name;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: ros2_map_listener DOMAIN NAMESPACE OUT_DIR TIMEOUT_S\n";
    return 2;
  }
  const int domain = std::stoi(argv[1]);
  const std::string ns = argv[2] == std::string("-") ? "" : argv[2];
  const std::string out_dir = argv[3];
  const double timeout_s = std::stod(argv[4]);

  DomainParticipant* participant = MakeParticipant(domain);
  if (participant == nullptr) {
    std::cerr << "ros2_map_listener: no participant\n";
    return 1;
  }
  TypeSupport map_type(new nav_msgs::msg::OccupancyGridPubSubType());
  TypeSupport string_type(new std_msgs::msg::StringPubSubType());
  map_type.register_type(participant);
  string_type.register_type(participant);
  Topic* map_topic =
      participant->create_topic(TopicName(ns, "map"), map_type.get_type_name(), TOPIC_QOS_DEFAULT);
  Topic* status_topic = participant->create_topic(TopicName(ns, "pirouette/status"),
                                                  string_type.get_type_name(), TOPIC_QOS_DEFAULT);
  Subscriber* subscriber = participant->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
  DataReader* map_reader = subscriber->create_datareader(map_topic, LatchedReaderQos());
  DataReader* status_reader = subscriber->create_datareader(status_topic, LatchedReaderQos());

  using Clock = std::chrono::steady_clock;
  const auto start = Clock::now();
  auto last_map = Clock::now();
  nav_msgs::msg::OccupancyGrid map;
  std::string status;
  int maps = 0;
  bool final_status = false;
  std::vector<double> latencies_ms;
  std::size_t bytes = 0;  // the maps' cells
  for (;;) {
    SampleInfo info;
    nav_msgs::msg::OccupancyGrid m;
    while (map_reader->take_next_sample(&m, &info) == ReturnCode_t::RETCODE_OK) {
      if (!info.valid_data) continue;
      map = m;
      ++maps;
      last_map = Clock::now();
      // The latency from the map's stamp (pirouette's system clock, the same
      // machine) to its arrival here.
      const double now_s =
          std::chrono::duration<double>(std::chrono::system_clock::now().time_since_epoch())
              .count();
      latencies_ms.push_back(
          1e3 * (now_s - (m.header().stamp().sec() + 1e-9 * m.header().stamp().nanosec())));
      bytes += m.data().size();
    }
    std_msgs::msg::String s;
    while (status_reader->take_next_sample(&s, &info) == ReturnCode_t::RETCODE_OK) {
      if (!info.valid_data) continue;
      status = s.data();
      final_status = status.find("\"status\":\"running\"") == std::string::npos;
    }
    const auto now = Clock::now();
    if (final_status && maps > 0 && now - last_map > std::chrono::seconds(3)) break;
    if (std::chrono::duration<double>(now - start).count() > timeout_s) break;
    std::this_thread::sleep_for(std::chrono::milliseconds(20));
  }
  participant->delete_contained_entities();
  DomainParticipantFactory::get_instance()->delete_participant(participant);
  if (maps == 0 || !final_status) {
    std::cerr << "ros2_map_listener: " << maps << " maps, status: " << status << "\n";
    return 1;
  }

  const unsigned width = map.info().width();
  const unsigned height = map.info().height();
  std::ofstream pgm(out_dir + "/received.pgm", std::ios::binary);
  pgm << "P5\n" << width << " " << height << "\n255\n";
  for (unsigned row = height; row-- > 0;) {
    for (unsigned col = 0; col < width; ++col) {
      const int v = map.data().at(static_cast<std::size_t>(row) * width + col);
      pgm.put(static_cast<char>(v == 100 ? 0 : v == 0 ? 254 : 205));
    }
  }
  std::ofstream txt(out_dir + "/received.txt");
  char line[256];
  std::snprintf(line, sizeof line, "%.9g %.9g %.9g %d\n", map.info().resolution(),
                map.info().origin().position().x(), map.info().origin().position().y(), maps);
  txt << line << status << "\n";
  std::sort(latencies_ms.begin(), latencies_ms.end());
  std::snprintf(line, sizeof line, "latency_ms median %.2f max %.2f; map cells received %zu\n",
                latencies_ms[latencies_ms.size() / 2], latencies_ms.back(), bytes);
  txt << line;
  return 0;
}
