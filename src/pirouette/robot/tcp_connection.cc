#include "pirouette/robot/tcp_connection.h"

#include <fcntl.h>
#include <fmt/format.h>
#include <netdb.h>
#include <netinet/in.h>
#include <netinet/tcp.h>
#include <poll.h>
#include <sys/socket.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cerrno>
#include <cstring>
#include <memory>
#include <utility>

#include "pirouette/robot/robot_error.h"

namespace pirouette::robot {
namespace {

using Clock = std::chrono::steady_clock;

std::string ErrnoText(int error) { return std::strerror(error); }

// Milliseconds left until `deadline`, for poll(), at most `cap`.
int MillisecondsLeft(Clock::time_point deadline, TcpConnection::Duration cap) {
  const auto left = std::chrono::duration_cast<TcpConnection::Duration>(deadline - Clock::now());
  return static_cast<int>(std::clamp(left, TcpConnection::Duration{0}, cap).count());
}

}  // namespace

void ConfigureSocket(int fd) {
  const int flags = ::fcntl(fd, F_GETFL, 0);
  ::fcntl(fd, F_SETFL, flags | O_NONBLOCK);
  const int one = 1;
  ::setsockopt(fd, IPPROTO_TCP, TCP_NODELAY, &one, sizeof one);
}

TcpConnection::TcpConnection(int fd) : fd_(fd) {}

TcpConnection::~TcpConnection() { Close(); }

TcpConnection::TcpConnection(TcpConnection&& other) noexcept
    : fd_(std::exchange(other.fd_, -1)),
      buffer_(std::move(other.buffer_)),
      error_(std::move(other.error_)) {}

TcpConnection& TcpConnection::operator=(TcpConnection&& other) noexcept {
  if (this != &other) {
    Close();
    fd_ = std::exchange(other.fd_, -1);
    buffer_ = std::move(other.buffer_);
    error_ = std::move(other.error_);
  }
  return *this;
}

void TcpConnection::Close() {
  if (fd_ >= 0) ::close(fd_);
  fd_ = -1;
  buffer_.clear();
}

TcpConnection TcpConnection::Connect(const std::string& host, int port, Duration timeout) {
  const std::string where = fmt::format("{}:{}", host, port);
  addrinfo hints{};
  hints.ai_family = AF_UNSPEC;
  hints.ai_socktype = SOCK_STREAM;
  addrinfo* found = nullptr;
  const std::string service = std::to_string(port);
  if (const int error = ::getaddrinfo(host.c_str(), service.c_str(), &hints, &found); error != 0) {
    throw RobotError(
        fmt::format("cannot connect to the robot at {}: {}", where, ::gai_strerror(error)));
  }
  const std::unique_ptr<addrinfo, decltype(&::freeaddrinfo)> addresses(found, &::freeaddrinfo);
  std::string failure = "no address";
  const Clock::time_point deadline = Clock::now() + timeout;
  for (const addrinfo* a = addresses.get(); a != nullptr; a = a->ai_next) {
    const int fd = ::socket(a->ai_family, a->ai_socktype, a->ai_protocol);
    if (fd < 0) {
      failure = ErrnoText(errno);
      continue;
    }
    TcpConnection connection(fd);
    ConfigureSocket(fd);
    if (::connect(fd, a->ai_addr, a->ai_addrlen) == 0) return connection;
    if (errno != EINPROGRESS) {
      failure = ErrnoText(errno);
      continue;
    }
    pollfd p{fd, POLLOUT, 0};
    int ready = 0;
    do {
      ready = ::poll(&p, 1, MillisecondsLeft(deadline, timeout));
    } while (ready < 0 && errno == EINTR);
    if (ready == 0) {
      failure =
          fmt::format("no answer within {} s", std::chrono::duration<double>(timeout).count());
      continue;
    }
    int error = 0;
    socklen_t length = sizeof error;
    if (ready < 0) {
      error = errno;
    } else {
      ::getsockopt(fd, SOL_SOCKET, SO_ERROR, &error, &length);
    }
    if (error == 0) return connection;
    failure = ErrnoText(error);
  }
  throw RobotError(
      fmt::format("cannot connect to the robot at {}: {} (is it serving?)", where, failure));
}

bool TcpConnection::HasInput() {
  if (!buffer_.empty()) return true;
  if (!is_open()) return false;
  pollfd p{fd_, POLLIN, 0};
  return ::poll(&p, 1, 0) > 0;
}

TcpConnection::Status TcpConnection::Wait(short events, Duration timeout) {
  const Clock::time_point deadline = Clock::now() + timeout;
  while (true) {
    pollfd p{fd_, events, 0};
    const int ready = ::poll(&p, 1, MillisecondsLeft(deadline, timeout));
    if (ready > 0) return Status::kOk;  // errors and hang-ups show in the recv/send that follows
    if (ready < 0 && errno != EINTR) {
      error_ = ErrnoText(errno);
      return Status::kClosed;
    }
    if (Clock::now() >= deadline) return Status::kTimedOut;
  }
}

TcpConnection::Status TcpConnection::Fill() {
  std::array<char, 65536> chunk{};
  while (true) {
    const ssize_t n = ::recv(fd_, chunk.data(), chunk.size(), 0);
    if (n > 0) {
      buffer_.append(chunk.data(), static_cast<std::size_t>(n));
      return Status::kOk;
    }
    if (n == 0) {
      error_ = "the connection was closed";
      return Status::kClosed;
    }
    if (errno == EINTR) continue;
    if (errno == EAGAIN || errno == EWOULDBLOCK) return Status::kOk;  // spurious wake-up
    error_ = ErrnoText(errno);
    return Status::kClosed;
  }
}

TcpConnection::Line TcpConnection::ReadLine(std::size_t max_length, Duration timeout) {
  if (!is_open()) return {Status::kClosed, {}};
  const Clock::time_point deadline = Clock::now() + timeout;
  std::size_t searched = 0;
  while (true) {
    const std::size_t end = buffer_.find('\n', searched);
    if (end != std::string::npos) {
      if (end > max_length) return {Status::kTooLong, {}};
      Line line{Status::kOk, buffer_.substr(0, end)};
      buffer_.erase(0, end + 1);
      return line;
    }
    if (buffer_.size() > max_length) return {Status::kTooLong, {}};
    searched = buffer_.size();
    const auto left = std::chrono::duration_cast<Duration>(deadline - Clock::now());
    if (const Status s = Wait(POLLIN, std::max(left, Duration{0})); s != Status::kOk) {
      return {s, {}};
    }
    if (const Status s = Fill(); s != Status::kOk) return {s, {}};
  }
}

TcpConnection::Status TcpConnection::ReadExactly(std::uint8_t* out, std::size_t size,
                                                 Duration timeout) {
  return ReadExactly(out, size, timeout, Clock::time_point::max());
}

TcpConnection::Status TcpConnection::ReadExactly(std::uint8_t* out, std::size_t size,
                                                 Duration timeout, Clock::time_point deadline) {
  if (!is_open()) return Status::kClosed;
  std::size_t done = std::min(size, buffer_.size());
  std::copy_n(buffer_.data(), done, out);
  buffer_.erase(0, done);
  while (done < size) {
    const Clock::time_point now = Clock::now();
    if (now >= deadline) return Status::kTimedOut;
    const Duration wait = std::min(timeout, std::chrono::ceil<Duration>(deadline - now));
    if (const Status s = Wait(POLLIN, wait); s != Status::kOk) return s;
    const ssize_t n = ::recv(fd_, out + done, size - done, 0);
    if (n > 0) {
      done += static_cast<std::size_t>(n);
    } else if (n == 0) {
      error_ = "the connection was closed";
      return Status::kClosed;
    } else if (errno != EINTR && errno != EAGAIN && errno != EWOULDBLOCK) {
      error_ = ErrnoText(errno);
      return Status::kClosed;
    }
  }
  return Status::kOk;
}

TcpConnection::Status TcpConnection::WriteAll(std::string_view bytes, Duration timeout) {
  return WriteAll(reinterpret_cast<const std::uint8_t*>(bytes.data()), bytes.size(), timeout);
}

TcpConnection::Status TcpConnection::WriteAll(const std::uint8_t* bytes, std::size_t size,
                                              Duration timeout) {
  if (!is_open()) return Status::kClosed;
  std::size_t done = 0;
  while (done < size) {
    // MSG_NOSIGNAL: a peer that went away is an error here, not a SIGPIPE.
    const ssize_t n = ::send(fd_, bytes + done, size - done, MSG_NOSIGNAL);
    if (n >= 0) {
      done += static_cast<std::size_t>(n);
    } else if (errno == EAGAIN || errno == EWOULDBLOCK) {
      if (const Status s = Wait(POLLOUT, timeout); s != Status::kOk) return s;
    } else if (errno != EINTR) {
      error_ = ErrnoText(errno);
      return Status::kClosed;
    }
  }
  return Status::kOk;
}

}  // namespace pirouette::robot
