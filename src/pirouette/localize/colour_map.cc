#include "pirouette/localize/colour_map.h"

#include <algorithm>
#include <array>
#include <stdexcept>
#include <utility>

namespace pirouette::localize {

ColourMap::ColourMap(core::GridGeometry geometry, std::vector<core::ColourClass> cells)
    : geometry_(std::move(geometry)), cells_(std::move(cells)) {
  if (cells_.size() != geometry_.CellCount()) {
    throw std::invalid_argument("ColourMap: one class a cell of the geometry");
  }
}

ColourMap ColourMap::FromSightings(const core::GridGeometry& geometry,
                                   const std::vector<ColourSighting>& sightings) {
  std::vector<std::array<int, core::kColourClasses>> votes(geometry.CellCount());
  for (const ColourSighting& s : sightings) {
    if (s.colour == core::ColourClass::kNone) continue;
    const core::CellIndex c = geometry.CellOf(s.p_m);
    if (!geometry.Contains(c)) continue;
    for (int dy = -1; dy <= 1; ++dy) {
      for (int dx = -1; dx <= 1; ++dx) {
        const core::CellIndex n{c.x + dx, c.y + dy};
        if (!geometry.Contains(n)) continue;
        votes[geometry.Flat(n)][static_cast<std::size_t>(s.colour)] += dx == 0 && dy == 0 ? 2 : 1;
      }
    }
  }
  std::vector<core::ColourClass> cells(geometry.CellCount(), core::ColourClass::kNone);
  for (std::size_t i = 0; i < votes.size(); ++i) {
    const auto best = std::max_element(votes[i].begin(), votes[i].end());
    if (*best > 0) cells[i] = static_cast<core::ColourClass>(best - votes[i].begin());
  }
  return {geometry, std::move(cells)};
}

core::ColourClass ColourMap::At(const core::CellIndex& c) const {
  if (cells_.empty() || !geometry_.Contains(c)) return core::ColourClass::kNone;
  return cells_[geometry_.Flat(c)];
}

}  // namespace pirouette::localize
