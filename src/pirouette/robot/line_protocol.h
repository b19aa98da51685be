#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

#include "pirouette/core/pose2.h"
#include "pirouette/robot/robot.h"

namespace pirouette::robot {

// The line protocol that drives a robot over TCP (docs/robot-protocol.md is
// its reference; keep the two in step). Every message is one line of ASCII
// ending in '\n' (a '\r' before it is ignored), words separated by spaces;
// the client sends a request and the robot answers it before the next one:
//
//   HELLO pirouette-robot/1   →  OK pirouette-robot/1
//   TURN <degrees>            →  OK <achieved_deg> <x> <y> <heading_deg> <contact 0|1>
//   MOVE <metres>             →  OK <achieved_m> <x> <y> <heading_deg> <contact 0|1>
//   CAPTURE                   →  FRAME <width> <height> <x> <y> <heading_deg> <time_s>
//                                followed by width·height·3 bytes of RGB8
//   ODOM                      →  OK <x> <y> <heading_deg>
//   (any refused request)     →  ERR <message>
//
// Lengths are metres, angles degrees counter-clockwise, x/y/heading the
// odometry odom_T_robot after the request. Inside the code angles are
// radians: the conversion happens here and nowhere else (FormatDegrees,
// ParseDegrees). Numbers are written so that they read back bit-exactly.
//
// This file is pure: it formats and parses text, and knows nothing of
// sockets. Parsers throw RobotError for anything that is not the protocol,
// with a message that quotes what was received.

// The greeting's version; a new version is a new string.
inline constexpr std::string_view kProtocolVersion = "pirouette-robot/1";
// Longest line either side accepts, '\n' excluded.
inline constexpr std::size_t kMaxLineLength = 1024;
// Largest frame side a client accepts, pixels; guards against a garbage
// header asking for gigabytes.
inline constexpr int kMaxFrameSide = 16384;

struct Request {
  enum class Kind { kHello, kTurn, kMove, kCapture, kOdometry };

  Kind kind = Kind::kOdometry;
  // kTurn: radians, counter-clockwise positive; kMove: metres, negative
  // backwards; unused otherwise.
  double amount = 0.0;
  // kHello: the version the client speaks.
  std::string version;

  static Request Hello() { return {Kind::kHello, 0.0, std::string(kProtocolVersion)}; }
  static Request Capture() { return {Kind::kCapture, 0.0, {}}; }
  static Request Odometry() { return {Kind::kOdometry, 0.0, {}}; }
  static Request FromMove(const core::Move& move) {
    return {move.kind == core::Move::Kind::kTurn ? Kind::kTurn : Kind::kMove, move.amount, {}};
  }
};

// The request's command word: "HELLO", "TURN", "MOVE", "CAPTURE", "ODOM".
std::string_view CommandName(Request::Kind kind);

// One request line, '\n' included. Throws RobotError for a non-finite amount.
std::string FormatRequest(const Request& request);
// Parses a request line ('\n' excluded).
Request ParseRequest(std::string_view line);

// The header line of a CAPTURE reply; the image's bytes follow it.
struct FrameHeader {
  int width = 0;
  int height = 0;
  core::Pose2 odometry;
  double time_s = 0.0;

  // width·height·3: the bytes that follow the header.
  std::size_t ByteCount() const { return static_cast<std::size_t>(width) * height * 3; }
};

// Replies, each one line with its '\n'.
std::string FormatHelloReply();
std::string FormatMoveReply(const core::MoveOutcome& outcome);
std::string FormatFrameHeader(const Frame& frame);
std::string FormatOdometryReply(const core::Pose2& odom_T_robot);
// "ERR <message>", the message on one line (line breaks become spaces).
std::string FormatErrorReply(std::string_view message);

// Parsers of the replies (line without its '\n'). ParseMoveReply fills in
// `requested` and reads `achieved` in its unit (radians for a turn).
void ParseHelloReply(std::string_view line);
core::MoveOutcome ParseMoveReply(std::string_view line, const core::Move& requested);
FrameHeader ParseFrameHeader(std::string_view line);
core::Pose2 ParseOdometryReply(std::string_view line);
// The message of an "ERR <message>" line; nullopt for any other line.
std::optional<std::string> ErrorReplyMessage(std::string_view line);

// An angle in radians as the shortest decimal number of degrees that
// ParseDegrees turns back into exactly the same double, so that odometry and
// turns cross the wire bit-exactly (30° written by a script reads as the
// double nearest π/6; π/6 as a double is written 29.999999999999997).
// The conversion is carried in long double (64-bit significand on x86-64).
std::string FormatDegrees(double radians);
// A decimal number of degrees in radians; throws RobotError if `text` is not
// a finite number.
double ParseDegrees(std::string_view text);

// `text` quoted for an error message: at most 80 characters, bytes outside
// printable ASCII as \xNN.
std::string Quote(std::string_view text);

}  // namespace pirouette::robot
