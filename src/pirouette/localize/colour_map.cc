#include "pirouette/localize/colour_map.h"

#include <stdexcept>
#include <utility>

#include "pirouette/localize/colour_votes.h"

namespace pirouette::localize {

ColourMap::ColourMap(core::GridGeometry geometry, std::vector<core::ColourClass> cells)
    : geometry_(std::move(geometry)), cells_(std::move(cells)) {
  if (cells_.size() != geometry_.CellCount()) {
    throw std::invalid_argument("ColourMap: one class a cell of the geometry");
  }
}

ColourMap ColourMap::FromSightings(const core::GridGeometry& geometry,
                                   const std::vector<ColourSighting>& sightings) {
  ColourVotes votes(geometry);
  for (const ColourSighting& s : sightings) votes.Add(s);
  return votes.Map();
}

ColourMap ColourMap::On(const core::GridGeometry& geometry) const {
  std::vector<core::ColourClass> cells(geometry.CellCount(), core::ColourClass::kNone);
  for (std::size_t i = 0; i < cells.size(); ++i) {
    cells[i] = At(geometry_.CellOf(geometry.CellCentre(geometry.Unflat(i))));
  }
  return {geometry, std::move(cells)};
}

core::ColourClass ColourMap::At(const core::CellIndex& c) const {
  if (cells_.empty() || !geometry_.Contains(c)) return core::ColourClass::kNone;
  return cells_[geometry_.Flat(c)];
}

}  // namespace pirouette::localize
