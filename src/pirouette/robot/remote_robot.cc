#include "pirouette/robot/remote_robot.h"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <optional>
#include <system_error>
#include <utility>

#include "pirouette/core/input_error.h"
#include "pirouette/robot/robot_error.h"

namespace pirouette::robot {
namespace {

double Seconds(std::chrono::milliseconds d) { return std::chrono::duration<double>(d).count(); }

}  // namespace

std::string RobotAddress::ToString() const {
  return host.find(':') != std::string::npos ? fmt::format("[{}]:{}", host, port)
                                             : fmt::format("{}:{}", host, port);
}

RobotAddress ParseRobotUrl(std::string_view url, const std::string& option) {
  const auto bad = [&](std::string_view problem) {
    return core::InputError(option, 0, "",
                            fmt::format("expected tcp://HOST:PORT, got '{}' ({})", url, problem));
  };
  constexpr std::string_view kScheme = "tcp://";
  if (!url.starts_with(kScheme)) throw bad("it must start with tcp://");
  std::string_view rest = url.substr(kScheme.size());
  if (!rest.empty() && rest.back() == '/') rest.remove_suffix(1);
  RobotAddress address;
  std::string_view port;
  if (rest.starts_with('[')) {  // [IPv6]:PORT
    const std::size_t close = rest.find(']');
    if (close == std::string_view::npos || close + 1 >= rest.size() || rest[close + 1] != ':') {
      throw bad("an IPv6 address is written [ADDRESS]:PORT");
    }
    address.host = std::string(rest.substr(1, close - 1));
    port = rest.substr(close + 2);
  } else {
    const std::size_t colon = rest.rfind(':');
    if (colon == std::string_view::npos) throw bad("no port");
    address.host = std::string(rest.substr(0, colon));
    port = rest.substr(colon + 1);
    if (address.host.find(':') != std::string::npos) {
      throw bad("an IPv6 address is written [ADDRESS]:PORT");
    }
  }
  if (address.host.empty()) throw bad("no host");
  const char* last = port.data() + port.size();
  const auto [end, error] = std::from_chars(port.data(), last, address.port);
  if (port.empty() || error != std::errc() || end != last || address.port < 1 ||
      address.port > 65535) {
    throw bad("the port must be a number 1..65535");
  }
  return address;
}

template <typename Parse>
auto RemoteRobot::ParseReply(const Request& request, const std::string& line, Parse parse) {
  try {
    return parse(line);
  } catch (const RobotError& e) {
    Fail(fmt::format("answered {} with garbage: {}", CommandName(request.kind), e.what()));
  }
}

RemoteRobot::RemoteRobot(std::string_view url, const RemoteRobotOptions& options)
    : RemoteRobot(ParseRobotUrl(url), options) {}

RemoteRobot::RemoteRobot(const RobotAddress& address, const RemoteRobotOptions& options)
    : address_(address),
      options_(options),
      connection_(TcpConnection::Connect(address.host, address.port, options.connect_timeout)) {
  const Request hello = Request::Hello();
  ParseReply(hello, Ask(hello), ParseHelloReply);
  const Request odometry = Request::Odometry();
  odometry_ = ParseReply(odometry, Ask(odometry), ParseOdometryReply);
  CheckOdometry(odometry_, "ODOM");
}

core::MoveOutcome RemoteRobot::Execute(const core::Move& move) {
  const Request request = Request::FromMove(move);
  core::MoveOutcome outcome = ParseReply(
      request, Ask(request), [&move](std::string_view line) { return ParseMoveReply(line, move); });
  CheckOdometry(outcome.odometry, CommandName(request.kind));
  odometry_ = outcome.odometry;
  return outcome;
}

Frame RemoteRobot::Capture() {
  const Request request = Request::Capture();
  const FrameHeader header = ParseReply(request, Ask(request), ParseFrameHeader);
  // Checked before the bytes are read (or memory taken for them).
  if (header.width == 0 || header.height == 0) {
    Fail(fmt::format("answered CAPTURE with an empty {}x{} frame", header.width, header.height));
  }
  if (options_.frame_width > 0 &&
      (header.width != options_.frame_width || header.height != options_.frame_height)) {
    Fail(fmt::format("answered CAPTURE with a {}x{} frame; the camera file's frames are {}x{}",
                     header.width, header.height, options_.frame_width, options_.frame_height));
  }
  CheckOdometry(header.odometry, "CAPTURE");
  Frame frame;
  frame.image = core::ImageRgb8(header.width, header.height);
  frame.odometry = header.odometry;
  frame.time_s = header.time_s;
  const TcpConnection::Status status = connection_.ReadExactly(
      frame.image.data(), header.ByteCount(), options_.reply_timeout, deadline_);
  if (status == TcpConnection::Status::kTimedOut && TcpConnection::Clock::now() >= deadline_) {
    Fail(
        fmt::format("did not send the whole {}x{} frame answering CAPTURE within {} s (the "
                    "deadline of a request)",
                    header.width, header.height, Seconds(options_.request_timeout)));
  }
  if (status == TcpConnection::Status::kTimedOut) {
    Fail(fmt::format("stopped sending the {}x{} frame answering CAPTURE (nothing for {} s)",
                     header.width, header.height, Seconds(options_.reply_timeout)));
  }
  if (status != TcpConnection::Status::kOk) {
    Fail(
        fmt::format("dropped the connection in the middle of the {}x{} frame answering CAPTURE "
                    "({})",
                    header.width, header.height, connection_.error()));
  }
  odometry_ = frame.odometry;
  return frame;
}

std::string RemoteRobot::Ask(const Request& request) {
  const std::string line = FormatRequest(request);
  const std::string_view command = std::string_view(line).substr(0, line.size() - 1);
  if (!connection_.is_open()) {
    throw RobotError(
        fmt::format("the connection to the robot at {} was closed after an earlier "
                    "error; cannot send {}",
                    address_.ToString(), command));
  }
  deadline_ = TcpConnection::Clock::now() + options_.request_timeout;
  if (connection_.WriteAll(line, options_.reply_timeout) != TcpConnection::Status::kOk) {
    Fail(fmt::format("dropped the connection before {} could be sent ({})", command,
                     connection_.error()));
  }
  const TcpConnection::Line reply = connection_.ReadLine(
      kMaxLineLength,
      std::min(options_.reply_timeout, std::chrono::ceil<std::chrono::milliseconds>(
                                           deadline_ - TcpConnection::Clock::now())));
  switch (reply.status) {
    case TcpConnection::Status::kOk:
      break;
    case TcpConnection::Status::kTimedOut:
      Fail(fmt::format("did not answer {} within {} s", command, Seconds(options_.reply_timeout)));
    case TcpConnection::Status::kTooLong:
      Fail(fmt::format("answered {} with a line longer than {} bytes (not the protocol)", command,
                       kMaxLineLength));
    default:
      Fail(fmt::format("dropped the connection without answering {} ({})", command,
                       connection_.error()));
  }
  if (const std::optional<std::string> message = ErrorReplyMessage(reply.text)) {
    Fail(fmt::format("refused {}: {}", command, *message));
  }
  return reply.text;
}

void RemoteRobot::CheckOdometry(const core::Pose2& odometry, std::string_view command) {
  if (std::abs(odometry.x()) > options_.max_odometry_m ||
      std::abs(odometry.y()) > options_.max_odometry_m) {
    Fail(fmt::format("answered {} with odometry ({}, {}) m, farther than {} m from its origin",
                     command, odometry.x(), odometry.y(), options_.max_odometry_m));
  }
}

void RemoteRobot::Fail(const std::string& what) {
  connection_.Close();
  throw RobotError(fmt::format("the robot at {} {}", address_.ToString(), what));
}

}  // namespace pirouette::robot
