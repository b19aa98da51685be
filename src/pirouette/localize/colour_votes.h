#pragma once

#include <array>
#include <cstdint>
#include <unordered_map>

#include "pirouette/core/colour_class.h"
#include "pirouette/core/grid_geometry.h"
#include "pirouette/localize/colour_map.h"

namespace pirouette::localize {

// The votes of colour sightings on a grid, added one at a time, so that a
// run's colour map is made without holding every sighting at once (a
// 3,000-frame apartment run's sightings took 50 MB). Counts as
// ColourMap::FromSightings says: a sighting votes for its class in its cell
// twice and once in each of the 8 around it; off the grid it is dropped.
// Only the cells voted for are held (obstacles' bases: a few percent of a
// map; a dense count on a 1.5M-cell map took 45 MB); a count stops at 65,535
// (a cell seen that often by one class has its answer).
class ColourVotes {
 public:
  explicit ColourVotes(core::GridGeometry geometry);

  void Add(const ColourSighting& sighting);
  // Each cell the class with the most votes (the lowest on a tie), kNone
  // without votes.
  ColourMap Map() const;

 private:
  core::GridGeometry geometry_;
  std::unordered_map<std::size_t, std::array<std::uint16_t, core::kColourClasses>> votes_;
};

}  // namespace pirouette::localize
