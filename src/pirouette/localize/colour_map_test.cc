#include "pirouette/localize/colour_map.h"

#include <gtest/gtest.h>

namespace pirouette::localize {
namespace {

const core::GridGeometry kGeometry(0.1, Eigen::Vector2d::Zero(), 10, 10);

TEST(ColourMapTest, EachCellTakesTheColourMostSightingsNear) {
  // Three red sightings in cell (2, 2), one blue in (3, 2): (2, 2) and the
  // cells round it are red; (4, 2), beyond red's reach, is blue.
  std::vector<ColourSighting> s = {{{0.25, 0.25}, core::ColourClass::kHue0},
                                   {{0.21, 0.29}, core::ColourClass::kHue0},
                                   {{0.24, 0.22}, core::ColourClass::kHue0},
                                   {{0.35, 0.25}, core::ColourClass::kHue8}};
  const ColourMap map = ColourMap::FromSightings(kGeometry, s);
  EXPECT_EQ(map.At({2, 2}), core::ColourClass::kHue0);
  EXPECT_EQ(map.At({3, 2}), core::ColourClass::kHue0);  // 3 red neighbours against 2 blue votes
  EXPECT_EQ(map.At({1, 1}), core::ColourClass::kHue0);
  EXPECT_EQ(map.At({4, 2}), core::ColourClass::kHue8);
  EXPECT_EQ(map.At({5, 2}), core::ColourClass::kNone);
  EXPECT_EQ(map.At({7, 7}), core::ColourClass::kNone);
}

TEST(ColourMapTest, OffTheMapIsNone) {
  const ColourMap map = ColourMap::FromSightings(
      kGeometry,
      {{{5.0, 5.0}, core::ColourClass::kWhite}, {{0.05, 0.05}, core::ColourClass::kWhite}});
  EXPECT_EQ(map.At({0, 0}), core::ColourClass::kWhite);
  EXPECT_EQ(map.At({-1, 0}), core::ColourClass::kNone);
  EXPECT_EQ(map.At({10, 10}), core::ColourClass::kNone);
  EXPECT_EQ(ColourMap().At({0, 0}), core::ColourClass::kNone);
  EXPECT_TRUE(ColourMap().empty());
}

TEST(ColourMapTest, RefusesCellsThatDoNotFitTheGeometry) {
  EXPECT_THROW(ColourMap(kGeometry, std::vector<core::ColourClass>(3, core::ColourClass::kNone)),
               std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::localize
