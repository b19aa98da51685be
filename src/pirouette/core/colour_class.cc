#include "pirouette/core/colour_class.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace pirouette::core {

Ihls ToIhls(double r, double g, double b) {
  Ihls out;
  out.luminance = 0.2125 * r + 0.7154 * g + 0.0721 * b;
  out.saturation = std::max({r, g, b}) - std::min({r, g, b});
  const double d = r * r + g * g + b * b - r * g - r * b - g * b;
  if (out.saturation <= 0.0 || d <= 0.0) return out;
  const double c = std::clamp((r - 0.5 * g - 0.5 * b) / std::sqrt(d), -1.0, 1.0);
  const double h = std::acos(c);
  out.hue_rad = b > g ? 2.0 * std::numbers::pi - h : h;
  return out;
}

Ihls ToIhls(core::Rgb rgb) { return ToIhls(rgb.r / 255.0, rgb.g / 255.0, rgb.b / 255.0); }

ColourClass Classify(const Ihls& colour) {
  if (colour.luminance < kDarkLuminance) return ColourClass::kBlack;
  if (colour.saturation < kAchromaticSaturation) {
    if (colour.luminance < kBlackLuminance) return ColourClass::kBlack;
    if (colour.luminance > kWhiteLuminance) return ColourClass::kWhite;
    return ColourClass::kGrey;
  }
  const double sector = 2.0 * std::numbers::pi / kHueClasses;
  const int hue = static_cast<int>(std::floor(colour.hue_rad / sector + 0.5)) % kHueClasses;
  return static_cast<ColourClass>(hue);
}

ColourClass ClassifyColour(core::Rgb rgb) { return Classify(ToIhls(rgb)); }

namespace {
constexpr std::array<char, kColourClasses + 1> kChars = {'0', '1', '2', '3', '4', '5', '6', '7',
                                                         '8', '9', 'a', 'b', 'k', 'w', 'g', '-'};
constexpr std::array<std::string_view, kColourClasses + 1> kNames = {
    "red",  "orange", "yellow",  "lime", "green", "spring", "cyan", "azure",
    "blue", "violet", "magenta", "rose", "black", "white",  "grey", "none"};
}  // namespace

char ColourClassChar(ColourClass colour) { return kChars[static_cast<std::size_t>(colour)]; }

std::optional<ColourClass> ColourClassFromChar(char c) {
  for (std::size_t i = 0; i < kChars.size(); ++i) {
    if (kChars[i] == c) return static_cast<ColourClass>(i);
  }
  return std::nullopt;
}

core::Rgb ColourClassSwatch(ColourClass colour) {
  switch (colour) {
    case ColourClass::kBlack:
      return {20, 20, 20};
    case ColourClass::kWhite:
      return {250, 250, 250};
    case ColourClass::kGrey:
      return {128, 128, 128};
    case ColourClass::kNone:
      throw std::invalid_argument("ColourClassSwatch: kNone has no colour");
    default:
      break;
  }
  // HSV to RGB at S = 1, V = 0.9: the IHLS hue of such a colour is its HSV
  // hue at every multiple of 30°.
  const double hue_deg = 30.0 * static_cast<int>(colour);
  const double v = 0.9 * 255.0;
  const double sector = hue_deg / 60.0;
  const int i = static_cast<int>(std::floor(sector)) % 6;
  const double f = sector - std::floor(sector);
  const auto q = static_cast<std::uint8_t>(std::lround(v * (1.0 - f)));
  const auto t = static_cast<std::uint8_t>(std::lround(v * f));
  const auto m = static_cast<std::uint8_t>(std::lround(v));
  switch (i) {
    case 0:
      return {m, t, 0};
    case 1:
      return {q, m, 0};
    case 2:
      return {0, m, t};
    case 3:
      return {0, q, m};
    case 4:
      return {t, 0, m};
    default:
      return {m, 0, q};
  }
}

std::string_view ColourClassName(ColourClass colour) {
  return kNames[static_cast<std::size_t>(colour)];
}

}  // namespace pirouette::core
