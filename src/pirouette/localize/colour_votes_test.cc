#include "pirouette/localize/colour_votes.h"

#include <gtest/gtest.h>

namespace pirouette::localize {
namespace {

const core::GridGeometry kVotesGeometry(0.1, Eigen::Vector2d::Zero(), 10, 10);

TEST(ColourVotesTest, CountsAsTheMapOfAllSightingsAtOnce) {
  const std::vector<ColourSighting> s = {
      {{0.25, 0.25}, core::ColourClass::kHue0}, {{0.35, 0.25}, core::ColourClass::kHue8},
      {{0.45, 0.25}, core::ColourClass::kHue8}, {{0.95, 0.95}, core::ColourClass::kWhite},
      {{2.0, 0.5}, core::ColourClass::kWhite},  {{0.55, 0.55}, core::ColourClass::kNone}};
  ColourVotes votes(kVotesGeometry);
  for (const ColourSighting& x : s) votes.Add(x);
  EXPECT_EQ(votes.Map().cells(), ColourMap::FromSightings(kVotesGeometry, s).cells());
  EXPECT_EQ(votes.Map().At({3, 2}), core::ColourClass::kHue8);
  EXPECT_EQ(votes.Map().At({9, 9}), core::ColourClass::kWhite);
  EXPECT_EQ(votes.Map().At({5, 5}), core::ColourClass::kNone);
}

TEST(ColourVotesTest, ACountStopsAtItsLargestValueWithoutWrappingRound) {
  // 40,000 sightings of one class in a cell (80,000 votes, past 65,535) still
  // beat one of another: a wrapped count would have lost.
  ColourVotes votes(kVotesGeometry);
  for (int i = 0; i < 40000; ++i) votes.Add({{0.55, 0.55}, core::ColourClass::kHue3});
  votes.Add({{0.55, 0.55}, core::ColourClass::kHue1});
  EXPECT_EQ(votes.Map().At({5, 5}), core::ColourClass::kHue3);
}

TEST(ColourMapOnTest, ACropKeepsEachCellsClass) {
  const ColourMap map = ColourMap::FromSightings(
      kVotesGeometry,
      {{{0.25, 0.25}, core::ColourClass::kHue0}, {{0.75, 0.75}, core::ColourClass::kHue5}});
  // Cells (1..6, 1..6) of the map, and one column past its right edge.
  const core::GridGeometry crop(0.1, Eigen::Vector2d(0.1, 0.1), 6, 6);
  const ColourMap cropped = map.On(crop);
  for (int y = 0; y < 6; ++y) {
    for (int x = 0; x < 6; ++x) {
      EXPECT_EQ(cropped.At({x, y}), map.At({x + 1, y + 1})) << x << "," << y;
    }
  }
  const ColourMap wider = map.On(core::GridGeometry(0.1, Eigen::Vector2d(0.5, 0.0), 6, 1));
  EXPECT_EQ(wider.At({5, 0}), core::ColourClass::kNone);  // x = 1.05 m: off the map
}

}  // namespace
}  // namespace pirouette::localize
