// An independent ROS 2 robot for pirouette's tests, on eProsima Fast DDS
// with types fastddsgen generated from ROS 2's message definitions
// (ros2_msgs.idl): it shares no code with pirouette's DDS layer.
//
// ros2_fake_robot DOMAIN NAMESPACE HOST PORT TIMEOUT_S
//
// A ROS 2 base as a driver would publish it: it obeys NAMESPACE/cmd_vel
// (geometry_msgs/Twist, reliable), publishes NAMESPACE/odom
// (nav_msgs/Odometry, reliable, 50 Hz of its own clock) and, while it stands
// still, NAMESPACE/image_raw (sensor_msgs/Image in bgr8, 10 Hz). Its body and
// camera are a simulator it reaches over TCP with pirouette's documented
// robot line protocol (docs/robot-protocol.md: HELLO, TURN, MOVE, CAPTURE,
// written here from the document): each step of 20 ms of its clock it sends
// the step's motion (TURN ω·dt, MOVE v·dt) and takes the odometry the
// simulator answers, so a drive into a wall stalls there as a real base
// does. Its clock steps when a cmd_vel arrives and after 20 ms of wall time
// otherwise. Exits 0 at the timeout, or 1 when the simulator fails.
#include <arpa/inet.h>
#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>
#include <netdb.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <iostream>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

#include "ros2_msgsPubSubTypes.h"

using namespace eprosima::fastdds::dds;  // NOLINT(google-build-using-namespace): a test client

namespace {

constexpr double kStepS = 0.02;           // odometry at 50 Hz
constexpr double kFramePeriodS = 0.1;     // frames at 10 Hz while still
constexpr double kCommandTimeoutS = 0.5;  // a base stops when cmd_vel goes silent
constexpr double kDegPerRad = 180.0 / std::numbers::pi;

// The line protocol over one TCP connection.
class LineClient {
 public:
  LineClient(const std::string& host, const std::string& port) {
    addrinfo hints{};
    hints.ai_socktype = SOCK_STREAM;
    addrinfo* found = nullptr;
    if (getaddrinfo(host.c_str(), port.c_str(), &hints, &found) != 0) {
      throw std::runtime_error("cannot resolve " + host);
    }
    fd_ = socket(found->ai_family, found->ai_socktype, found->ai_protocol);
    const int rc = connect(fd_, found->ai_addr, found->ai_addrlen);
    freeaddrinfo(found);
    if (rc != 0) throw std::runtime_error("cannot connect to " + host + ":" + port);
  }
  ~LineClient() { close(fd_); }
  LineClient(const LineClient&) = delete;
  LineClient& operator=(const LineClient&) = delete;

  std::string Ask(const std::string& line) {
    const std::string out = line + "\n";
    if (send(fd_, out.data(), out.size(), MSG_NOSIGNAL) != static_cast<ssize_t>(out.size())) {
      throw std::runtime_error("send failed");
    }
    std::string reply;
    for (;;) {
      const char c = Byte();
      if (c == '\n') break;
      if (c != '\r') reply += c;
    }
    if (reply.rfind("ERR", 0) == 0) throw std::runtime_error("simulator: " + reply);
    return reply;
  }
  void Read(std::vector<unsigned char>& bytes) {
    std::size_t got = 0;
    while (got < bytes.size()) {
      const std::size_t from_buffer = std::min(bytes.size() - got, end_ - begin_);
      if (from_buffer > 0) {
        std::copy(buffer_ + begin_, buffer_ + begin_ + from_buffer, bytes.data() + got);
        begin_ += from_buffer;
        got += from_buffer;
        continue;
      }
      Fill();
    }
  }

 private:
  char Byte() {
    if (begin_ == end_) Fill();
    return buffer_[begin_++];
  }
  void Fill() {
    const ssize_t n = recv(fd_, buffer_, sizeof buffer_, 0);
    if (n <= 0) throw std::runtime_error("the simulator closed the connection");
    begin_ = 0;
    end_ = static_cast<std::size_t>(n);
  }
  int fd_ = -1;
  char buffer_[65536];
  std::size_t begin_ = 0;
  std::size_t end_ = 0;
};

// The body: odometry as the simulator answers it.
struct Body {
  double x = 0.0;
  double y = 0.0;
  double heading = 0.0;  // radians
  bool contact = false;
  // Reads "OK <achieved> <x> <y> <heading_deg> <contact>".
  void FromMoveReply(const std::string& reply) {
    std::istringstream in(reply);
    std::string ok;
    double achieved = 0.0;
    double heading_deg = 0.0;
    int touched = 0;
    in >> ok >> achieved >> x >> y >> heading_deg >> touched;
    heading = heading_deg / kDegPerRad;
    contact = touched != 0;
  }
};

DomainParticipant* MakeParticipant(int domain) {
  DomainParticipantQos qos;
  qos.name("ros2_fake_robot");
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

builtin_interfaces::msg::Time Stamp(double t) {
  const long long nanoseconds = std::llround(t * 1e9);
  builtin_interfaces::msg::Time time;
  time.sec(static_cast<int32_t>(nanoseconds / 1000000000));
  time.nanosec(static_cast<uint32_t>(nanoseconds % 1000000000));
  return time;
}

}  // namespace

int main(int argc, char** argv) {
  if (argc != 6) {
    std::cerr << "usage: ros2_fake_robot DOMAIN NAMESPACE HOST PORT TIMEOUT_S\n";
    return 2;
  }
  const int domain = std::stoi(argv[1]);
  const std::string ns = argv[2] == std::string("-") ? "" : argv[2];
  const double timeout_s = std::stod(argv[5]);
  try {
    LineClient sim(argv[3], argv[4]);
    sim.Ask("HELLO pirouette-robot/1");
    Body body;
    {
      std::istringstream in(sim.Ask("ODOM"));
      std::string ok;
      double heading_deg = 0.0;
      in >> ok >> body.x >> body.y >> heading_deg;
      body.heading = heading_deg / kDegPerRad;
    }

    DomainParticipant* participant = MakeParticipant(domain);
    if (participant == nullptr) throw std::runtime_error("no participant");
    TypeSupport twist_type(new geometry_msgs::msg::TwistPubSubType());
    TypeSupport odom_type(new nav_msgs::msg::OdometryPubSubType());
    TypeSupport image_type(new sensor_msgs::msg::ImagePubSubType());
    twist_type.register_type(participant);
    odom_type.register_type(participant);
    image_type.register_type(participant);
    Topic* cmd_topic = participant->create_topic(TopicName(ns, "cmd_vel"),
                                                 twist_type.get_type_name(), TOPIC_QOS_DEFAULT);
    Topic* odom_topic = participant->create_topic(TopicName(ns, "odom"), odom_type.get_type_name(),
                                                  TOPIC_QOS_DEFAULT);
    Topic* image_topic = participant->create_topic(TopicName(ns, "image_raw"),
                                                   image_type.get_type_name(), TOPIC_QOS_DEFAULT);
    Subscriber* subscriber = participant->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
    Publisher* publisher = participant->create_publisher(PUBLISHER_QOS_DEFAULT);
    DataReaderQos reader_qos = DATAREADER_QOS_DEFAULT;
    reader_qos.reliability().kind = RELIABLE_RELIABILITY_QOS;
    reader_qos.history().depth = 10;
    DataReader* cmd_reader = subscriber->create_datareader(cmd_topic, reader_qos);
    DataWriterQos writer_qos = DATAWRITER_QOS_DEFAULT;
    writer_qos.reliability().kind = RELIABLE_RELIABILITY_QOS;
    writer_qos.history().depth = 10;
    DataWriter* odom_writer = publisher->create_datawriter(odom_topic, writer_qos);
    writer_qos.history().depth = 1;
    DataWriter* image_writer = publisher->create_datawriter(image_topic, writer_qos);

    using Clock = std::chrono::steady_clock;
    const auto start = Clock::now();
    double t = 0.0;
    double linear = 0.0;
    double angular = 0.0;
    double last_command_s = 0.0;
    double still_s = 0.0;
    double last_frame_s = -1.0;
    std::vector<unsigned char> rgb;
    long commands = 0;
    while (std::chrono::duration<double>(Clock::now() - start).count() < timeout_s) {
      cmd_reader->wait_for_unread_message(eprosima::fastrtps::Duration_t(0, 20000000));
      geometry_msgs::msg::Twist twist;
      SampleInfo info;
      while (cmd_reader->take_next_sample(&twist, &info) == ReturnCode_t::RETCODE_OK) {
        if (!info.valid_data) continue;
        ++commands;
        linear = twist.linear().x();
        angular = twist.angular().z();
        last_command_s = t;
      }
      if (t - last_command_s > kCommandTimeoutS) linear = angular = 0.0;
      t += kStepS;
      bool moved = false;
      if (angular != 0.0) {
        std::ostringstream turn;
        turn.precision(17);
        turn << "TURN " << angular * kStepS * kDegPerRad;
        body.FromMoveReply(sim.Ask(turn.str()));
        moved = true;
      }
      double executed = 0.0;
      if (linear != 0.0) {
        std::ostringstream move;
        move.precision(17);
        move << "MOVE " << linear * kStepS;
        body.FromMoveReply(sim.Ask(move.str()));
        executed = body.contact ? 0.0 : linear;
        moved = moved || !body.contact;
      }
      still_s = moved ? 0.0 : still_s + kStepS;

      nav_msgs::msg::Odometry odom;
      odom.header().stamp(Stamp(t));
      odom.header().frame_id("odom");
      odom.child_frame_id("base_link");
      odom.pose().pose().position().x(body.x);
      odom.pose().pose().position().y(body.y);
      odom.pose().pose().orientation().z(std::sin(0.5 * body.heading));
      odom.pose().pose().orientation().w(std::cos(0.5 * body.heading));
      odom.twist().twist().linear().x(executed);
      odom.twist().twist().angular().z(angular);
      odom_writer->write(&odom);

      if (still_s >= kStepS && t - last_frame_s >= kFramePeriodS - 1e-9) {
        std::istringstream header(sim.Ask("CAPTURE"));
        std::string word;
        int width = 0;
        int height = 0;
        header >> word >> width >> height;
        rgb.resize(static_cast<std::size_t>(width) * height * 3);
        sim.Read(rgb);
        sensor_msgs::msg::Image image;
        image.header().stamp(Stamp(t));
        image.header().frame_id("camera_optical_frame");
        image.width(width);
        image.height(height);
        image.encoding("bgr8");
        image.step(width * 3);
        image.data().resize(rgb.size());
        for (std::size_t i = 0; i + 2 < rgb.size(); i += 3) {
          image.data()[i] = rgb[i + 2];
          image.data()[i + 1] = rgb[i + 1];
          image.data()[i + 2] = rgb[i];
        }
        image_writer->write(&image);
        last_frame_s = t;
      }
    }
    std::cerr << "ros2_fake_robot: " << commands << " commands in " << t << " s\n";
    participant->delete_contained_entities();
    DomainParticipantFactory::get_instance()->delete_participant(participant);
  } catch (const std::exception& e) {
    std::cerr << "ros2_fake_robot: " << e.what() << "\n";
    return 1;
  }
  return 0;
}
