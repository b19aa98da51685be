#include "pirouette/eval/place_observer.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "pirouette/camera/range_resolution.h"
#include "pirouette/core/angle.h"
#include "pirouette/core/input_error.h"
#include "pirouette/io/world_file.h"
#include "pirouette/run/explorer.h"

namespace pirouette::eval {
namespace {

std::string World(const std::string& name) {
  return std::string(PIROUETTE_WORLDS_DIR) + "/" + name + ".yaml";
}

TEST(PlaceObserverTest, ATurnedPirouetteFindsItsPlaceAndHeading) {
  const sim::World world = io::LoadWorldFile(World("soccer_field"));
  PlaceObserver observer(world, vision::MaskSource::kDefault, 0.6, 1);
  const localize::ObservedPlace a = observer.Observe(core::Pose2(0.3, 0.3, 0.0), 1);
  const localize::ObservedPlace b =
      observer.Observe(core::Pose2(0.3, 0.3, core::DegToRad(100.0)), 2);
  ASSERT_EQ(a.view.ranges_m.size(), 360u);
  ASSERT_EQ(a.view.colours.size(), 360u);
  ASSERT_EQ(a.kinds.size(), 360u);
  // Some bins hit something coloured (the field's walls or obstacles).
  int coloured = 0;
  for (core::ColourClass c : a.view.colours) coloured += c != core::ColourClass::kNone;
  EXPECT_GT(coloured, 30);
  for (bool use_colour : {false, true}) {
    const localize::Alignment al = localize::AlignProfiles(b.view, a.view, use_colour);
    EXPECT_LT(
        std::abs(core::RadToDeg(core::NormalizeAngle(al.heading_rad - core::DegToRad(100.0)))), 5.0)
        << use_colour;
  }
}

TEST(PlaceObserverTest, PirouettesAreReadNoFartherThanEveryColumnSeesTheFloor) {
  const sim::World world = io::LoadWorldFile(World("soccer_field"));
  const camera::CameraModel& camera = world.robot().camera;
  const double map_range = camera::MaxRange(camera, mapping::DefaultCellSize(world.robot().radius));
  EXPECT_DOUBLE_EQ(eval::PlaceMaxRange(world, 1.0), map_range);
  EXPECT_DOUBLE_EQ(eval::PlaceMaxRange(world, 2.0), 2.0 * map_range);  // 0.81 m
  // The paper's camera: its centre columns see the floor to 1.10 m at their
  // top row, short of 3 × 0.41 m.
  EXPECT_LT(camera::FloorSeenInEveryColumn(camera), 3.0 * map_range);
  EXPECT_DOUBLE_EQ(eval::PlaceMaxRange(world, 3.0), camera::FloorSeenInEveryColumn(camera));
  EXPECT_THROW(eval::PlaceMaxRange(world, 0.5), core::InputError);
}

}  // namespace
}  // namespace pirouette::eval
