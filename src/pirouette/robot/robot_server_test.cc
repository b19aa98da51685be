#include "pirouette/robot/robot_server.h"

#include <gmock/gmock.h>
#include <gtest/gtest.h>

#include <chrono>
#include <cstdint>
#include <mutex>
#include <thread>
#include <vector>

#include "pirouette/robot/robot_error.h"
#include "pirouette/robot/tcp_connection.h"
#include "pirouette/testing/fake_robot.h"
#include "pirouette/testing/serving.h"

namespace pirouette::robot {
namespace {

using ::testing::HasSubstr;
using ::testing::StartsWith;
using namespace std::chrono_literals;  // NOLINT(google-build-using-namespace)

RobotServerOptions AnyPort() {
  RobotServerOptions options;
  options.port = 0;
  return options;
}

// A raw client: sends lines, reads reply lines.
class Client {
 public:
  explicit Client(int port) : connection_(TcpConnection::Connect("127.0.0.1", port, 2000ms)) {}

  std::string Ask(const std::string& line) {
    EXPECT_EQ(connection_.WriteAll(line + "\n", 1000ms), TcpConnection::Status::kOk);
    return Reply();
  }
  std::string Reply() {
    const TcpConnection::Line line = connection_.ReadLine(kMaxLineLength, 2000ms);
    return line.status == TcpConnection::Status::kOk ? line.text : "<no reply>";
  }
  TcpConnection& connection() { return connection_; }

 private:
  TcpConnection connection_;
};

using testing::Serving;

TEST(RobotServerTest, ReportsThePortItPicked) {
  testing::FakeRobot robot(2, 2);
  const RobotServer server(robot, AnyPort());
  EXPECT_GT(server.port(), 0);
  EXPECT_EQ(server.address(), "127.0.0.1:" + std::to_string(server.port()));
}

TEST(RobotServerTest, APortInUseIsARobotErrorThatSaysSo) {
  testing::FakeRobot robot(2, 2);
  const RobotServer first(robot, AnyPort());
  RobotServerOptions same;
  same.port = first.port();
  try {
    const RobotServer second(robot, same);
    FAIL();
  } catch (const RobotError& e) {
    EXPECT_THAT(e.what(), HasSubstr(first.address()));
    EXPECT_THAT(e.what(), HasSubstr("in use"));
  }
}

TEST(RobotServerTest, AnswersEveryRequest) {
  testing::FakeRobot robot(4, 2);
  RobotServer server(robot, AnyPort());
  const Serving serving(server);
  Client client(server.port());
  EXPECT_EQ(client.Ask("HELLO pirouette-robot/1"), "OK pirouette-robot/1");
  EXPECT_EQ(client.Ask("ODOM"), "OK 0.2 0.2 45");
  EXPECT_EQ(client.Ask("TURN 45"), "OK 45 0.2 0.2 90 0");
  EXPECT_THAT(client.Ask("MOVE 0.5"), StartsWith("OK 0.5 0.2"));
  EXPECT_THAT(client.Ask("CAPTURE"), StartsWith("FRAME 4 2 0.2"));
  std::vector<std::uint8_t> bytes(std::size_t{4} * 2 * 3);
  EXPECT_EQ(client.connection().ReadExactly(bytes.data(), bytes.size(), 1000ms),
            TcpConnection::Status::kOk);
  EXPECT_EQ(bytes[0], 0);
  EXPECT_EQ(bytes[1], 7);
}

TEST(RobotServerTest, AMalformedRequestIsAnsweredWithErrAndServingGoesOn) {
  testing::FakeRobot robot(2, 2);
  RobotServer server(robot, AnyPort());
  const Serving serving(server);
  Client client(server.port());
  EXPECT_THAT(client.Ask("JUMP 3"), StartsWith("ERR expected"));
  EXPECT_THAT(client.Ask("TURN left"), StartsWith("ERR "));
  EXPECT_THAT(client.Ask("HELLO pirouette-robot/7"), HasSubstr("ERR this robot speaks"));
  EXPECT_EQ(client.Ask("ODOM"), "OK 0.2 0.2 45");
}

TEST(RobotServerTest, ARobotThatThrowsIsAnsweredWithErr) {
  testing::FakeRobot robot(2, 2);
  robot.fail_capture = true;
  RobotServer server(robot, AnyPort());
  const Serving serving(server);
  Client client(server.port());
  EXPECT_EQ(client.Ask("CAPTURE"), "ERR CAPTURE failed: the camera is unplugged");
  EXPECT_EQ(client.Ask("ODOM"), "OK 0.2 0.2 45");
}

TEST(RobotServerTest, ServesOneClientAtATimeAndTheNextAfterIt) {
  testing::FakeRobot robot(2, 2);
  std::mutex mutex;
  std::vector<std::string> log;
  RobotServerOptions options = AnyPort();
  options.log = [&](const std::string& line) {
    const std::lock_guard lock(mutex);
    log.push_back(line);
  };
  RobotServer server(robot, options);
  const Serving serving(server);
  {
    Client first(server.port());
    EXPECT_EQ(first.Ask("TURN 45"), "OK 45 0.2 0.2 90 0");
    Client second(server.port());
    EXPECT_THAT(second.Reply(), StartsWith("ERR busy"));
    EXPECT_EQ(first.Ask("ODOM"), "OK 0.2 0.2 90");
  }
  Client third(server.port());  // the first left: the robot is free again
  EXPECT_EQ(third.Ask("ODOM"), "OK 0.2 0.2 90");
  const std::lock_guard lock(mutex);
  EXPECT_GE(log.size(), 3U);
}

// The fault for testing: half a frame's bytes, then nothing, however long
// the client waits; the server still stops at once and serves the next.
TEST(RobotServerTest, HalfFrameFromSendsHalfAFrameAndHangs) {
  testing::FakeRobot robot(4, 4);
  RobotServerOptions options = AnyPort();
  options.half_frame_from = 2;
  RobotServer server(robot, options);
  const Serving serving(server);
  {
    Client client(server.port());
    EXPECT_EQ(client.Ask("TURN 45"), "OK 45 0.2 0.2 90 0");
    EXPECT_THAT(client.Ask("CAPTURE"), StartsWith("FRAME 4 4 "));
    std::vector<std::uint8_t> bytes(48);
    EXPECT_EQ(client.connection().ReadExactly(bytes.data(), 24, 1000ms),
              TcpConnection::Status::kOk);
    EXPECT_EQ(client.connection().ReadExactly(bytes.data(), 1, 300ms),
              TcpConnection::Status::kTimedOut);
    EXPECT_EQ(client.Ask("ODOM"), "<no reply>");
  }
  Client next(server.port());
  EXPECT_EQ(next.Ask("ODOM"), "OK 0.2 0.2 90");
}

TEST(RobotServerTest, AnOverlongLineClosesTheClientButNotTheServer) {
  testing::FakeRobot robot(2, 2);
  RobotServer server(robot, AnyPort());
  const Serving serving(server);
  {
    Client client(server.port());
    EXPECT_THAT(client.Ask(std::string(3000, 'A')), StartsWith("ERR a line longer"));
  }
  Client next(server.port());
  EXPECT_EQ(next.Ask("ODOM"), "OK 0.2 0.2 45");
}

TEST(RobotServerTest, StopEndsServePromptlyEvenWithAClientConnected) {
  testing::FakeRobot robot(2, 2);
  RobotServer server(robot, AnyPort());
  std::thread thread([&server] { server.Serve(); });
  Client client(server.port());
  EXPECT_EQ(client.Ask("ODOM"), "OK 0.2 0.2 45");
  const auto start = std::chrono::steady_clock::now();
  server.Stop();
  thread.join();
  EXPECT_LT(std::chrono::steady_clock::now() - start, 1s);
}

TEST(RobotServerTest, AnExternalStopFlagEndsServe) {
  testing::FakeRobot robot(2, 2);
  std::atomic<bool> stop{false};
  RobotServerOptions options = AnyPort();
  options.stop_requested = &stop;
  RobotServer server(robot, options);
  std::thread thread([&server] { server.Serve(); });
  std::this_thread::sleep_for(100ms);
  stop.store(true);
  thread.join();
  SUCCEED();
}

}  // namespace
}  // namespace pirouette::robot
