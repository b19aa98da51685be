#pragma once

// For the tests of world files and generated worlds: two worlds compared
// value for value, exactly (a world written and read back must be the same
// doubles, not nearly).

#include <gtest/gtest.h>

#include <cstddef>
#include <string>

#include "pirouette/sim/world.h"

namespace pirouette::testing {

inline ::testing::AssertionResult SameCamera(const camera::CameraModel& a,
                                             const camera::CameraModel& b) {
  const auto& ia = a.intrinsics();
  const auto& ib = b.intrinsics();
  const auto& da = a.distortion();
  const auto& db = b.distortion();
  const bool same =
      a.name() == b.name() && a.width() == b.width() && a.height() == b.height() &&
      ia.fx == ib.fx && ia.fy == ib.fy && ia.cx == ib.cx && ia.cy == ib.cy && da == db &&
      a.mount().height_m == b.mount().height_m && a.mount().tilt_rad == b.mount().tilt_rad &&
      a.mount().forward_m == b.mount().forward_m && a.vignetting().k == b.vignetting().k;
  if (same) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << "the cameras " << a.name() << " and " << b.name() << " differ";
}

inline ::testing::AssertionResult SameSolid(const sim::Solid& a, const sim::Solid& b) {
  if (a.kind != b.kind) return ::testing::AssertionFailure() << "another kind of solid";
  if (a.footprint.size() != b.footprint.size()) {
    return ::testing::AssertionFailure()
           << "footprints of " << a.footprint.size() << " and " << b.footprint.size() << " points";
  }
  for (std::size_t i = 0; i < a.footprint.size(); ++i) {
    if (a.footprint[i] != b.footprint[i]) {
      return ::testing::AssertionFailure()
             << "footprint point " << i << ": (" << a.footprint[i].transpose() << ") vs ("
             << b.footprint[i].transpose() << ")";
    }
  }
  if (a.circle.has_value() != b.circle.has_value() ||
      (a.circle &&
       (a.circle->centre != b.circle->centre || a.circle->radius != b.circle->radius))) {
    return ::testing::AssertionFailure() << "another circle";
  }
  if (a.height != b.height || !(a.colour == b.colour)) {
    return ::testing::AssertionFailure() << "another height or colour";
  }
  return ::testing::AssertionSuccess();
}

inline ::testing::AssertionResult SameWorld(const sim::World& a, const sim::World& b) {
  const auto fail = [](const std::string& what) {
    return ::testing::AssertionFailure() << what << " differ";
  };
  if (a.name() != b.name()) return fail("the names");
  if (a.floor().size != b.floor().size || !(a.floor().colour == b.floor().colour) ||
      a.floor().texture != b.floor().texture) {
    return fail("the floors");
  }
  if (a.walls().has_value() != b.walls().has_value() ||
      (a.walls() &&
       (a.walls()->height != b.walls()->height || a.walls()->thickness != b.walls()->thickness ||
        !(a.walls()->colour == b.walls()->colour)))) {
    return fail("the walls");
  }
  if (a.solids().size() != b.solids().size()) return fail("the numbers of solids");
  for (std::size_t i = 0; i < a.solids().size(); ++i) {
    const auto same = SameSolid(a.solids()[i], b.solids()[i]);
    if (!same) return ::testing::AssertionFailure() << "solid " << i << ": " << same.message();
  }
  if (a.light().ambient != b.light().ambient || a.light().direction != b.light().direction ||
      a.light().intensity != b.light().intensity) {
    return fail("the lights");
  }
  const sim::RobotSpec& ra = a.robot();
  const sim::RobotSpec& rb = b.robot();
  if (ra.start.translation() != rb.start.translation() ||
      ra.start.heading() != rb.start.heading() || ra.radius != rb.radius) {
    return fail("the robots' starts or radii");
  }
  if (ra.odometry_noise.translation != rb.odometry_noise.translation ||
      ra.odometry_noise.rotation != rb.odometry_noise.rotation ||
      ra.odometry_noise.translation_bias != rb.odometry_noise.translation_bias ||
      ra.odometry_noise.rotation_bias != rb.odometry_noise.rotation_bias) {
    return fail("the odometry noises");
  }
  if (a.chessboards().size() != b.chessboards().size()) return fail("the chessboards");
  return SameCamera(ra.camera, rb.camera);
}

}  // namespace pirouette::testing
