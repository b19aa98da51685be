#pragma once

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace pirouette::robot {

// One end of a TCP connection (POSIX sockets, non-blocking, TCP_NODELAY) with
// line reads that wait at most a given time: the transport under RemoteRobot
// and RobotServer. Move-only; closes the socket when destroyed.
//
// No call blocks longer than its timeout. A read that times out keeps what
// it received, so a reader can wait in short slices (to look at a stop flag
// between them) without losing a line.
class TcpConnection {
 public:
  using Duration = std::chrono::milliseconds;
  using Clock = std::chrono::steady_clock;

  // How a read or write ended.
  enum class Status {
    kOk,
    kTimedOut,  // nothing (more) arrived within the timeout
    kClosed,    // the peer closed or reset the connection; error() says how
    kTooLong,   // a line longer than the limit
  };

  struct Line {
    Status status = Status::kOk;
    std::string text;  // without its '\n'
  };

  TcpConnection() = default;
  // Takes ownership of a connected socket.
  explicit TcpConnection(int fd);
  ~TcpConnection();
  TcpConnection(TcpConnection&& other) noexcept;
  TcpConnection& operator=(TcpConnection&& other) noexcept;
  TcpConnection(const TcpConnection&) = delete;
  TcpConnection& operator=(const TcpConnection&) = delete;

  // Connects to host:port (a name or a numeric IPv4/IPv6 address) within
  // `timeout`; throws RobotError naming host:port and the cause (cannot
  // resolve, connection refused, timed out).
  static TcpConnection Connect(const std::string& host, int port, Duration timeout);

  bool is_open() const { return fd_ >= 0; }
  // True when something waits to be read: data, or the peer's close.
  bool HasInput();
  void Close();

  // Reads up to the next '\n'; fails with kTooLong past `max_length` bytes.
  // `timeout` bounds the whole wait.
  Line ReadLine(std::size_t max_length, Duration timeout);
  // Reads exactly `size` bytes into `out`; `timeout` bounds each wait for more
  // data (a slow but steady sender is not cut off).
  Status ReadExactly(std::uint8_t* out, std::size_t size, Duration timeout);
  // The same, and all of it by `deadline`: a sender that trickles the bytes,
  // never pausing as long as `timeout`, is cut off too (kTimedOut).
  Status ReadExactly(std::uint8_t* out, std::size_t size, Duration timeout,
                     Clock::time_point deadline);
  // Writes all of `bytes`; `timeout` bounds each wait for the peer to read.
  Status WriteAll(std::string_view bytes, Duration timeout);
  Status WriteAll(const std::uint8_t* bytes, std::size_t size, Duration timeout);

  // What closed the connection, for messages ("connection reset by peer").
  const std::string& error() const { return error_; }

 private:
  // Waits until the socket is readable (POLLIN) or writable (POLLOUT).
  Status Wait(short events, Duration timeout);
  // Reads what is there into buffer_.
  Status Fill();

  int fd_ = -1;
  std::string buffer_;  // received, not yet consumed
  std::string error_;
};

// Sets O_NONBLOCK and TCP_NODELAY on a socket (for accepted connections).
void ConfigureSocket(int fd);

}  // namespace pirouette::robot
