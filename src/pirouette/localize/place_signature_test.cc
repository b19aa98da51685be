#include "pirouette/localize/place_signature.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "pirouette/core/angle.h"
#include "pirouette/mapping/radial_profile.h"
#include "pirouette/testing/test_places.h"

namespace pirouette::localize {
namespace {

constexpr int kBins = mapping::kRadialProfileBins;

// The ROP of a robot at (px, py) in a w × h rectangular room, heading
// `heading_deg`, with a coloured block on one wall: bin b looks at bearing
// heading + b + 0.5 degrees.
PlaceView RoomView(double px, double py, double heading_deg, double w = 1.5, double h = 1.0) {
  PlaceView view;
  for (int b = 0; b < kBins; ++b) {
    const double a = core::DegToRad(heading_deg + b + 0.5);
    const double c = std::cos(a), s = std::sin(a);
    const double t = testing::WallRange(px, py, a, w, h);
    const double range = std::min(t, 1.2);
    view.ranges_m.push_back(range);
    const double hx = px + t * c;
    const double hy = py + t * s;
    // A red stretch of the top wall, x in [0.2, 0.6]; the rest is white.
    core::ColourClass colour = core::ColourClass::kWhite;
    if (t > 1.2) {
      colour = core::ColourClass::kNone;
    } else if (std::abs(hy - h) < 1e-6 && hx > 0.2 && hx < 0.6) {
      colour = core::ColourClass::kHue0;
    }
    view.colours.push_back(colour);
  }
  return view;
}

PlaceView Shifted(const PlaceView& view, int bins) {
  PlaceView out = view;
  for (int b = 0; b < kBins; ++b) {
    out.ranges_m[b] = view.ranges_m[(b + bins) % kBins];
    out.colours[b] = view.colours[(b + bins) % kBins];
  }
  return out;
}

double AngleError(double a, double b) { return std::abs(core::NormalizeAngle(a - b)); }

TEST(PlaceSignatureTest, DctIsIdenticalOnIdenticalProfilesAndChangesWithHeading) {
  const PlaceView view = RoomView(0.4, 0.3, 0.0);
  const std::vector<double> a = DctSignature(view.ranges_m);
  ASSERT_EQ(a.size(), 20u);
  EXPECT_EQ(SignatureDistance(a, DctSignature(view.ranges_m)), 0.0);
  EXPECT_GT(SignatureDistance(a, DctSignature(Shifted(view, 90).ranges_m)), 0.01);
}

TEST(PlaceSignatureTest, HuMomentsOfADiscAndASquare) {
  // A disc of any radius: h1 = 1/(2π), the others 0.
  const std::vector<double> disc(kBins, 0.7);
  const auto hu = RawHuMoments(disc);
  EXPECT_NEAR(hu[0], 1.0 / (2.0 * std::numbers::pi), 1e-4);
  for (int i = 1; i < 7; ++i) EXPECT_NEAR(hu[i], 0.0, 1e-8) << i;
  // A square seen from its centre: h1 = 1/6.
  const PlaceView square = RoomView(0.5, 0.5, 0.0, 1.0, 1.0);
  EXPECT_NEAR(RawHuMoments(square.ranges_m)[0], 1.0 / 6.0, 1e-3);
}

TEST(PlaceSignatureTest, HuMomentsAreInvariantUnderRotation) {
  const PlaceView view = RoomView(0.4, 0.3, 0.0);
  const HuSignature a = HuMoments(view.ranges_m);
  for (int shift : {1, 37, 90, 200}) {
    EXPECT_LT(HuDistance(a, HuMoments(Shifted(view, shift).ranges_m)), 1e-6) << shift;
  }
  EXPECT_GT(HuDistance(a, HuMoments(RoomView(0.2, 0.5, 0.0).ranges_m)), 0.01);
}

TEST(PlaceSignatureTest, FourierSignatureIsHeadingInvariantAndAlignmentFindsTheHeading) {
  const PlaceView view = RoomView(0.4, 0.3, 0.0);
  const std::vector<double> a = FourierSignature(view.ranges_m);
  ASSERT_EQ(a.size(), 20u);
  for (int shift : {1, 45, 123, 300}) {
    const PlaceView turned = Shifted(view, shift);
    EXPECT_LT(SignatureDistance(a, FourierSignature(turned.ranges_m)), 1e-9) << shift;
    const Alignment al = AlignProfiles(turned, view, false);
    EXPECT_LT(AngleError(al.heading_rad, core::DegToRad(shift)), core::DegToRad(0.5)) << shift;
    EXPECT_NEAR(al.cost, 0.0, 1e-12);
  }
  EXPECT_GT(SignatureDistance(a, FourierSignature(RoomView(1.0, 0.7, 0.0).ranges_m)), 0.01);
}

TEST(PlaceSignatureTest, AlignmentRefinesBelowABin) {
  const PlaceView view = RoomView(0.4, 0.3, 0.0);
  const PlaceView turned = RoomView(0.4, 0.3, 57.4);  // the robot turned 57.4°
  const Alignment al = AlignProfiles(turned, view, false);
  EXPECT_LT(AngleError(al.heading_rad, core::DegToRad(57.4)), core::DegToRad(0.5));
}

TEST(PlaceSignatureTest, ColourTellsASymmetricRoomsHalvesApart) {
  // From the centre of a rectangle the ranges repeat every 180°: ranges alone
  // cannot tell heading h from h + 180°. The red stretch on one wall can.
  const PlaceView view = RoomView(0.75, 0.5, 0.0);
  const PlaceView turned = Shifted(view, 200);
  const ColourSignature a = MakeColourSignature(view);
  EXPECT_LT(ColourSignatureDistance(a, MakeColourSignature(turned)), 1e-9);
  const Alignment al = AlignProfiles(turned, view, true);
  EXPECT_LT(AngleError(al.heading_rad, core::DegToRad(200)), core::DegToRad(0.5));
  const Alignment ranges_only = AlignProfiles(turned, view, false);
  // Both 200° and 20° fit the ranges exactly.
  EXPECT_NEAR(ranges_only.cost, 0.0, 1e-12);
  // Turned by 20°, the ranges fit at 20° and at 200° alike; the colours only at 20°.
  const PlaceView other = Shifted(view, 20);
  EXPECT_LT(AngleError(AlignProfiles(other, view, true).heading_rad, core::DegToRad(20)),
            core::DegToRad(0.5));
  PlaceView uncoloured = view;
  uncoloured.colours.clear();
  EXPECT_NEAR(AlignProfiles(other, uncoloured, true).cost, 0.0, 1e-12);  // ranges only
}

TEST(PlaceSignatureTest, ReprojectingToTheSameOriginKeepsTheView) {
  const PlaceView view = RoomView(0.4, 0.3, 0.0, 1.0, 0.8);  // every wall within 1.2 m
  const PlaceView same = Reproject(view, Eigen::Vector2d::Zero(), 1.2);
  for (int b = 0; b < kBins; ++b) {
    EXPECT_NEAR(same.ranges_m[b], view.ranges_m[b], 1e-9) << b;
    EXPECT_EQ(same.colours[b], view.colours[b]) << b;
  }
}

TEST(PlaceSignatureTest, AlignPoseFindsTheOffsetAndHeadingOfANearbyPirouette) {
  // The reference pirouette at (0.5, 0.35) facing 0; the query 7 cm away,
  // turned by 130°. Plain alignment is biased by the parallax; AlignPose
  // finds the offset and the heading.
  const PlaceView reference = RoomView(0.5, 0.35, 0.0);
  const PlaceView query = RoomView(0.44, 0.315, 130.0);
  const PoseAlignment pose = AlignPose(query, reference, 1.2, 0.12, 0.005, true);
  EXPECT_NEAR(pose.position_m.x(), -0.06, 0.015);
  EXPECT_NEAR(pose.position_m.y(), -0.035, 0.015);
  EXPECT_LT(AngleError(pose.heading_rad, core::DegToRad(130.0)), core::DegToRad(2.0));
}

TEST(PlaceSignatureTest, ColourHistogramCountsTheBearings) {
  const ColourSignature s = MakeColourSignature(RoomView(0.75, 0.5, 0.0));
  double total = 0.0;
  for (double h : s.histogram) total += h;
  EXPECT_NEAR(total, 1.0, 1e-9);  // every bearing hits a wall within 1.2 m
  EXPECT_GT(s.histogram[static_cast<int>(core::ColourClass::kHue0)], 0.0);
}

}  // namespace
}  // namespace pirouette::localize
