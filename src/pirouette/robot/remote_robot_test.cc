#include "pirouette/robot/remote_robot.h"

#include <arpa/inet.h>
#include <fmt/format.h>
#include <gmock/gmock.h>
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <functional>
#include <thread>
#include <utility>

#include "pirouette/core/input_error.h"
#include "pirouette/robot/robot_error.h"
#include "pirouette/robot/robot_server.h"
#include "pirouette/robot/tcp_connection.h"
#include "pirouette/testing/fake_robot.h"
#include "pirouette/testing/serving.h"

namespace pirouette::robot {
namespace {

using ::testing::AllOf;
using ::testing::HasSubstr;
using namespace std::chrono_literals;  // NOLINT(google-build-using-namespace)

using testing::Serving;

// A misbehaving robot: listens on 127.0.0.1 (any free port), takes one
// client and runs `script` on the connection, on a thread.
class ScriptedServer {
 public:
  explicit ScriptedServer(std::function<void(TcpConnection&)> script) {
    listen_fd_ = ::socket(AF_INET, SOCK_STREAM, 0);
    sockaddr_in address{};
    address.sin_family = AF_INET;
    address.sin_addr.s_addr = htonl(INADDR_LOOPBACK);
    address.sin_port = 0;
    EXPECT_EQ(::bind(listen_fd_, reinterpret_cast<sockaddr*>(&address), sizeof address), 0);
    EXPECT_EQ(::listen(listen_fd_, 1), 0);
    socklen_t length = sizeof address;
    ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&address), &length);
    port_ = ntohs(address.sin_port);
    thread_ = std::thread([this, script = std::move(script)] {
      pollfd p{listen_fd_, POLLIN, 0};
      if (::poll(&p, 1, 5000) <= 0) return;
      const int fd = ::accept(listen_fd_, nullptr, nullptr);
      if (fd < 0) return;
      ConfigureSocket(fd);
      TcpConnection connection(fd);
      script(connection);
    });
  }
  ~ScriptedServer() {
    thread_.join();
    ::close(listen_fd_);
  }
  ScriptedServer(const ScriptedServer&) = delete;
  ScriptedServer& operator=(const ScriptedServer&) = delete;

  int port() const { return port_; }
  std::string url() const { return fmt::format("tcp://127.0.0.1:{}", port_); }

 private:
  int listen_fd_ = -1;
  int port_ = 0;
  std::thread thread_;
};

// Reads one request line; "" when the client has gone.
std::string Read(TcpConnection& connection) {
  const TcpConnection::Line line = connection.ReadLine(kMaxLineLength, 5000ms);
  return line.status == TcpConnection::Status::kOk ? line.text : "";
}

// Answers the greeting and the first ODOM as a good robot would.
void Greet(TcpConnection& connection) {
  EXPECT_EQ(Read(connection), "HELLO pirouette-robot/1");
  connection.WriteAll(FormatHelloReply(), 1000ms);
  EXPECT_EQ(Read(connection), "ODOM");
  connection.WriteAll(FormatOdometryReply(core::Pose2(1.0, 2.0, 0.5)), 1000ms);
}

// Waits until the client closes the connection.
void WaitForClose(TcpConnection& connection) {
  while (!Read(connection).empty()) {
  }
}

// The message of the RobotError that `call` throws; fails the test if none.
std::string ErrorOf(const std::function<void()>& call) {
  try {
    call();
  } catch (const RobotError& e) {
    return e.what();
  }
  ADD_FAILURE() << "no RobotError";
  return {};
}

void ExpectSamePose(const core::Pose2& actual, const core::Pose2& expected) {
  EXPECT_EQ(actual.x(), expected.x());
  EXPECT_EQ(actual.y(), expected.y());
  EXPECT_EQ(actual.heading(), expected.heading());
}

TEST(ParseRobotUrlTest, ReadsHostAndPort) {
  const RobotAddress a = ParseRobotUrl("tcp://127.0.0.1:5555");
  EXPECT_EQ(a.host, "127.0.0.1");
  EXPECT_EQ(a.port, 5555);
  EXPECT_EQ(a.ToString(), "127.0.0.1:5555");
  EXPECT_EQ(ParseRobotUrl("tcp://robot.local:80/").host, "robot.local");
  const RobotAddress v6 = ParseRobotUrl("tcp://[::1]:6000");
  EXPECT_EQ(v6.host, "::1");
  EXPECT_EQ(v6.ToString(), "[::1]:6000");
}

TEST(ParseRobotUrlTest, RefusesAnythingElseNamingTheOption) {
  for (const char* url : {"127.0.0.1:5555", "tcp://127.0.0.1", "tcp://:5555", "tcp://host:0",
                          "tcp://host:70000", "tcp://host:55a", "http://host:80", "tcp://::1:5"}) {
    EXPECT_THROW(ParseRobotUrl(url), core::InputError) << url;
  }
  try {
    ParseRobotUrl("udp://x:1");
    FAIL();
  } catch (const core::InputError& e) {
    EXPECT_THAT(e.what(), AllOf(HasSubstr("--robot"), HasSubstr("tcp://HOST:PORT")));
  }
}

TEST(RemoteRobotTest, DrivesARobotServerBitExactly) {
  testing::FakeRobot served(64, 48);
  testing::FakeRobot twin(64, 48);  // the same robot driven in-process
  served.contact_after_m = twin.contact_after_m = 0.4;
  RobotServerOptions options;
  options.port = 0;
  RobotServer server(served, options);
  const Serving serving(server);

  RemoteRobot remote(fmt::format("tcp://127.0.0.1:{}", server.port()));
  ExpectSamePose(remote.Odometry(), twin.Odometry());
  const std::vector<core::Move> moves = {core::Move::Turn(0.5236),
                                         core::Move::Straight(0.3),
                                         core::Move::Turn(-1.234567891),
                                         core::Move::Straight(-0.05),
                                         core::Move::Turn(0.5236),
                                         core::Move::Turn(0.5236),
                                         core::Move::Turn(0.5236),
                                         core::Move::Straight(2.0),
                                         core::Move::Turn(std::numbers::pi / 6),
                                         core::Move::Straight(1e-7),
                                         core::Move::Turn(-7.0),
                                         core::Move::Straight(0.1 + 0.2)};
  for (const core::Move& move : moves) {
    const core::MoveOutcome outcome = remote.Execute(move);
    const core::MoveOutcome expected = twin.Execute(move);
    EXPECT_EQ(outcome.requested.kind, move.kind);
    EXPECT_EQ(outcome.requested.amount, move.amount);
    EXPECT_EQ(outcome.achieved, expected.achieved);
    EXPECT_EQ(outcome.stopped_at_contact, expected.stopped_at_contact);
    ExpectSamePose(outcome.odometry, expected.odometry);
    ExpectSamePose(remote.Odometry(), twin.Odometry());

    const Frame frame = remote.Capture();
    const Frame expected_frame = twin.Capture();
    ASSERT_EQ(frame.image.width(), 64);
    ASSERT_EQ(frame.image.height(), 48);
    EXPECT_TRUE(std::equal(frame.image.data(), frame.image.data() + frame.image.size_bytes(),
                           expected_frame.image.data()));
    ExpectSamePose(frame.odometry, expected_frame.odometry);
    EXPECT_EQ(frame.time_s, expected_frame.time_s);
  }
  EXPECT_TRUE(twin.Execute(core::Move::Straight(2.0)).stopped_at_contact);
}

TEST(RemoteRobotTest, AnErrReplyIsARobotErrorAndLaterCallsFail) {
  testing::FakeRobot served(8, 8);
  served.fail_capture = true;
  RobotServerOptions options;
  options.port = 0;
  RobotServer server(served, options);
  const Serving serving(server);
  RemoteRobot remote(fmt::format("tcp://127.0.0.1:{}", server.port()));
  const std::string where = fmt::format("127.0.0.1:{}", server.port());
  EXPECT_THAT(
      ErrorOf([&] { remote.Capture(); }),
      AllOf(HasSubstr(where), HasSubstr("refused CAPTURE"), HasSubstr("the camera is unplugged")));
  EXPECT_THAT(ErrorOf([&] { remote.Execute(core::Move::Turn(1.0)); }),
              AllOf(HasSubstr(where), HasSubstr("closed after an earlier error")));
}

TEST(RemoteRobotTest, ARefusedConnectionNamesTheAddress) {
  int port = 0;
  {
    testing::FakeRobot unused(1, 1);
    RobotServerOptions options;
    options.port = 0;
    const RobotServer closed_again(unused, options);
    port = closed_again.port();
  }
  EXPECT_THAT(ErrorOf([&] { RemoteRobot(fmt::format("tcp://127.0.0.1:{}", port)); }),
              AllOf(HasSubstr(fmt::format("127.0.0.1:{}", port)), HasSubstr("refused")));
}

TEST(RemoteRobotTest, AConnectionDroppedInTheMiddleOfAFrameIsARobotError) {
  const ScriptedServer server([](TcpConnection& connection) {
    Greet(connection);
    EXPECT_EQ(Read(connection), "CAPTURE");
    connection.WriteAll("FRAME 4 4 1 2 3 0.5\n" + std::string(10, 'x'), 1000ms);
    connection.Close();
  });
  RemoteRobot remote(server.url());
  ExpectSamePose(remote.Odometry(), core::Pose2(1.0, 2.0, 0.5));
  EXPECT_THAT(ErrorOf([&] { remote.Capture(); }),
              AllOf(HasSubstr(fmt::format("127.0.0.1:{}", server.port())),
                    HasSubstr("dropped the connection in the middle of the 4x4 frame"),
                    HasSubstr("CAPTURE")));
}

TEST(RemoteRobotTest, AConnectionDroppedBeforeTheReplyIsARobotError) {
  const ScriptedServer server([](TcpConnection& connection) {
    Greet(connection);
    EXPECT_EQ(Read(connection), "TURN 90");
    connection.Close();
  });
  RemoteRobot remote(server.url());
  EXPECT_THAT(ErrorOf([&] { remote.Execute(core::Move::Turn(std::numbers::pi / 2)); }),
              HasSubstr("dropped the connection without answering TURN 90"));
}

TEST(RemoteRobotTest, GarbageIsARobotErrorThatQuotesIt) {
  const ScriptedServer server([](TcpConnection& connection) {
    Greet(connection);
    EXPECT_EQ(Read(connection), "MOVE 0.5");
    connection.WriteAll("OK forward march\n", 1000ms);
    WaitForClose(connection);
  });
  RemoteRobot remote(server.url());
  EXPECT_THAT(ErrorOf([&] { remote.Execute(core::Move::Straight(0.5)); }),
              AllOf(HasSubstr(fmt::format("127.0.0.1:{}", server.port())),
                    HasSubstr("answered MOVE with garbage"), HasSubstr("'OK forward march'")));
}

TEST(RemoteRobotTest, BinaryGarbageWithoutLineBreaksIsARobotError) {
  const ScriptedServer server([](TcpConnection& connection) {
    EXPECT_EQ(Read(connection), "HELLO pirouette-robot/1");
    connection.WriteAll(FormatHelloReply(), 1000ms);
    EXPECT_EQ(Read(connection), "ODOM");
    connection.WriteAll(std::string(5000, '\x7f'), 1000ms);
    WaitForClose(connection);
  });
  EXPECT_THAT(ErrorOf([&] { RemoteRobot{server.url()}; }),
              HasSubstr("answered ODOM with a line longer than 1024 bytes"));
}

TEST(RemoteRobotTest, ARobotThatNeverAnswersTimesOutWithAClearMessage) {
  const ScriptedServer server([](TcpConnection& connection) {
    Greet(connection);
    EXPECT_EQ(Read(connection), "CAPTURE");
    WaitForClose(connection);
  });
  RemoteRobotOptions options;
  options.reply_timeout = 200ms;
  RemoteRobot remote(server.url(), options);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THAT(ErrorOf([&] { remote.Capture(); }),
              HasSubstr(fmt::format("the robot at 127.0.0.1:{} did not answer CAPTURE within 0.2 s",
                                    server.port())));
  EXPECT_LT(std::chrono::steady_clock::now() - start, 2s);
}

// Half a frame, then the rest a byte at a time, never pausing as long as the
// reply timeout: the request's deadline cuts it off, naming the robot and
// the request.
TEST(RemoteRobotTest, AFrameTrickledByteByByteFailsWithinTheRequestDeadline) {
  const ScriptedServer server([](TcpConnection& connection) {
    Greet(connection);
    EXPECT_EQ(Read(connection), "CAPTURE");
    connection.WriteAll("FRAME 4 4 1 2 3 0.5\n" + std::string(24, 'x'), 1000ms);
    for (int i = 0; i < 24; ++i) {
      std::this_thread::sleep_for(100ms);
      if (connection.WriteAll("x", 1000ms) != TcpConnection::Status::kOk) return;
    }
  });
  RemoteRobotOptions options;
  options.reply_timeout = 300ms;
  options.request_timeout = 600ms;
  RemoteRobot remote(server.url(), options);
  const auto start = std::chrono::steady_clock::now();
  EXPECT_THAT(ErrorOf([&] { remote.Capture(); }),
              AllOf(HasSubstr(fmt::format("the robot at 127.0.0.1:{}", server.port())),
                    HasSubstr("did not send the whole 4x4 frame answering CAPTURE within 0.6 s")));
  EXPECT_LT(std::chrono::steady_clock::now() - start, 2s);
}

TEST(RemoteRobotTest, AServerOfAnotherProtocolIsRefusedAtConnection) {
  const ScriptedServer server([](TcpConnection& connection) {
    Read(connection);
    connection.WriteAll("HTTP/1.1 400 Bad Request\r\n\r\n", 1000ms);
    WaitForClose(connection);
  });
  EXPECT_THAT(ErrorOf([&] { RemoteRobot{server.url()}; }),
              AllOf(HasSubstr("answered HELLO with garbage"), HasSubstr("HTTP/1.1 400")));
}

TEST(RemoteRobotTest, ARobotOfAnotherVersionIsRefusedAtConnection) {
  const ScriptedServer server([](TcpConnection& connection) {
    Read(connection);
    connection.WriteAll("OK pirouette-robot/9\n", 1000ms);
    WaitForClose(connection);
  });
  EXPECT_THAT(ErrorOf([&] { RemoteRobot{server.url()}; }), HasSubstr("pirouette-robot/9"));
}

}  // namespace
}  // namespace pirouette::robot
