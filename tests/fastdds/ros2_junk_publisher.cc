// Publishes junk under ROS 2's names, for the test that malformed samples from
// the network never crash pirouette: on NAMESPACE/odom and NAMESPACE/image_raw,
// samples whose bytes are random (seeded), from truncated (0 bytes) to
// oversized (64 kB), typed as nav_msgs/Odometry and sensor_msgs/Image on the
// wire. Eclipse Cyclone DDS in pirouette must drop or refuse every one.
//
// ros2_junk_publisher DOMAIN NAMESPACE SECONDS SEED
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <chrono>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <iostream>
#include <random>
#include <string>
#include <thread>

#include "bad_msgsPubSubTypes.h"

using namespace eprosima::fastdds::dds;  // NOLINT(google-build-using-namespace): a test client

namespace {

DomainParticipant* MakeParticipant(int domain) {
  DomainParticipantQos qos;
  qos.name("ros2_junk_publisher");
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

std::string TopicName(const std::string& ns, const std::string& name) {
  return ns.empty() ? "rt/" + name : "rt/" + ns + "/" + name;
}

// Random bytes: mostly short (the length fields of a real message fall in
// them), sometimes up to 64 kB.
std::vector<unsigned char> Junk(std::mt19937& rng) {
  std::uniform_int_distribution<int> kind(0, 9);
  std::uniform_int_distribution<int> short_size(0, 400);
  std::uniform_int_distribution<int> long_size(0, 65536);
  std::uniform_int_distribution<int> byte(0, 255);
  std::vector<unsigned char> bytes(kind(rng) == 0 ? long_size(rng) : short_size(rng));
  for (unsigned char& b : bytes) b = static_cast<unsigned char>(byte(rng));
  return bytes;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 5) {
    std::cerr << "usage: ros2_junk_publisher DOMAIN NAMESPACE SECONDS SEED\n";
    return 2;
  }
  const std::string ns = argv[2] == std::string("-") ? "" : argv[2];
  DomainParticipant* participant = MakeParticipant(std::stoi(argv[1]));
  if (participant == nullptr) return 1;
  TypeSupport odom_type(new nav_msgs::msg::OdometryPubSubType());
  TypeSupport image_type(new sensor_msgs::msg::ImagePubSubType());
  odom_type.register_type(participant);
  image_type.register_type(participant);
  Topic* odom_topic = participant->create_topic(TopicName(ns, "odom"), odom_type.get_type_name(),
                                                TOPIC_QOS_DEFAULT);
  Topic* image_topic = participant->create_topic(TopicName(ns, "image_raw"),
                                                 image_type.get_type_name(), TOPIC_QOS_DEFAULT);
  Publisher* publisher = participant->create_publisher(PUBLISHER_QOS_DEFAULT);
  DataWriterQos qos = DATAWRITER_QOS_DEFAULT;
  qos.reliability().kind = RELIABLE_RELIABILITY_QOS;
  DataWriter* odom_writer = publisher->create_datawriter(odom_topic, qos);
  DataWriter* image_writer = publisher->create_datawriter(image_topic, qos);
  std::mt19937 rng(static_cast<unsigned>(std::stoul(argv[4])));
  const auto end =
      std::chrono::steady_clock::now() + std::chrono::duration<double>(std::stod(argv[3]));
  long sent = 0;
  while (std::chrono::steady_clock::now() < end) {
    nav_msgs::msg::Odometry odom;
    odom.junk(Junk(rng));
    odom_writer->write(&odom);
    sensor_msgs::msg::Image image;
    image.junk(Junk(rng));
    image_writer->write(&image);
    sent += 2;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  std::cerr << "ros2_junk_publisher: " << sent << " samples\n";
  participant->delete_contained_entities();
  DomainParticipantFactory::get_instance()->delete_participant(participant);
  return 0;
}
