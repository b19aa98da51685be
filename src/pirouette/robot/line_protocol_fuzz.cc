// Fuzzes both directions of the line protocol (docs/robot-protocol.md): each
// line of the input, cut at kMaxLineLength as TcpConnection cuts it, goes to
// the server's request parser and to every one of the client's reply
// parsers. Only RobotError is the protocol's answer to garbage; a request that
// parses must format back to a line that parses to the same kind and amount.

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "pirouette/robot/line_protocol.h"
#include "pirouette/robot/robot_error.h"
#include "pirouette/testing/fuzz_input.h"

namespace pirouette::robot {
namespace {

void Check(bool condition) {
  if (!condition) std::abort();
}

void FuzzRequest(std::string_view line) {
  try {
    const Request request = ParseRequest(line);
    Check(request.kind != Request::Kind::kTurn || std::isfinite(request.amount));
    Check(request.kind != Request::Kind::kMove || std::isfinite(request.amount));
    std::string text = FormatRequest(request);
    Check(!text.empty() && text.back() == '\n');
    text.pop_back();
    const Request again = ParseRequest(text);
    // The amounts cross bit-exactly; a HELLO's version is only compared (a
    // version ending in '\r' loses it, and is refused as a version anyway).
    Check(again.kind == request.kind && again.amount == request.amount);
  } catch (const RobotError&) {
  }
}

void FuzzReplies(std::string_view line) {
  try {
    ParseHelloReply(line);
  } catch (const RobotError&) {
  }
  for (const core::Move& move : {core::Move::Turn(0.5), core::Move::Straight(-0.2)}) {
    try {
      const core::MoveOutcome outcome = ParseMoveReply(line, move);
      Check(std::isfinite(outcome.achieved));
    } catch (const RobotError&) {
    }
  }
  try {
    const FrameHeader header = ParseFrameHeader(line);
    Check(header.width >= 0 && header.width <= kMaxFrameSide);
    Check(header.height >= 0 && header.height <= kMaxFrameSide);
    Check(std::isfinite(header.time_s));
  } catch (const RobotError&) {
  }
  try {
    const core::Pose2 pose = ParseOdometryReply(line);
    Check(std::isfinite(pose.x()) && std::isfinite(pose.y()) && std::isfinite(pose.heading()));
  } catch (const RobotError&) {
  }
  if (const auto message = ErrorReplyMessage(line)) {
    Check(message->find('\n') == std::string::npos);
  }
  Check(Quote(line).size() <= 4 * 80 + 8);
}

}  // namespace
}  // namespace pirouette::robot

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string_view rest = pirouette::testing::FuzzText(data, size);
  while (!rest.empty()) {
    const std::size_t end = rest.find('\n');
    const std::string_view line = rest.substr(0, end);
    rest.remove_prefix(end == std::string_view::npos ? rest.size() : end + 1);
    if (line.size() > pirouette::robot::kMaxLineLength) continue;
    pirouette::robot::FuzzRequest(line);
    pirouette::robot::FuzzReplies(line);
  }
  return 0;
}
