#include "pirouette/robot/ros2/dds_participant.h"

#include <gtest/gtest.h>

#include <chrono>
#include <cstdlib>
#include <thread>
#include <vector>

#include "pirouette/robot/ros2/dds_reader.h"
#include "pirouette/robot/ros2/dds_writer.h"

namespace pirouette::robot::ros2 {
namespace {

// Each test that talks uses a domain of its own (ports 7400 + 250·d...).
constexpr int kRoundTripDomain = 171;
constexpr int kSharedDomain = 172;

TEST(RosTopicName, FollowsRos2sDdsNaming) {
  EXPECT_EQ(RosTopicName("", "map"), "rt/map");
  EXPECT_EQ(RosTopicName("/robot1/", "pirouette/status"), "rt/robot1/pirouette/status");
  EXPECT_EQ(RosTopicName("a/b", "cmd_vel"), "rt/a/b/cmd_vel");
}

TEST(RosTopicName, RefusesWhatRos2Refuses) {
  EXPECT_THROW(RosTopicName("", ""), std::invalid_argument);
  EXPECT_THROW(RosTopicName("bad ns", "map"), std::invalid_argument);
  EXPECT_THROW(RosTopicName("1robot", "map"), std::invalid_argument);
  EXPECT_THROW(RosTopicName("", "a//b"), std::invalid_argument);
  EXPECT_THROW(RosTopicName("", "map-2"), std::invalid_argument);
}

TEST(RosDomainId, ReadsTheEnvironmentAndRefusesNonsense) {
  ::unsetenv("ROS_DOMAIN_ID");
  EXPECT_EQ(RosDomainIdFromEnvironment(), 0);
  ::setenv("ROS_DOMAIN_ID", "42", 1);
  EXPECT_EQ(RosDomainIdFromEnvironment(), 42);
  for (const char* bad : {"-1", "233", "4x", "x"}) {
    ::setenv("ROS_DOMAIN_ID", bad, 1);
    EXPECT_THROW(RosDomainIdFromEnvironment(), std::invalid_argument) << bad;
  }
  ::unsetenv("ROS_DOMAIN_ID");
}

TEST(CycloneConfig, LoopbackByDefaultWithoutMulticast) {
  const std::string config = CycloneConfigFor({});
  EXPECT_NE(config.find("address=\"127.0.0.1\""), std::string::npos);
  EXPECT_NE(config.find("<AllowMulticast>false</AllowMulticast>"), std::string::npos);
  EXPECT_NE(config.find("<Peer address=\"127.0.0.1\"/>"), std::string::npos);
  EXPECT_EQ(CycloneConfigFor({"auto"}), "");
  EXPECT_NE(CycloneConfigFor({"eth0"}).find("name=\"eth0\""), std::string::npos);
  EXPECT_NE(CycloneConfigFor({"10.0.0.7"}).find("address=\"10.0.0.7\""), std::string::npos);
  EXPECT_THROW(CycloneConfigFor({"eth0\"/><x"}), std::invalid_argument);
}

// Waits until `ready` or about five seconds have passed.
template <class F>
bool WaitUntil(F ready) {
  for (int i = 0; i < 500; ++i) {
    if (ready()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return ready();
}

TEST(DdsParticipant, AWriterAndAReaderOnLoopbackExchangeAMap) {
  const DdsParticipant a(kRoundTripDomain, {}, "pirouette_test");
  const DdsParticipant b(kRoundTripDomain, {}, "pirouette_test");
  DdsWriter<nav_msgs_msg_dds__OccupancyGrid_> writer(a, "map", kMapQos);
  EXPECT_EQ(writer.topic_name(), "rt/pirouette_test/map");

  Sample<nav_msgs_msg_dds__OccupancyGrid_> map;
  SetString(map->header.frame_id, "map");
  map->info.width = 3;
  map->info.height = 2;
  map->info.resolution = 0.05F;
  const std::vector<std::int8_t> cells = {0, 100, -1, -1, 0, 100};
  SetSequence(map->data, std::span<const std::int8_t>(cells));
  writer.Write(*map);  // before the reader exists: transient local keeps it

  DdsReader<nav_msgs_msg_dds__OccupancyGrid_> reader(b, "map", kMapQos);
  ASSERT_TRUE(WaitUntil([&] { return reader.MatchedWriters() == 1; }));
  ASSERT_TRUE(reader.WaitForData(DDS_SECS(5)));
  const auto got = reader.Take();
  ASSERT_TRUE(got.has_value());
  EXPECT_STREQ((*got)->header.frame_id, "map");
  EXPECT_EQ((*got)->info.width, 3U);
  EXPECT_FLOAT_EQ((*got)->info.resolution, 0.05F);
  ASSERT_EQ((*got)->data._length, cells.size());
  EXPECT_EQ(std::vector<std::int8_t>((*got)->data._buffer, (*got)->data._buffer + cells.size()),
            cells);
  EXPECT_FALSE(reader.Take().has_value());
}

TEST(DdsParticipant, ParticipantsShareADomainAndOutliveEachOther) {
  auto first = std::make_unique<DdsParticipant>(kSharedDomain, DdsNetwork{});
  const DdsParticipant second(kSharedDomain, {});
  first.reset();  // the domain stays for the second
  DdsWriter<std_msgs_msg_dds__String_> writer(second, "chatter", kReliableQos);
  Sample<std_msgs_msg_dds__String_> text;
  SetString(text->data, "still here");
  EXPECT_NO_THROW(writer.Write(*text));
}

TEST(DdsParticipant, ANamespaceRos2WouldRefuseIsRefused) {
  EXPECT_THROW(DdsParticipant(kSharedDomain, {}, "not a namespace"), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::robot::ros2
