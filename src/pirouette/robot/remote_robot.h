#pragma once

#include <chrono>
#include <string>
#include <string_view>

#include "pirouette/robot/line_protocol.h"
#include "pirouette/robot/robot.h"
#include "pirouette/robot/tcp_connection.h"

namespace pirouette::robot {

// Where a robot serves the line protocol.
struct RobotAddress {
  std::string host;  // a name, an IPv4 address, or an IPv6 address (written [::1] in a URL)
  int port = 0;      // 1..65535

  // "HOST:PORT", for messages.
  std::string ToString() const;
};

// Parses "tcp://HOST:PORT". Throws core::InputError naming `option` (the
// command-line option it came from, e.g. "--robot") for anything else.
RobotAddress ParseRobotUrl(std::string_view url, const std::string& option = "--robot");

struct RemoteRobotOptions {
  // How long a reply may take to start, and the longest pause while a
  // frame's bytes arrive. A move that takes the robot longer must be
  // answered within it too.
  std::chrono::milliseconds reply_timeout{30000};
  // How long a whole request may take, from sending it to the last byte of
  // its reply (a frame's too): a robot that answers half a frame and then
  // trickles the rest, never pausing as long as reply_timeout, is cut off by
  // this.
  std::chrono::milliseconds request_timeout{60000};
  // How long connecting may take.
  std::chrono::milliseconds connect_timeout{10000};
  // The size frames must have (the camera file's); 0: any size but empty.
  int frame_width = 0;
  int frame_height = 0;
  // Odometry farther than this from its origin (metres) is not a robot's.
  double max_odometry_m = 1e4;
};

// A robot driven over TCP with the line protocol (line_protocol.h,
// docs/robot-protocol.md): each call sends one request and waits for its
// reply. The constructor connects, greets the robot (HELLO) and reads its
// odometry (ODOM), so Odometry() is known from the start; afterwards it is the
// odometry of the last reply, without asking the robot.
//
// Every failure throws RobotError with a message naming HOST:PORT and the
// request: the connection refused, no reply within the timeout, a reply not
// whole within the request's deadline, the
// connection dropped (also in the middle of a frame), a reply that is not
// the protocol, or an ERR reply. After a failure the connection is closed
// (its state is unknown) and every later call throws too.
class RemoteRobot : public Robot {
 public:
  explicit RemoteRobot(const RobotAddress& address, const RemoteRobotOptions& options = {});
  // `url` is "tcp://HOST:PORT"; a malformed one throws core::InputError.
  explicit RemoteRobot(std::string_view url, const RemoteRobotOptions& options = {});

  // Angles of moves are radians (as everywhere inside the code); the wire
  // carries degrees.
  core::MoveOutcome Execute(const core::Move& move) override;
  Frame Capture() override;
  core::Pose2 Odometry() const override { return odometry_; }

  const RobotAddress& address() const { return address_; }

 private:
  // Sends the request and returns its reply line (an ERR reply throws).
  std::string Ask(const Request& request);
  // Closes the connection and throws RobotError "the robot at HOST:PORT <what>".
  [[noreturn]] void Fail(const std::string& what);
  // Fails for odometry too far from its origin to be a robot's.
  void CheckOdometry(const core::Pose2& odometry, std::string_view command);
  // Parses a reply with `parse`, turning its errors into Fail.
  template <typename Parse>
  auto ParseReply(const Request& request, const std::string& line, Parse parse);

  RobotAddress address_;
  RemoteRobotOptions options_;
  TcpConnection connection_;
  core::Pose2 odometry_;
  // The end of the request under way (set by Ask).
  TcpConnection::Clock::time_point deadline_;
};

}  // namespace pirouette::robot
