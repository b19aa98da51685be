// The live view's controls and sim-serve's view, end to end: the program as a
// user runs it, a WebSocket client (Beast's) speaking the Foxglove protocol.
// The protocol's conformance is checked against Foxglove's own client in
// tests/js (foxglove_client_test.mjs); this checks what a run does with it.

#include <gtest/gtest.h>

#include <chrono>
#include <future>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <thread>
#include <utility>  // before Asio: Boost 1.74's awaitable.hpp uses std::exchange unincluded

#include <boost/asio.hpp>
#include <boost/beast/core.hpp>
#include <boost/beast/websocket.hpp>

#include "pirouette/io/world_file.h"
#include "pirouette/robot/ros2/ros2_cdr.h"
#include "pirouette/robot/ros2/ros2_sample.h"
#include "pirouette/testing/temp_dir.h"
#include "run_pirouette.h"

namespace pirouette::live_view_cli_test {
namespace {

namespace asio = boost::asio;
namespace beast = boost::beast;
namespace websocket = beast::websocket;
namespace ros2 = robot::ros2;
using tcp = asio::ip::tcp;
using nlohmann::json;
using testing::RunPirouette;

std::string World(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml";
}

// A Foxglove client of a run's live view: connects (retrying while the run
// starts), subscribes to every channel, and hands on what arrives.
class ViewClient {
 public:
  explicit ViewClient(int port) : ws_(io_) {
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(30);
    while (true) {
      beast::error_code error;
      ws_.next_layer().close(error);
      ws_.next_layer().connect(
          tcp::endpoint(asio::ip::make_address("127.0.0.1"), static_cast<std::uint16_t>(port)),
          error);
      if (!error) break;
      if (std::chrono::steady_clock::now() > deadline) throw beast::system_error(error);
      std::this_thread::sleep_for(std::chrono::milliseconds(50));
    }
    timeval tv{30, 0};
    setsockopt(ws_.next_layer().native_handle(), SOL_SOCKET, SO_RCVTIMEO, &tv, sizeof tv);
    ws_.set_option(websocket::stream_base::decorator([](websocket::request_type& r) {
      r.set(beast::http::field::sec_websocket_protocol, "foxglove.websocket.v1");
    }));
    ws_.handshake("127.0.0.1", "/");
    info_ = json::parse(ReadText());
    const json advertise = json::parse(ReadText());
    json subscriptions = json::array();
    for (const json& c : advertise["channels"]) {
      topics_[c["id"].get<std::uint32_t>()] = c["topic"].get<std::string>();
      subscriptions.push_back({{"id", c["id"]}, {"channelId", c["id"]}});
    }
    Send(json{{"op", "subscribe"}, {"subscriptions", subscriptions}});
  }

  const json& info() const { return info_; }

  void Send(const json& message) {
    ws_.text(true);
    ws_.write(asio::buffer(message.dump()));
  }

  void Command(const std::string& command) {
    Send(json::parse(
        R"({"op":"advertise","channels":[{"id":1,"topic":"/pirouette/control","encoding":"json","schemaName":"pirouette/Control"}]})"));
    std::vector<std::uint8_t> bytes = {0x01, 1, 0, 0, 0};
    const std::string payload = json{{"command", command}}.dump();
    bytes.insert(bytes.end(), payload.begin(), payload.end());
    ws_.binary(true);
    ws_.write(asio::buffer(bytes));
  }

  struct Message {
    std::string topic;  // empty: a text message (its JSON in `text`)
    std::vector<std::uint8_t> cdr;
    std::string text;
  };
  // The next message; none when the server closed.
  std::optional<Message> Next() {
    beast::flat_buffer buffer;
    beast::error_code error;
    ws_.read(buffer, error);
    if (error) return std::nullopt;
    const std::string bytes = beast::buffers_to_string(buffer.data());
    if (ws_.got_text()) return Message{"", {}, bytes};
    std::uint32_t subscription = 0;
    std::memcpy(&subscription, bytes.data() + 1, 4);
    return Message{topics_[subscription], {bytes.begin() + 13, bytes.end()}, ""};
  }

  // The status JSON in a /pirouette/status message.
  static json Status(const Message& m) {
    ros2::Sample<std_msgs_msg_dds__String_> s;
    EXPECT_TRUE(ros2::DeserializeCdr(
        m.cdr, *ros2::MessageType<std_msgs_msg_dds__String_>::Descriptor(), &*s));
    return json::parse(s->data);
  }

 private:
  std::string ReadText() {
    beast::flat_buffer buffer;
    ws_.read(buffer);
    return beast::buffers_to_string(buffer.data());
  }

  asio::io_context io_;
  websocket::stream<tcp::socket> ws_;
  json info_;
  std::map<std::uint32_t, std::string> topics_;
};

std::future<testing::RunResult> Explore(const testing::TempDir& dir, const std::string& world,
                                        const std::string& view) {
  return std::async(std::launch::async, [=, out = dir / "out"] {
    return RunPirouette("explore --world " + World(world) + " --out " + out + " --quiet " + view);
  });
}

TEST(LiveViewCliTest, AStopFromTheViewEndsTheRunWithTheMapSoFar) {
  testing::TempDir dir;
  auto run = Explore(dir, "soccer_field", "--view 18741 --view-control --view-linger 5");
  ViewClient client(18741);
  EXPECT_EQ(client.info()["capabilities"], json::array({"clientPublish"}));
  int maps = 0;
  while (auto m = client.Next()) {
    if (m->topic == "/map" && ++maps == 2) client.Command("stop");
    if (m->topic.empty() && json::parse(m->text)["op"] == "status") {
      EXPECT_EQ(json::parse(m->text)["level"], 0) << m->text;
    }
    if (m->topic == "/pirouette/status" && ViewClient::Status(*m)["status"] != "running") {
      EXPECT_EQ(ViewClient::Status(*m)["status"], "interrupted");
      break;
    }
  }
  const testing::RunResult result = run.get();
  EXPECT_EQ(result.exit_code, 1) << result.output();
  EXPECT_NE(result.stderr_only.find("interrupted"), std::string::npos) << result.output();
  const json run_json = json::parse(dir.Read("out/run.json"));
  EXPECT_EQ(run_json["status"], "interrupted");
  EXPECT_EQ(run_json["reason"], "stopped from the live view");
  EXPECT_FALSE(dir.Read("out/map.pgm").empty());
}

TEST(LiveViewCliTest, WithoutViewControlTheRunRefusesAndGoesOn) {
  testing::TempDir dir;
  auto run = Explore(dir, "soccer_field", "--view 18742 --view-linger 5");
  ViewClient client(18742);
  EXPECT_TRUE(client.info()["capabilities"].empty());
  client.Command("stop");
  int refusals = 0;
  std::string end;
  while (auto m = client.Next()) {
    if (m->topic.empty() && json::parse(m->text)["op"] == "status") {
      EXPECT_EQ(json::parse(m->text)["level"], 2) << m->text;
      ++refusals;
    }
    if (m->topic == "/pirouette/status" && ViewClient::Status(*m)["status"] != "running") {
      end = ViewClient::Status(*m)["status"];
      break;
    }
  }
  EXPECT_EQ(refusals, 2);  // the advertisement and the command
  EXPECT_EQ(end, "complete");
  const testing::RunResult result = run.get();
  EXPECT_EQ(result.exit_code, 0) << result.output();
}

TEST(LiveViewCliTest, PauseHoldsTheRunAndResumeLetsItFinish) {
  testing::TempDir dir;
  auto run = Explore(dir, "soccer_field", "--view 18743 --view-control --view-linger 5");
  ViewClient client(18743);
  bool paused = false;
  bool resumed = false;
  int maps_while_paused = 0;
  std::string end;
  std::chrono::steady_clock::time_point paused_at;
  while (auto m = client.Next()) {
    if (m->topic == "/map" && !paused) {
      client.Command("pause");
      paused = true;
      paused_at = std::chrono::steady_clock::now();
    } else if (m->topic == "/map" && !resumed) {
      ++maps_while_paused;
    }
    if (m->topic != "/pirouette/status") continue;
    const json status = ViewClient::Status(*m);
    if (status["status"] == "paused" && !resumed) {
      // Held: wait a while, then let it go on.
      std::this_thread::sleep_for(std::chrono::milliseconds(800));
      client.Command("resume");
      resumed = true;
    } else if (status["status"] != "running" && status["status"] != "paused") {
      end = status["status"];
      break;
    }
  }
  EXPECT_TRUE(resumed);
  EXPECT_LE(maps_while_paused, 1);  // the step under way when the pause came may end
  EXPECT_EQ(end, "complete");
  const testing::RunResult result = run.get();
  EXPECT_EQ(result.exit_code, 0) << result.output();
}

TEST(LiveViewCliTest, HomeDrivesTheRobotBackToItsStart) {
  testing::TempDir dir;
  auto run = Explore(dir, "soccer_field", "--view 18744 --view-control --view-linger 5");
  ViewClient client(18744);
  int maps = 0;
  while (auto m = client.Next()) {
    if (m->topic == "/map" && ++maps == 6) client.Command("home");
    if (m->topic == "/pirouette/status" && ViewClient::Status(*m)["status"] != "running") break;
  }
  const testing::RunResult result = run.get();
  EXPECT_EQ(result.exit_code, 1) << result.output();
  const json run_json = json::parse(dir.Read("out/run.json"));
  EXPECT_EQ(run_json["status"], "interrupted");
  EXPECT_EQ(run_json["reason"], "sent home from the live view");
  const sim::World world = io::LoadWorldFile(World("soccer_field"));
  const json& at = run_json["final_true_pose"];
  const Eigen::Vector2d end(at[0].get<double>(), at[1].get<double>());
  EXPECT_LT((end - world.robot().start.translation()).norm(), 0.1) << at;
  EXPECT_GT(run_json["path_length_m"].get<double>(), 0.1);
}

TEST(LiveViewCliTest, SimServeShowsTheTruthAndTheCamera) {
  testing::TempDir dir;
  auto serve = std::async(std::launch::async, [&] {
    return RunPirouette("sim-serve --world " + World("soccer_field") + " --port 0 --port-file " +
                        (dir / "port") + " --view 18745");
  });
  ViewClient client(18745);
  bool truth = false;
  // The truth: free floor and occupied walls and obstacles.
  while (auto m = client.Next()) {
    if (m->topic != "/map") continue;
    ros2::Sample<nav_msgs_msg_dds__OccupancyGrid_> grid;
    ASSERT_TRUE(ros2::DeserializeCdr(
        m->cdr, *ros2::MessageType<nav_msgs_msg_dds__OccupancyGrid_>::Descriptor(), &*grid));
    int free = 0;
    int occupied = 0;
    for (std::uint32_t i = 0; i < grid->data._length; ++i) {
      free += grid->data._buffer[i] == 0 ? 1 : 0;
      occupied += grid->data._buffer[i] == 100 ? 1 : 0;
    }
    EXPECT_GT(free, 100);
    EXPECT_GT(occupied, 50);
    truth = true;
    break;
  }
  EXPECT_TRUE(truth);
  while (dir.Read("port").empty()) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  const std::string port = std::to_string(std::stoi(dir.Read("port")));
  const testing::RunResult run =
      RunPirouette("explore --robot tcp://127.0.0.1:" + port + " --world " + World("soccer_field") +
                   " --out " + (dir / "out") + " --quiet --max-steps 2");
  EXPECT_EQ(run.exit_code, 0) << run.output();
  bool camera = false;
  while (auto m = client.Next()) {  // the frames the run took, as the simulator rendered them
    if (m->topic == "/pirouette/floor") {
      ros2::Sample<sensor_msgs_msg_dds__CompressedImage_> image;
      ASSERT_TRUE(ros2::DeserializeCdr(
          m->cdr, *ros2::MessageType<sensor_msgs_msg_dds__CompressedImage_>::Descriptor(),
          &*image));
      EXPECT_STREQ(image->format, "jpeg");
      ASSERT_GT(image->data._length, 2U);
      EXPECT_EQ(image->data._buffer[0], 0xFF);  // a JPEG's SOI
      EXPECT_EQ(image->data._buffer[1], 0xD8);
      camera = true;
      break;
    }
  }
  EXPECT_TRUE(camera);
  // Ctrl-C, as a user would (the program itself, not popen's shell).
  const std::string interrupt =
      "pkill -INT -f '^" + std::string(PIROUETTE_BINARY) + " sim-serve .*--view 18745'";
  EXPECT_EQ(std::system(interrupt.c_str()), 0);  // NOLINT(cert-env33-c): a test's own command
  EXPECT_EQ(serve.get().exit_code, 0);
}

}  // namespace
}  // namespace pirouette::live_view_cli_test
