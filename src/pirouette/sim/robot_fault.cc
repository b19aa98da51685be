#include "pirouette/sim/robot_fault.h"

#include <array>
#include <charconv>
#include <utility>

#include "pirouette/core/input_error.h"

namespace pirouette::sim {
namespace {

using Kind = RobotFault::Kind;

constexpr std::array<std::pair<Kind, std::string_view>, 9> kNames = {{
    {Kind::kTeleport, "teleport"},
    {Kind::kFlip, "flip"},
    {Kind::kClockBack, "clock-back"},
    {Kind::kSameFrame, "same-frame"},
    {Kind::kLate, "late"},
    {Kind::kOutOfOrder, "out-of-order"},
    {Kind::kShortMoves, "short-moves"},
    {Kind::kStalled, "stalled"},
    {Kind::kHalfFrame, "half-frame"},
}};

}  // namespace

std::string_view RobotFaultName(Kind kind) {
  for (const auto& [k, name] : kNames) {
    if (k == kind) return name;
  }
  return "none";
}

std::string RobotFaultKinds() {
  std::string kinds;
  for (const auto& [k, name] : kNames) {
    if (!kinds.empty()) kinds += ", ";
    kinds += name;
  }
  return kinds;
}

RobotFault ParseRobotFault(std::string_view text, const std::string& option) {
  const std::size_t at = text.find('@');
  const std::string_view name = text.substr(0, at);
  RobotFault fault;
  for (const auto& [k, n] : kNames) {
    if (n == name) fault.kind = k;
  }
  if (fault.kind == Kind::kNone) {
    throw core::InputError(option, 0, "",
                           "expected KIND[@N], KIND one of " + RobotFaultKinds() + ", got '" +
                               std::string(text) + "'");
  }
  if (at != std::string_view::npos) {
    const std::string_view n = text.substr(at + 1);
    const auto [end, error] = std::from_chars(n.data(), n.data() + n.size(), fault.from);
    if (n.empty() || error != std::errc() || end != n.data() + n.size() || fault.from < 1) {
      throw core::InputError(
          option, 0, "",
          "the N of KIND@N must be a whole number ≥ 1, got '" + std::string(n) + "'");
    }
  }
  return fault;
}

}  // namespace pirouette::sim
