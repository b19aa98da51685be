#pragma once

#include <array>
#include <cstdint>

namespace pirouette::core {

// An sRGB colour, 0–255 a channel, as the world and camera files give it.
struct Rgb {
  std::uint8_t r = 0;
  std::uint8_t g = 0;
  std::uint8_t b = 0;

  friend bool operator==(const Rgb&, const Rgb&) = default;
};

}  // namespace pirouette::core
