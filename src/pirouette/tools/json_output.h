#pragma once

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

#include "pirouette/core/obstacle_profile.h"

namespace pirouette::tools {

// How the commands' reports write numbers and text, in one place.

// `value` to `decimals` decimal places, as the nearest double, so that
// nlohmann (which prints the shortest text that reads back the same double)
// prints it short: RoundTo(0.123456, 4) prints 0.1235. The reports' figures
// are measurements whose further digits are noise; camera files are rounded
// the same way.
inline double RoundTo(double value, int decimals) {
  const double scale = std::pow(10.0, decimals);
  return std::round(value * scale) / scale;
}

// The JSON text of a report for standard output: one line (indent < 0) or
// indented by `indent` spaces, then a newline. Text that is not UTF-8 (a file
// name in another encoding) is written with U+FFFD in place of its bad bytes
// rather than refused.
inline std::string JsonText(const nlohmann::ordered_json& json, int indent) {
  return json.dump(indent, ' ', false, nlohmann::ordered_json::error_handler_t::replace) + "\n";
}

// A reading's kind as the reports name it: "hit", "clear" or "blind".
inline const char* ReadingKindName(core::ReadingKind kind) {
  switch (kind) {
    case core::ReadingKind::kHit:
      return "hit";
    case core::ReadingKind::kClear:
      return "clear";
    case core::ReadingKind::kBlind:
      break;
  }
  return "blind";
}

}  // namespace pirouette::tools
