#include "pirouette/core/colour_class.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

namespace pirouette::core {
namespace {

TEST(ColourClassTest, IhlsOfPrimaries) {
  const Ihls red = ToIhls(core::Rgb{255, 0, 0});
  EXPECT_NEAR(red.luminance, 0.2125, 1e-9);
  EXPECT_NEAR(red.saturation, 1.0, 1e-9);
  EXPECT_NEAR(red.hue_rad, 0.0, 1e-9);
  EXPECT_NEAR(ToIhls(core::Rgb{0, 255, 0}).hue_rad, 2.0 * std::numbers::pi / 3.0, 1e-9);
  EXPECT_NEAR(ToIhls(core::Rgb{0, 0, 255}).hue_rad, 4.0 * std::numbers::pi / 3.0, 1e-9);
  const Ihls grey = ToIhls(core::Rgb{128, 128, 128});
  EXPECT_EQ(grey.saturation, 0.0);
  EXPECT_NEAR(grey.luminance, 128.0 / 255.0, 1e-9);
}

TEST(ColourClassTest, PureColoursFallInTheirHueClass) {
  EXPECT_EQ(ClassifyColour({255, 0, 0}), ColourClass::kHue0);
  EXPECT_EQ(ClassifyColour({255, 255, 0}), ColourClass::kHue2);
  EXPECT_EQ(ClassifyColour({0, 255, 0}), ColourClass::kHue4);
  EXPECT_EQ(ClassifyColour({0, 255, 255}), ColourClass::kHue6);
  EXPECT_EQ(ClassifyColour({0, 0, 255}), ColourClass::kHue8);
  EXPECT_EQ(ClassifyColour({255, 0, 255}), ColourClass::kHue10);
  // A red a little towards blue stays red (the classes are centred on 0°).
  EXPECT_EQ(ClassifyColour({255, 0, 20}), ColourClass::kHue0);
  // Shaded colours keep their class.
  EXPECT_EQ(ClassifyColour({100, 20, 20}), ColourClass::kHue0);
  EXPECT_EQ(ClassifyColour({20, 35, 80}), ColourClass::kHue8);
}

TEST(ColourClassTest, AchromaticColoursByLuminance) {
  EXPECT_EQ(ClassifyColour({0, 0, 0}), ColourClass::kBlack);
  EXPECT_EQ(ClassifyColour({10, 0, 0}), ColourClass::kBlack);  // too dark for a hue
  EXPECT_EQ(ClassifyColour({255, 255, 255}), ColourClass::kWhite);
  EXPECT_EQ(ClassifyColour({240, 235, 245}), ColourClass::kWhite);
  EXPECT_EQ(ClassifyColour({128, 128, 128}), ColourClass::kGrey);
  EXPECT_EQ(ClassifyColour({120, 130, 125}), ColourClass::kGrey);
}

TEST(ColourClassTest, CharsRoundTrip) {
  for (int i = 0; i <= kColourClasses; ++i) {
    const auto c = static_cast<ColourClass>(i);
    EXPECT_EQ(ColourClassFromChar(ColourClassChar(c)), c);
  }
  EXPECT_FALSE(ColourClassFromChar('z').has_value());
  EXPECT_EQ(ColourClassName(ColourClass::kHue8), "blue");
}

TEST(ColourClassTest, EachSwatchIsItsOwnClass) {
  for (int i = 0; i < kColourClasses; ++i) {
    const auto c = static_cast<ColourClass>(i);
    EXPECT_EQ(ClassifyColour(ColourClassSwatch(c)), c) << ColourClassName(c);
  }
  EXPECT_THROW(ColourClassSwatch(ColourClass::kNone), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::core
