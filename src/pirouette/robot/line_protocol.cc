#include "pirouette/robot/line_protocol.h"

#include <fmt/format.h>

#include <charconv>
#include <cmath>
#include <limits>
#include <numbers>
#include <string>
#include <system_error>
#include <vector>

#include "pirouette/robot/robot_error.h"

namespace pirouette::robot {
namespace {

constexpr long double kDegreesPerRadian = 180.0L / std::numbers::pi_v<long double>;
constexpr long double kRadiansPerDegree = std::numbers::pi_v<long double> / 180.0L;

constexpr std::string_view kMoveReplyForm = "OK <achieved> <x> <y> <heading_deg> <contact 0|1>";
constexpr std::string_view kFrameHeaderForm =
    "FRAME <width> <height> <x> <y> <heading_deg> <time_s>";
constexpr std::string_view kOdometryReplyForm = "OK <x> <y> <heading_deg>";

// The words of a line, split at spaces and tabs; a '\r' at its end is ignored.
std::vector<std::string_view> Words(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  std::vector<std::string_view> words;
  std::size_t i = 0;
  while (i < line.size()) {
    while (i < line.size() && (line[i] == ' ' || line[i] == '\t')) ++i;
    const std::size_t start = i;
    while (i < line.size() && line[i] != ' ' && line[i] != '\t') ++i;
    if (i > start) words.push_back(line.substr(start, i - start));
  }
  return words;
}

[[noreturn]] void Garbage(std::string_view expected, std::string_view line) {
  throw RobotError(fmt::format("expected '{}', got {}", expected, Quote(line)));
}

// `text` as a finite number, or nullopt. Accepts what Python's repr() and
// fmt's "{}" write, and a leading '+'.
template <typename Number>
std::optional<Number> ToNumber(std::string_view text) {
  if (!text.empty() && text.front() == '+') text.remove_prefix(1);
  // libstdc++ 12 reads a long double with strtold, which goes on to a NUL
  // past `last` (fuzz/regressions/line_protocol): parse a copy that ends in one.
  const std::string copy(text);
  Number value{};
  const char* last = copy.data() + copy.size();
  const auto [end, error] = std::from_chars(copy.data(), last, value);
  if (copy.empty() || error != std::errc() || end != last || !std::isfinite(value)) {
    return std::nullopt;
  }
  return value;
}

double Number(std::string_view text, std::string_view expected, std::string_view line) {
  const std::optional<double> value = ToNumber<double>(text);
  if (!value) Garbage(expected, line);
  return *value;
}

double Degrees(std::string_view text, std::string_view expected, std::string_view line) {
  const std::optional<long double> degrees = ToNumber<long double>(text);
  if (!degrees) Garbage(expected, line);
  // A long double reads numbers far beyond a double's range (1e4000): those
  // are not angles, and would turn into infinity.
  const long double radians = *degrees * kRadiansPerDegree;
  if (!(std::fabs(radians) <= std::numeric_limits<double>::max())) Garbage(expected, line);
  return static_cast<double>(radians);
}

// A number for the wire: the shortest decimal that reads back as `value`.
std::string Decimal(double value) {
  if (!std::isfinite(value)) throw RobotError(fmt::format("cannot send the number {}", value));
  return fmt::format("{}", value);
}

core::Pose2 Pose(std::string_view x, std::string_view y, std::string_view heading_deg,
                 std::string_view expected, std::string_view line) {
  return {Number(x, expected, line), Number(y, expected, line),
          Degrees(heading_deg, expected, line)};
}

std::string PoseWords(const core::Pose2& pose) {
  return fmt::format("{} {} {}", Decimal(pose.x()), Decimal(pose.y()),
                     FormatDegrees(pose.heading()));
}

int FrameSide(std::string_view text, std::string_view line) {
  int value = 0;
  const char* last = text.data() + text.size();
  const auto [end, error] = std::from_chars(text.data(), last, value);
  if (error != std::errc() || end != last || value < 0 || value > kMaxFrameSide) {
    throw RobotError(fmt::format("expected '{}' with sides 0..{}, got {}", kFrameHeaderForm,
                                 kMaxFrameSide, Quote(line)));
  }
  return value;
}

}  // namespace

std::string_view CommandName(Request::Kind kind) {
  switch (kind) {
    case Request::Kind::kHello:
      return "HELLO";
    case Request::Kind::kTurn:
      return "TURN";
    case Request::Kind::kMove:
      return "MOVE";
    case Request::Kind::kCapture:
      return "CAPTURE";
    case Request::Kind::kOdometry:
      return "ODOM";
  }
  return "?";
}

std::string FormatRequest(const Request& request) {
  switch (request.kind) {
    case Request::Kind::kHello:
      return fmt::format("HELLO {}\n", request.version);
    case Request::Kind::kTurn:
      return fmt::format("TURN {}\n", FormatDegrees(request.amount));
    case Request::Kind::kMove:
      return fmt::format("MOVE {}\n", Decimal(request.amount));
    case Request::Kind::kCapture:
    case Request::Kind::kOdometry:
      return fmt::format("{}\n", CommandName(request.kind));
  }
  return {};
}

Request ParseRequest(std::string_view line) {
  constexpr std::string_view kForms =
      "HELLO <version>', 'TURN <degrees>', 'MOVE <metres>', 'CAPTURE' or 'ODOM";
  const std::vector<std::string_view> words = Words(line);
  if (words.empty()) Garbage(kForms, line);
  const std::string_view command = words[0];
  if (command == "HELLO" && words.size() == 2) {
    return {Request::Kind::kHello, 0.0, std::string(words[1])};
  }
  if (command == "TURN" && words.size() == 2) {
    return {Request::Kind::kTurn, Degrees(words[1], "TURN <degrees>", line), {}};
  }
  if (command == "MOVE" && words.size() == 2) {
    return {Request::Kind::kMove, Number(words[1], "MOVE <metres>", line), {}};
  }
  if (command == "CAPTURE" && words.size() == 1) return Request::Capture();
  if (command == "ODOM" && words.size() == 1) return Request::Odometry();
  Garbage(kForms, line);
}

std::string FormatHelloReply() { return fmt::format("OK {}\n", kProtocolVersion); }

std::string FormatMoveReply(const core::MoveOutcome& outcome) {
  const std::string achieved = outcome.requested.kind == core::Move::Kind::kTurn
                                   ? FormatDegrees(outcome.achieved)
                                   : Decimal(outcome.achieved);
  return fmt::format("OK {} {} {}\n", achieved, PoseWords(outcome.odometry),
                     outcome.stopped_at_contact ? 1 : 0);
}

std::string FormatFrameHeader(const Frame& frame) {
  return fmt::format("FRAME {} {} {} {}\n", frame.image.width(), frame.image.height(),
                     PoseWords(frame.odometry), Decimal(frame.time_s));
}

std::string FormatOdometryReply(const core::Pose2& odom_T_robot) {
  return fmt::format("OK {}\n", PoseWords(odom_T_robot));
}

std::string FormatErrorReply(std::string_view message) {
  std::string text(message);
  for (char& c : text) {
    if (c == '\n' || c == '\r') c = ' ';
  }
  if (text.empty()) text = "refused";
  return fmt::format("ERR {}\n", text);
}

void ParseHelloReply(std::string_view line) {
  const std::vector<std::string_view> words = Words(line);
  if (words.size() != 2 || words[0] != "OK") Garbage(fmt::format("OK {}", kProtocolVersion), line);
  if (words[1] != kProtocolVersion) {
    throw RobotError(fmt::format("the robot speaks {}, not {}", Quote(words[1]), kProtocolVersion));
  }
}

core::MoveOutcome ParseMoveReply(std::string_view line, const core::Move& requested) {
  const std::vector<std::string_view> words = Words(line);
  if (words.size() != 6 || words[0] != "OK" || (words[5] != "0" && words[5] != "1")) {
    Garbage(kMoveReplyForm, line);
  }
  core::MoveOutcome outcome;
  outcome.requested = requested;
  outcome.achieved = requested.kind == core::Move::Kind::kTurn
                         ? Degrees(words[1], kMoveReplyForm, line)
                         : Number(words[1], kMoveReplyForm, line);
  outcome.odometry = Pose(words[2], words[3], words[4], kMoveReplyForm, line);
  outcome.stopped_at_contact = words[5] == "1";
  return outcome;
}

FrameHeader ParseFrameHeader(std::string_view line) {
  const std::vector<std::string_view> words = Words(line);
  if (words.size() != 7 || words[0] != "FRAME") Garbage(kFrameHeaderForm, line);
  FrameHeader header;
  header.width = FrameSide(words[1], line);
  header.height = FrameSide(words[2], line);
  if ((header.width == 0) != (header.height == 0)) Garbage(kFrameHeaderForm, line);
  header.odometry = Pose(words[3], words[4], words[5], kFrameHeaderForm, line);
  header.time_s = Number(words[6], kFrameHeaderForm, line);
  return header;
}

core::Pose2 ParseOdometryReply(std::string_view line) {
  const std::vector<std::string_view> words = Words(line);
  if (words.size() != 4 || words[0] != "OK") Garbage(kOdometryReplyForm, line);
  return Pose(words[1], words[2], words[3], kOdometryReplyForm, line);
}

std::optional<std::string> ErrorReplyMessage(std::string_view line) {
  if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
  if (line == "ERR") return std::string("(no message)");
  if (!line.starts_with("ERR ")) return std::nullopt;
  return std::string(line.substr(4));
}

// Tries ever more significant digits of the degrees, in long double, until
// one reads back as `radians`; 17 digits always do in practice (the long
// double carries 11 bits more than the double), 21 is the long double's own
// round-trip precision.
std::string FormatDegrees(double radians) {
  if (!std::isfinite(radians)) throw RobotError(fmt::format("cannot send the angle {}", radians));
  const long double degrees = static_cast<long double>(radians) * kDegreesPerRadian;
  std::string text;
  for (int digits = 6; digits <= 21; ++digits) {
    text = fmt::format("{:.{}g}", degrees, digits);
    if (ParseDegrees(text) == radians) return text;
  }
  return text;
}

double ParseDegrees(std::string_view text) { return Degrees(text, "<degrees>", text); }

std::string Quote(std::string_view text) {
  constexpr std::size_t kMaxShown = 80;
  std::string out = "'";
  for (std::size_t i = 0; i < text.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(text[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      out += fmt::format("\\x{:02x}", c);
    }
  }
  out += text.size() > kMaxShown ? "'..." : "'";
  return out;
}

}  // namespace pirouette::robot
