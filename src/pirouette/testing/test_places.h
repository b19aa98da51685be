#pragma once

// A room of place views for the place-table tests (localize and app): a
// robot's ROP in a 2 × 1.4 m room with a blue block on the left wall, and a
// table of such places on a grid.

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "pirouette/core/angle.h"
#include "pirouette/localize/place_table.h"
#include "pirouette/mapping/radial_profile.h"

namespace pirouette::testing {

inline constexpr int kBins = mapping::kRadialProfileBins;

// The range from (px, py) along `bearing_rad` to the walls of the room
// [0, w] × [0, h].
inline double WallRange(double px, double py, double bearing_rad, double w, double h) {
  const double c = std::cos(bearing_rad), s = std::sin(bearing_rad);
  double t = 1e9;
  if (c > 1e-12) t = std::min(t, (w - px) / c);
  if (c < -1e-12) t = std::min(t, -px / c);
  if (s > 1e-12) t = std::min(t, (h - py) / s);
  if (s < -1e-12) t = std::min(t, -py / s);
  return t;
}

// A robot at (px, py) facing heading_deg in a 2 × 1.4 m room with a blue
// block on the left wall.
inline localize::PlaceView View(double px, double py, double heading_deg) {
  const double w = 2.0, h = 1.4;
  localize::PlaceView view;
  for (int b = 0; b < kBins; ++b) {
    const double a = core::DegToRad(heading_deg + b + 0.5);
    const double c = std::cos(a), s = std::sin(a);
    const double t = WallRange(px, py, a, w, h);
    view.ranges_m.push_back(std::min(t, 1.5));
    const double hy = py + t * s;
    const bool blue = c < -1e-12 && std::abs(px + t * c) < 1e-6 && hy > 0.3 && hy < 0.7;
    view.colours.push_back(t > 1.5 ? core::ColourClass::kNone
                                   : (blue ? core::ColourClass::kHue8 : core::ColourClass::kGrey));
  }
  return view;
}

inline localize::PlaceTable Grid() {
  std::vector<localize::PlaceEntry> entries;
  for (double x = 0.2; x < 1.9; x += 0.3) {
    for (double y = 0.2; y < 1.3; y += 0.3) {
      localize::PlaceEntry e;
      e.x_m = x;
      e.y_m = y;
      e.heading_rad = 0.0;
      e.view = View(x, y, 0.0);
      e.kinds.assign(kBins, core::ReadingKind::kHit);
      entries.push_back(std::move(e));
    }
  }
  return {"room", 1.5, std::move(entries)};
}

}  // namespace pirouette::testing
