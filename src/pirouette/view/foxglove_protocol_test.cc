#include "pirouette/view/foxglove_protocol.h"

#include <gtest/gtest.h>
#include <nlohmann/json.hpp>

namespace pirouette::view {
namespace {

using nlohmann::json;

TEST(FoxgloveProtocolTest, ServerInfoOffersClientPublishOnlyWithControl) {
  const json plain = json::parse(ServerInfoJson("pirouette", false, "s1"));
  EXPECT_EQ(plain["op"], "serverInfo");
  EXPECT_EQ(plain["name"], "pirouette");
  EXPECT_TRUE(plain["capabilities"].empty());
  EXPECT_EQ(plain["sessionId"], "s1");
  const json control = json::parse(ServerInfoJson("pirouette", true, "s1"));
  EXPECT_EQ(control["capabilities"], json::array({"clientPublish"}));
  EXPECT_EQ(control["supportedEncodings"], json::array({"json"}));
}

TEST(FoxgloveProtocolTest, AdvertisesEachChannelWithItsSchema) {
  const json advertise = json::parse(AdvertiseJson(
      {{3, "/map", "cdr", "nav_msgs/msg/OccupancyGrid", "int8[] data\n", "ros2msg"}}));
  EXPECT_EQ(advertise["op"], "advertise");
  ASSERT_EQ(advertise["channels"].size(), 1U);
  const json& c = advertise["channels"][0];
  EXPECT_EQ(c["id"], 3);
  EXPECT_EQ(c["topic"], "/map");
  EXPECT_EQ(c["encoding"], "cdr");
  EXPECT_EQ(c["schemaName"], "nav_msgs/msg/OccupancyGrid");
  EXPECT_EQ(c["schema"], "int8[] data\n");
  EXPECT_EQ(c["schemaEncoding"], "ros2msg");
}

TEST(FoxgloveProtocolTest, MessageDataHeaderIsLittleEndian) {
  const auto header = MessageDataHeader(0x01020304U, 0x1122334455667788ULL);
  const std::array<std::uint8_t, 13> expected = {0x01, 0x04, 0x03, 0x02, 0x01, 0x88, 0x77,
                                                 0x66, 0x55, 0x44, 0x33, 0x22, 0x11};
  EXPECT_EQ(header, expected);
}

TEST(FoxgloveProtocolTest, ParsesSubscribeAndUnsubscribe) {
  const ClientRequest s = ParseClientText(
      R"({"op":"subscribe","subscriptions":[{"id":0,"channelId":2},{"id":7,"channelId":1}]})");
  ASSERT_TRUE(std::holds_alternative<Subscribe>(s));
  ASSERT_EQ(std::get<Subscribe>(s).subscriptions.size(), 2U);
  EXPECT_EQ(std::get<Subscribe>(s).subscriptions[1].id, 7U);
  EXPECT_EQ(std::get<Subscribe>(s).subscriptions[1].channel, 1U);
  const ClientRequest u = ParseClientText(R"({"op":"unsubscribe","subscriptionIds":[0,7]})");
  ASSERT_TRUE(std::holds_alternative<Unsubscribe>(u));
  EXPECT_EQ(std::get<Unsubscribe>(u).ids, (std::vector<std::uint32_t>{0, 7}));
}

TEST(FoxgloveProtocolTest, ParsesAClientsAdvertisement) {
  const ClientRequest a = ParseClientText(
      R"({"op":"advertise","channels":[{"id":1,"topic":"/pirouette/control","encoding":"json","schemaName":"pirouette/Control"}]})");
  ASSERT_TRUE(std::holds_alternative<ClientAdvertise>(a));
  EXPECT_EQ(std::get<ClientAdvertise>(a).channels[0].topic, "/pirouette/control");
}

TEST(FoxgloveProtocolTest, NamesWhatIsWrongWithAMalformedMessage) {
  for (const char* bad : {"", "{", "[]", "42", R"({"op":3})", R"({"nop":"subscribe"})",
                          R"({"op":"subscribe"})", R"({"op":"subscribe","subscriptions":{}})",
                          R"({"op":"subscribe","subscriptions":[{"id":-1,"channelId":0}]})",
                          R"({"op":"subscribe","subscriptions":[{"id":1.5,"channelId":0}]})",
                          R"({"op":"subscribe","subscriptions":[{"id":4294967296,"channelId":0}]})",
                          R"({"op":"unsubscribe","subscriptionIds":["a"]})",
                          R"({"op":"advertise","channels":[{"id":1}]})"}) {
    const ClientRequest r = ParseClientText(bad);
    ASSERT_TRUE(std::holds_alternative<ParseError>(r)) << bad;
    EXPECT_FALSE(std::get<ParseError>(r).reason.empty()) << bad;
  }
  EXPECT_TRUE(std::holds_alternative<Unsupported>(ParseClientText(R"({"op":"getParameters"})")));
}

TEST(FoxgloveProtocolTest, ParsesAClientsBinaryMessage) {
  const std::vector<std::uint8_t> bytes = {0x01, 0x05, 0, 0, 0, '{', '}'};
  const auto m = ParseClientBinary(bytes);
  ASSERT_TRUE(std::holds_alternative<ClientMessage>(m));
  EXPECT_EQ(std::get<ClientMessage>(m).channel, 5U);
  EXPECT_EQ(std::get<ClientMessage>(m).payload.size(), 2U);
  EXPECT_TRUE(std::holds_alternative<ParseError>(ParseClientBinary({})));
  const std::vector<std::uint8_t> short_header = {0x01, 0x05};
  EXPECT_TRUE(std::holds_alternative<ParseError>(ParseClientBinary(short_header)));
  const std::vector<std::uint8_t> service_call = {0x02, 0, 0, 0, 0};
  EXPECT_TRUE(std::holds_alternative<ParseError>(ParseClientBinary(service_call)));
}

TEST(FoxgloveProtocolTest, StatusKeepsAnyTextValidJson) {
  const json status = json::parse(StatusJson(StatusLevel::kError, "bad \xff byte"));
  EXPECT_EQ(status["op"], "status");
  EXPECT_EQ(status["level"], 2);
}

}  // namespace
}  // namespace pirouette::view
