#include "pirouette/localize/place_table.h"

#include <gtest/gtest.h>

#include <cmath>

#include "pirouette/core/angle.h"
#include "pirouette/mapping/radial_profile.h"
#include "pirouette/testing/test_places.h"

namespace pirouette::localize {
namespace {

using testing::Grid;
using testing::View;

TEST(PlaceTableTest, ARotatedQueryFindsItsPlaceAndHeading) {
  const PlaceTable table = Grid();
  const int truth = 9;
  const PlaceEntry& e = table.entries()[truth];
  for (double heading_deg : {0.0, 33.0, 147.0, -100.0}) {
    const PlaceView query = View(e.x_m, e.y_m, heading_deg);
    for (SignatureKind kind : {SignatureKind::kFourier, SignatureKind::kColour}) {
      const std::vector<PlaceMatch> best = table.Nearest(query, kind, 3);
      ASSERT_EQ(best.size(), 3u);
      EXPECT_EQ(best[0].entry, truth) << SignatureKindName(kind) << " " << heading_deg;
      ASSERT_TRUE(best[0].heading_rad.has_value());
      EXPECT_LT(std::abs(core::NormalizeAngle(*best[0].heading_rad - core::DegToRad(heading_deg))),
                core::DegToRad(1.0))
          << SignatureKindName(kind) << " " << heading_deg;
      EXPECT_LE(best[0].distance, best[1].distance);
    }
    EXPECT_EQ(table.Nearest(query, SignatureKind::kHu, 1)[0].entry, truth);
  }
  // The DCT only knows the place at the heading it was stored with.
  const std::vector<PlaceMatch> dct = table.Nearest(View(e.x_m, e.y_m, 0.0), SignatureKind::kDct);
  ASSERT_EQ(dct.size(), 1u);
  EXPECT_EQ(dct[0].entry, truth);
  EXPECT_NEAR(dct[0].distance, 0.0, 1e-12);
  EXPECT_FALSE(dct[0].heading_rad.has_value());
}

TEST(PlaceTableTest, APoseSearchGivesTheQueryPositionBetweenPlaces) {
  const PlaceTable table = Grid();
  const PlaceView query = View(1.0, 0.65, -60.0);  // between the grid's places
  const std::vector<PlaceMatch> best =
      table.Nearest(query, SignatureKind::kColour, 1, PoseSearch{0.25, 0.005});
  ASSERT_EQ(best.size(), 1u);
  ASSERT_TRUE(best[0].position_m.has_value());
  EXPECT_NEAR(best[0].position_m->x(), 1.0, 0.02);
  EXPECT_NEAR(best[0].position_m->y(), 0.65, 0.02);
  EXPECT_LT(std::abs(core::NormalizeAngle(*best[0].heading_rad - core::DegToRad(-60.0))),
            core::DegToRad(2.0));
  // The ranges alone cannot tell the pose from its mirror through the room's
  // centre (1.0, 0.7); the colour signature can.
  const std::vector<PlaceMatch> ranges =
      table.Nearest(query, SignatureKind::kFourier, 1, PoseSearch{0.25, 0.005});
  ASSERT_TRUE(ranges[0].position_m.has_value());
  const double off = std::min((*ranges[0].position_m - Eigen::Vector2d(1.0, 0.65)).norm(),
                              (*ranges[0].position_m - Eigen::Vector2d(1.0, 0.75)).norm());
  EXPECT_LT(off, 0.03);
}

}  // namespace
}  // namespace pirouette::localize
