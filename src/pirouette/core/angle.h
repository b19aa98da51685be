#pragma once

#include <cmath>
#include <numbers>

namespace pirouette::core {

// Angles at the file and command-line edge are degrees (SPEC.md); inside the
// code they are radians.
constexpr double DegToRad(double degrees) { return degrees * std::numbers::pi / 180.0; }
constexpr double RadToDeg(double radians) { return radians * 180.0 / std::numbers::pi; }

// Returns the angle equal to `radians` modulo 2π in (-π, π].
inline double NormalizeAngle(double radians) {
  double a = std::remainder(radians, 2.0 * std::numbers::pi);
  if (a <= -std::numbers::pi) a += 2.0 * std::numbers::pi;
  return a;
}

}  // namespace pirouette::core
