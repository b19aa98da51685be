#include "pirouette/view/live_server.h"

#include <gtest/gtest.h>
#include <sys/socket.h>

#include <atomic>
#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange unincluded

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/http.hpp>
#include <boost/beast/websocket.hpp>
#include <nlohmann/json.hpp>
#include <thread>

namespace pirouette::view::live_server_test {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace http = beast::http;
namespace websocket = beast::websocket;
using tcp = asio::ip::tcp;
using nlohmann::json;

std::vector<Channel> TwoChannels() {
  return {{1, "/map", "cdr", "nav_msgs/msg/OccupancyGrid", "int8[] data\n", "ros2msg"},
          {2, "/pirouette/status", "cdr", "std_msgs/msg/String", "string data\n", "ros2msg"}};
}

std::shared_ptr<const std::vector<std::uint8_t>> Bytes(std::size_t n, std::uint8_t value) {
  return std::make_shared<const std::vector<std::uint8_t>>(n, value);
}

// Reads fail after 10 s instead of hanging a test.
void SetReadTimeout(tcp::socket& socket) {
  timeval tv{10, 0};
  setsockopt(socket.native_handle(), SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
}

http::response<http::string_body> Get(std::uint16_t port, const std::string& target,
                                      http::verb verb = http::verb::get,
                                      const std::string& upgrade = "") {
  asio::io_context io;
  tcp::socket socket(io);
  socket.connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
  SetReadTimeout(socket);
  http::request<http::string_body> request(verb, target, 11);
  request.set(http::field::host, "127.0.0.1");
  if (!upgrade.empty()) {
    request.set(http::field::connection, "Upgrade");
    request.set(http::field::upgrade, upgrade);
  }
  request.prepare_payload();
  http::write(socket, request);
  beast::flat_buffer buffer;
  http::response<http::string_body> response;
  http::read(socket, buffer, response);
  return response;
}

// A Foxglove client over Beast's synchronous WebSocket.
class Client {
 public:
  explicit Client(std::uint16_t port, std::size_t receive_buffer = 0,
                  const char* subprotocol = "foxglove.websocket.v1")
      : ws_(io_) {
    if (receive_buffer > 0) {
      ws_.next_layer().open(tcp::v4());
      ws_.next_layer().set_option(
          asio::socket_base::receive_buffer_size(static_cast<int>(receive_buffer)));
    }
    ws_.next_layer().connect(tcp::endpoint(asio::ip::make_address("127.0.0.1"), port));
    SetReadTimeout(ws_.next_layer());
    ws_.set_option(websocket::stream_base::decorator([subprotocol](websocket::request_type& r) {
      if (subprotocol != nullptr) r.set(http::field::sec_websocket_protocol, subprotocol);
    }));
    ws_.handshake(response_, "127.0.0.1", "/");
  }

  const websocket::response_type& handshake_response() const { return response_; }

  void SendText(const std::string& text) {
    ws_.text(true);
    ws_.write(asio::buffer(text));
  }
  void SendBinary(const std::vector<std::uint8_t>& bytes) {
    ws_.binary(true);
    ws_.write(asio::buffer(bytes));
  }

  // The next message; its text when it is text.
  std::string Read(bool* binary = nullptr) {
    beast::flat_buffer buffer;
    ws_.read(buffer);
    if (binary != nullptr) *binary = ws_.got_binary();
    return beast::buffers_to_string(buffer.data());
  }

  json ReadJson() { return json::parse(Read()); }

  beast::error_code ReadError() {
    beast::flat_buffer buffer;
    beast::error_code error;
    ws_.read(buffer, error);
    return error;
  }

 private:
  asio::io_context io_;
  websocket::stream<tcp::socket> ws_;
  websocket::response_type response_;
};

LiveServerOptions Loopback(bool control = false) {
  LiveServerOptions options;
  options.endpoint.port = 0;
  options.control = control;
  return options;
}

TEST(LiveServerTest, ServesThePageOnLoopbackByDefault) {
  LiveServer server(Loopback(), TwoChannels());
  EXPECT_EQ(server.endpoint().host, "127.0.0.1");
  ASSERT_NE(server.endpoint().port, 0);
  const auto page = Get(server.endpoint().port, "/");
  EXPECT_EQ(page.result(), http::status::ok);
  EXPECT_EQ(page[http::field::content_type], "text/html; charset=utf-8");
  EXPECT_NE(page.body().find("<html"), std::string::npos);
  EXPECT_EQ(Get(server.endpoint().port, "/app.js").result(), http::status::ok);
}

TEST(LiveServerTest, RefusesPathsMethodsAndUpgradesItDoesNotServe) {
  LiveServer server(Loopback(), TwoChannels());
  const std::uint16_t port = server.endpoint().port;
  EXPECT_EQ(Get(port, "/../etc/passwd").result(), http::status::not_found);
  EXPECT_EQ(Get(port, "/%2e%2e/etc/passwd").result(), http::status::not_found);
  EXPECT_EQ(Get(port, "/nothing.html").result(), http::status::not_found);
  EXPECT_EQ(Get(port, "/", http::verb::post).result(), http::status::method_not_allowed);
  EXPECT_EQ(Get(port, "/", http::verb::get, "h2c").result(), http::status::bad_request);
  EXPECT_GE(server.Stats().refused, 5U);
  EXPECT_EQ(Get(port, "/").result(), http::status::ok);  // it serves on
}

TEST(LiveServerTest, RefusesAWebSocketWithoutTheSubprotocolOrElsewhere) {
  LiveServer server(Loopback(), TwoChannels());
  EXPECT_THROW(Client(server.endpoint().port, 0, nullptr), beast::system_error);
  EXPECT_THROW(Client(server.endpoint().port, 0, "json"), beast::system_error);
  Client good(server.endpoint().port);
  EXPECT_EQ(good.handshake_response()[http::field::sec_websocket_protocol],
            "foxglove.websocket.v1");
}

TEST(LiveServerTest, SaysWhoItIsAdvertisesAndSendsTheLatestToALateSubscriber) {
  LiveServer server(Loopback(), TwoChannels());
  server.Publish(1, Bytes(5, 7), 42);  // before anyone listens
  Client client(server.endpoint().port);
  const json info = client.ReadJson();
  EXPECT_EQ(info["op"], "serverInfo");
  EXPECT_TRUE(info["capabilities"].empty());
  const json advertise = client.ReadJson();
  ASSERT_EQ(advertise["op"], "advertise");
  ASSERT_EQ(advertise["channels"].size(), 2U);
  EXPECT_EQ(advertise["channels"][0]["topic"], "/map");
  client.SendText(R"({"op":"subscribe","subscriptions":[{"id":9,"channelId":1}]})");
  bool binary = false;
  const std::string first = client.Read(&binary);
  ASSERT_TRUE(binary);
  ASSERT_EQ(first.size(), 13U + 5U);
  EXPECT_EQ(first[0], 0x01);
  EXPECT_EQ(first[1], 9);   // subscription id, little-endian
  EXPECT_EQ(first[5], 42);  // the time
  EXPECT_EQ(first[13], 7);
  server.Publish(2, Bytes(3, 1), 43);  // not subscribed: not sent
  server.Publish(1, Bytes(4, 8), 44);
  const std::string second = client.Read(&binary);
  ASSERT_EQ(second.size(), 13U + 4U);
  EXPECT_EQ(second[13], 8);
  EXPECT_TRUE(server.WaitFlushed(5.0));
  EXPECT_EQ(server.Stats().clients, 1);
}

TEST(LiveServerTest, AnswersAMalformedMessageAndServesOn) {
  LiveServer server(Loopback(), TwoChannels());
  Client client(server.endpoint().port);
  client.ReadJson();
  client.ReadJson();
  client.SendText("{not json");
  const json status = client.ReadJson();
  EXPECT_EQ(status["op"], "status");
  EXPECT_EQ(status["level"], 2);
  EXPECT_NE(status["message"].get<std::string>().find("malformed"), std::string::npos);
  client.SendText(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":77}]})");
  EXPECT_NE(client.ReadJson()["message"].get<std::string>().find("no channel 77"),
            std::string::npos);
  client.SendText(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":2}]})");
  server.Publish(2, Bytes(2, 3), 1);
  bool binary = false;
  client.Read(&binary);
  EXPECT_TRUE(binary);
}

TEST(LiveServerTest, RefusesSubscriptionsPastItsBound) {
  LiveServer server(Loopback(), TwoChannels());
  Client client(server.endpoint().port);
  client.ReadJson();
  client.ReadJson();
  json subscriptions = json::array();
  for (int i = 0; i < 65; ++i) subscriptions.push_back({{"id", i}, {"channelId", 1}});
  client.SendText(json{{"op", "subscribe"}, {"subscriptions", subscriptions}}.dump());
  const json refused = client.ReadJson();
  EXPECT_EQ(refused["level"], 2);
  EXPECT_NE(refused["message"].get<std::string>().find("64 subscriptions"), std::string::npos);
}

TEST(LiveServerTest, ClosesAClientWhoseMessageIsTooLargeAndServesOthers) {
  LiveServerOptions options = Loopback();
  options.max_client_message_bytes = 1024;
  LiveServer server(options, TwoChannels());
  Client big(server.endpoint().port);
  big.ReadJson();
  big.ReadJson();
  big.SendText(std::string(4096, ' '));
  // Closed with 1009, or reset: the server closes with the message's rest
  // unread, and TCP may then reset before the close frame is read.
  EXPECT_TRUE(big.ReadError());
  Client next(server.endpoint().port);
  EXPECT_EQ(next.ReadJson()["op"], "serverInfo");
}

TEST(LiveServerTest, RefusesEveryControlWithoutViewControl) {
  std::atomic<int> calls{0};
  LiveServerOptions options = Loopback(false);
  options.on_control = [&](ControlCommand) {
    ++calls;
    return std::string("done");
  };
  LiveServer server(options, TwoChannels());
  Client client(server.endpoint().port);
  client.ReadJson();
  client.ReadJson();
  client.SendText(
      R"({"op":"advertise","channels":[{"id":1,"topic":"/pirouette/control","encoding":"json","schemaName":"pirouette/Control"}]})");
  const json refused = client.ReadJson();
  EXPECT_EQ(refused["level"], 2);
  EXPECT_NE(refused["message"].get<std::string>().find("--view-control"), std::string::npos);
  std::vector<std::uint8_t> stop = {0x01, 1, 0, 0, 0};
  const std::string command = R"({"command":"stop"})";
  stop.insert(stop.end(), command.begin(), command.end());
  client.SendBinary(stop);
  EXPECT_EQ(client.ReadJson()["level"], 2);
  EXPECT_EQ(calls.load(), 0);
}

TEST(LiveServerTest, TakesAControlCommandWithViewControl) {
  std::vector<ControlCommand> commands;
  LiveServerOptions options = Loopback(true);
  options.on_control = [&](ControlCommand c) {
    commands.push_back(c);
    return std::string("pausing");
  };
  LiveServer server(options, TwoChannels());
  Client client(server.endpoint().port);
  EXPECT_EQ(client.ReadJson()["capabilities"], json::array({"clientPublish"}));
  client.ReadJson();
  std::vector<std::uint8_t> pause = {0x01, 4, 0, 0, 0};
  const std::string command = R"({"command":"pause"})";
  pause.insert(pause.end(), command.begin(), command.end());
  client.SendBinary(pause);  // not advertised yet
  EXPECT_NE(client.ReadJson()["message"].get<std::string>().find("not advertised"),
            std::string::npos);
  client.SendText(
      R"({"op":"advertise","channels":[{"id":4,"topic":"/pirouette/control","encoding":"json","schemaName":"pirouette/Control"}]})");
  client.SendBinary(pause);
  const json answer = client.ReadJson();
  EXPECT_EQ(answer["level"], 0);
  EXPECT_EQ(answer["message"], "pausing");
  ASSERT_EQ(commands.size(), 1U);
  EXPECT_EQ(commands[0], ControlCommand::kPause);
}

TEST(LiveServerTest, ASlowClientSkipsMessagesAndGetsTheNewest) {
  LiveServer server(Loopback(), TwoChannels());
  Client slow(server.endpoint().port, 4096);
  slow.ReadJson();
  slow.ReadJson();
  slow.SendText(R"({"op":"subscribe","subscriptions":[{"id":1,"channelId":1}]})");
  constexpr int kMessages = 60;
  constexpr std::size_t kBytes = 1 << 20;  // far more than the sockets buffer
  for (int i = 0; i < kMessages; ++i) {
    server.Publish(1, Bytes(kBytes, static_cast<std::uint8_t>(i)), static_cast<std::uint64_t>(i));
  }
  EXPECT_FALSE(server.WaitFlushed(0.2));  // the client has not read: the server waits on it
  int received = 0;
  std::uint8_t last = 0;
  while (true) {
    const std::string message = slow.Read();
    ++received;
    last = static_cast<std::uint8_t>(message.back());
    if (last == kMessages - 1) break;
  }
  EXPECT_LT(received, kMessages);
  EXPECT_GT(server.Stats().messages_skipped, 0U);
  EXPECT_TRUE(server.WaitFlushed(5.0));
}

TEST(LiveServerTest, SaysWhenItCannotListen) {
  LiveServer first(Loopback(), TwoChannels());
  LiveServerOptions same = Loopback();
  same.endpoint.port = first.endpoint().port;
  try {
    LiveServer second(same, TwoChannels());
    ADD_FAILURE() << "two servers on one port";
  } catch (const ViewError& e) {
    EXPECT_NE(std::string(e.what()).find(std::to_string(same.endpoint.port)), std::string::npos);
  }
  LiveServerOptions nowhere = Loopback();
  nowhere.endpoint.host = "192.0.2.1";  // TEST-NET-1: no interface of this machine
  EXPECT_THROW(LiveServer(nowhere, TwoChannels()), ViewError);
}

}  // namespace pirouette::view::live_server_test
