#pragma once

#include <numbers>

namespace pirouette::testing {

// Shorthands for tests: π, and one degree in radians.
inline constexpr double kPi = std::numbers::pi;
inline constexpr double kDeg = kPi / 180.0;

}  // namespace pirouette::testing
