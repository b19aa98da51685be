#include "pirouette/robot/robot_server.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <netdb.h>
#include <netinet/in.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <array>
#include <cerrno>
#include <cstring>
#include <exception>
#include <memory>
#include <utility>

#include "pirouette/robot/robot_error.h"

namespace pirouette::robot {
namespace {

// "HOST:PORT" of a socket address, numeric.
std::string Describe(const sockaddr* address, socklen_t length) {
  std::array<char, NI_MAXHOST> host{};
  std::array<char, NI_MAXSERV> port{};
  if (::getnameinfo(address, length, host.data(), host.size(), port.data(), port.size(),
                    NI_NUMERICHOST | NI_NUMERICSERV) != 0) {
    return "?";
  }
  return fmt::format("{}:{}", host.data(), port.data());
}

}  // namespace

RobotServer::RobotServer(Robot& robot, RobotServerOptions options)
    : robot_(robot), options_(std::move(options)) {
  const std::string where = fmt::format("{}:{}", options_.host, options_.port);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  hints.ai_flags = AI_PASSIVE;
  addrinfo* found = nullptr;
  const std::string service = std::to_string(options_.port);
  if (const int error = ::getaddrinfo(options_.host.c_str(), service.c_str(), &hints, &found);
      error != 0) {
    throw RobotError(fmt::format("cannot listen on {}: {}", where, ::gai_strerror(error)));
  }
  const std::unique_ptr<addrinfo, decltype(&::freeaddrinfo)> addresses(found, &::freeaddrinfo);
  const addrinfo& a = *addresses;
  listen_fd_ = ::socket(a.ai_family, a.ai_socktype, a.ai_protocol);
  if (listen_fd_ < 0) {
    throw RobotError(fmt::format("cannot listen on {}: {}", where, std::strerror(errno)));
  }
  const int one = 1;
  ::setsockopt(listen_fd_, SOL_SOCKET, SO_REUSEADDR, &one, sizeof one);
  if (::bind(listen_fd_, a.ai_addr, a.ai_addrlen) != 0 || ::listen(listen_fd_, 4) != 0) {
    const int error = errno;
    ::close(listen_fd_);
    listen_fd_ = -1;
    throw RobotError(
        error == EADDRINUSE
            ? fmt::format("cannot listen on {}: the port is in use (another server running? "
                          "pick another port, or 0 for any free one)",
                          where)
            : fmt::format("cannot listen on {}: {}", where, std::strerror(error)));
  }
  ::fcntl(listen_fd_, F_SETFL, ::fcntl(listen_fd_, F_GETFL, 0) | O_NONBLOCK);
  sockaddr_storage bound{};
  socklen_t length = sizeof bound;
  ::getsockname(listen_fd_, reinterpret_cast<sockaddr*>(&bound), &length);
  port_ = bound.ss_family == AF_INET6
              ? ntohs(reinterpret_cast<const sockaddr_in6*>(&bound)->sin6_port)
              : ntohs(reinterpret_cast<const sockaddr_in*>(&bound)->sin_port);
}

RobotServer::~RobotServer() {
  if (listen_fd_ >= 0) ::close(listen_fd_);
}

std::string RobotServer::address() const {
  return options_.host.find(':') != std::string::npos ? fmt::format("[{}]:{}", options_.host, port_)
                                                      : fmt::format("{}:{}", options_.host, port_);
}

bool RobotServer::Stopping() const {
  return stop_.load() || (options_.stop_requested != nullptr && options_.stop_requested->load());
}

void RobotServer::Log(const std::string& message) const {
  if (options_.log) options_.log(message);
}

void RobotServer::Serve() {
  while (!Stopping()) {
    pollfd p{listen_fd_, POLLIN, 0};
    if (::poll(&p, 1, static_cast<int>(kStopPollInterval.count())) <= 0) continue;
    sockaddr_storage peer{};
    socklen_t length = sizeof peer;
    const int fd = ::accept(listen_fd_, reinterpret_cast<sockaddr*>(&peer), &length);
    if (fd < 0) continue;  // gone before it was accepted, or interrupted
    ConfigureSocket(fd);
    ServeClient(TcpConnection(fd), Describe(reinterpret_cast<const sockaddr*>(&peer), length));
  }
}

void RobotServer::RefuseWaitingClients() {
  while (true) {
    const int fd = ::accept(listen_fd_, nullptr, nullptr);
    if (fd < 0) return;
    ConfigureSocket(fd);
    TcpConnection refused(fd);
    refused.WriteAll(FormatErrorReply("busy: another client is driving this robot"),
                     kStopPollInterval);
    Log("refused a second client: busy");
  }
}

void RobotServer::ServeClient(TcpConnection client, const std::string& peer) {
  Log(fmt::format("client {} connected", peer));
  requests_ = 0;
  hanging_ = false;
  while (!Stopping()) {
    // A client that has just left must not make its successor look like a
    // second client: read its close first.
    if (!client.HasInput()) RefuseWaitingClients();
    const TcpConnection::Line line = client.ReadLine(kMaxLineLength, kStopPollInterval);
    if (line.status == TcpConnection::Status::kTimedOut) continue;
    if (line.status == TcpConnection::Status::kTooLong) {
      client.WriteAll(
          FormatErrorReply(fmt::format("a line longer than {} bytes; closing", kMaxLineLength)),
          options_.write_timeout);
      Log(fmt::format("client {} sent a line longer than {} bytes; closed", peer, kMaxLineLength));
      return;
    }
    if (line.status != TcpConnection::Status::kOk) {
      Log(fmt::format("client {} left ({})", peer, client.error()));
      return;
    }
    if (!Answer(client, line.text)) {
      Log(fmt::format("client {} stopped reading ({}); closed", peer, client.error()));
      return;
    }
    if (hanging_) {
      Hang(client, peer);
      return;
    }
  }
}

void RobotServer::Hang(TcpConnection& client, const std::string& peer) {
  Log(fmt::format("sent client {} half a frame (a fault for testing); hanging", peer));
  while (!Stopping()) {
    if (!client.HasInput()) RefuseWaitingClients();
    const TcpConnection::Line line = client.ReadLine(kMaxLineLength, kStopPollInterval);
    if (line.status == TcpConnection::Status::kClosed ||
        line.status == TcpConnection::Status::kTooLong) {
      break;
    }
  }
  Log(fmt::format("client {} left", peer));
}

bool RobotServer::Answer(TcpConnection& client, const std::string& line) {
  const auto send = [&](std::string_view text) {
    return client.WriteAll(text, options_.write_timeout) == TcpConnection::Status::kOk;
  };
  Request request;
  try {
    request = ParseRequest(line);
  } catch (const RobotError& e) {
    return send(FormatErrorReply(e.what()));
  }
  if (request.kind == Request::Kind::kTurn || request.kind == Request::Kind::kMove ||
      request.kind == Request::Kind::kCapture) {
    ++requests_;
  }
  std::string reply;
  Frame frame;
  try {
    switch (request.kind) {
      case Request::Kind::kHello:
        reply = request.version == kProtocolVersion
                    ? FormatHelloReply()
                    : FormatErrorReply(fmt::format("this robot speaks {}, not {}", kProtocolVersion,
                                                   request.version));
        break;
      case Request::Kind::kTurn:
        reply = FormatMoveReply(robot_.Execute(core::Move::Turn(request.amount)));
        break;
      case Request::Kind::kMove:
        reply = FormatMoveReply(robot_.Execute(core::Move::Straight(request.amount)));
        break;
      case Request::Kind::kCapture:
        frame = robot_.Capture();
        reply = FormatFrameHeader(frame);
        break;
      case Request::Kind::kOdometry:
        reply = FormatOdometryReply(robot_.Odometry());
        break;
    }
  } catch (const std::exception& e) {
    return send(
        FormatErrorReply(fmt::format("{} failed: {}", CommandName(request.kind), e.what())));
  }
  if (!send(reply)) return false;
  std::size_t bytes = frame.image.size_bytes();
  if (options_.half_frame_from > 0 && requests_ >= options_.half_frame_from && bytes > 0) {
    bytes /= 2;
    hanging_ = true;
  }
  return bytes == 0 || client.WriteAll(frame.image.data(), bytes, options_.write_timeout) ==
                           TcpConnection::Status::kOk;
}

}  // namespace pirouette::robot
