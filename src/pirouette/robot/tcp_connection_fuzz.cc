// Fuzzes the byte stream under the line protocol, as RemoteRobot reads a
// robot's replies: TcpConnection over a local socket pair (no port), the
// input sent by the peer, which then closes. Lines are read and parsed; a
// frame header's bytes are read when they are few. Reads never wait (the
// peer has sent all), so an input that makes the reader wait is a hang.

#include <fcntl.h>
#include <sys/socket.h>
#include <unistd.h>

#include <chrono>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "pirouette/robot/line_protocol.h"
#include "pirouette/robot/robot_error.h"
#include "pirouette/robot/tcp_connection.h"

namespace {

// Frames larger than this are not read (the fuzzer's inputs are small).
constexpr std::size_t kMaxFrameBytes = 1U << 16;

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using pirouette::robot::TcpConnection;
  int fds[2];
  if (::socketpair(AF_UNIX, SOCK_STREAM, 0, fds) != 0) std::abort();
  ::fcntl(fds[0], F_SETFL, ::fcntl(fds[0], F_GETFL) | O_NONBLOCK);
  std::size_t sent = 0;
  while (sent < size) {
    const ssize_t n = ::send(fds[1], data + sent, size - sent, 0);
    if (n <= 0) std::abort();
    sent += static_cast<std::size_t>(n);
  }
  ::close(fds[1]);
  TcpConnection connection(fds[0]);
  constexpr TcpConnection::Duration kNoWait{0};
  while (true) {
    const TcpConnection::Line line = connection.ReadLine(pirouette::robot::kMaxLineLength, kNoWait);
    if (line.status != TcpConnection::Status::kOk) break;
    if (line.text.size() > pirouette::robot::kMaxLineLength) std::abort();
    try {
      (void)pirouette::robot::ParseRequest(line.text);
    } catch (const pirouette::robot::RobotError&) {
    }
    try {
      const pirouette::robot::FrameHeader header = pirouette::robot::ParseFrameHeader(line.text);
      if (header.ByteCount() <= kMaxFrameBytes) {
        std::vector<std::uint8_t> bytes(header.ByteCount());
        if (connection.ReadExactly(bytes.data(), bytes.size(), kNoWait) !=
            TcpConnection::Status::kOk) {
          break;
        }
      }
    } catch (const pirouette::robot::RobotError&) {
    }
  }
  return 0;
}
