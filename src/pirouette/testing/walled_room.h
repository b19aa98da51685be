#pragma once

#include <Eigen/Core>
#include <utility>
#include <vector>

#include "pirouette/core/colour_class.h"
#include "pirouette/core/grid_geometry.h"
#include "pirouette/localize/colour_map.h"
#include "pirouette/mapping/trinary_map.h"

namespace pirouette::testing {

// A saved map of a 1.0 m by 0.6 m room in 2 cm cells, walled all round (one
// cell thick) and free inside: the same turned by 180 degrees about its
// centre. Its colour layer has the west wall red, the east wall blue, the
// others grey, which tells the room from its mirror image.
struct WalledRoom {
  static constexpr double kCell = 0.02;
  mapping::TrinaryMap map{core::GridGeometry(kCell, Eigen::Vector2d::Zero(), 50, 30), {}};
  localize::ColourMap colours;
};

inline WalledRoom MakeWalledRoom() {
  WalledRoom room;
  const core::GridGeometry& g = room.map.geometry;
  room.map.cells.assign(g.CellCount(), mapping::CellState::kFree);
  std::vector<core::ColourClass> colours(g.CellCount(), core::ColourClass::kNone);
  for (int y = 0; y < g.height(); ++y) {
    for (int x = 0; x < g.width(); ++x) {
      const bool west = x == 0;
      const bool east = x == g.width() - 1;
      if (!west && !east && y != 0 && y != g.height() - 1) continue;
      room.map.cells[g.Flat({x, y})] = mapping::CellState::kOccupied;
      colours[g.Flat({x, y})] = west   ? core::ColourClass::kHue0
                                : east ? core::ColourClass::kHue8
                                       : core::ColourClass::kGrey;
    }
  }
  room.colours = localize::ColourMap(g, std::move(colours));
  return room;
}

}  // namespace pirouette::testing
