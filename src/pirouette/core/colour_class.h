#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

#include "pirouette/core/rgb.h"

namespace pirouette::core {

// A colour in the Improved HLS space (Hanbury & Serra 2002, "A 3D-polar
// coordinate colour representation suitable for image analysis"), the space
// the colour ROP of Taylor, Geva & Boles 2005 §5.1 plans to classify in.
// From r, g, b in [0, 1] (the sRGB values as given, not linearised):
//   Y = 0.2125 r + 0.7154 g + 0.0721 b          (luminance, [0, 1])
//   S = max(r, g, b) − min(r, g, b)             (saturation, [0, 1])
//   H = arccos((r − g/2 − b/2) / √(r² + g² + b² − rg − rb − gb)), 2π − H where b > g
// H is in [0, 2π), 0 at red, 2π/3 at green, 4π/3 at blue; 0 where S == 0.
struct Ihls {
  double luminance = 0.0;
  double saturation = 0.0;
  double hue_rad = 0.0;
};

// r, g, b in [0, 1].
Ihls ToIhls(double r, double g, double b);
Ihls ToIhls(core::Rgb rgb);

// The colour classes of the colour ROP (§5.1 of the paper): the hue
// quantised into 12 classes of 30° centred on 0°, 30°, …, 330° (kHue0 is
// red, kHue4 green, kHue8 blue), and black, white or grey where the
// saturation is too low for a hue to mean anything. kNone marks a bearing
// with no colour (nothing hit there: clear or blind).
enum class ColourClass : std::uint8_t {
  kHue0 = 0,
  kHue1,
  kHue2,
  kHue3,
  kHue4,
  kHue5,
  kHue6,
  kHue7,
  kHue8,
  kHue9,
  kHue10,
  kHue11,
  kBlack,
  kWhite,
  kGrey,
  kNone,
};

inline constexpr int kHueClasses = 12;
// The classes a colour can fall in (all but kNone).
inline constexpr int kColourClasses = 15;

// Below this saturation (S = max − min, of 1) a colour is achromatic: its
// hue is noise. Rendered and real obstacles under shading keep S well above
// it; the grey floor and white walls stay below.
inline constexpr double kAchromaticSaturation = 0.10;
// Achromatic colours darker than this luminance are black, brighter than
// kWhiteLuminance white, the rest grey.
inline constexpr double kBlackLuminance = 0.20;
inline constexpr double kWhiteLuminance = 0.75;
// Colours darker than this are black whatever their saturation: a dark
// colour's hue is unreliable (S ≤ max ≤ a few times Y).
inline constexpr double kDarkLuminance = 0.06;

ColourClass Classify(const Ihls& colour);
ColourClass ClassifyColour(core::Rgb rgb);

// One character a class, for files and messages: '0'…'9', 'a', 'b' for the
// hues, 'k' black, 'w' white, 'g' grey, '-' none.
char ColourClassChar(ColourClass colour);
// The inverse of ColourClassChar; nullopt for any other character.
std::optional<ColourClass> ColourClassFromChar(char c);

// A colour that stands for the class in a picture (colours.png): for hue k
// the fully saturated colour of hue 30k° at value 0.9, black (20, 20, 20),
// white (250, 250, 250), grey (128, 128, 128); ClassifyColour of each gives
// the class back. kNone has no swatch (std::invalid_argument).
core::Rgb ColourClassSwatch(ColourClass colour);

// "red", "orange", …, "black", "white", "grey", "none".
std::string_view ColourClassName(ColourClass colour);

}  // namespace pirouette::core
