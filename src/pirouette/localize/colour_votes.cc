#include "pirouette/localize/colour_votes.h"

#include <algorithm>
#include <limits>
#include <utility>
#include <vector>

namespace pirouette::localize {

ColourVotes::ColourVotes(core::GridGeometry geometry) : geometry_(std::move(geometry)) {}

void ColourVotes::Add(const ColourSighting& sighting) {
  if (sighting.colour == core::ColourClass::kNone) return;
  const core::CellIndex c = geometry_.CellOf(sighting.p_m);
  if (!geometry_.Contains(c)) return;
  const auto k = static_cast<std::size_t>(sighting.colour);
  for (int dy = -1; dy <= 1; ++dy) {
    for (int dx = -1; dx <= 1; ++dx) {
      const core::CellIndex n{c.x + dx, c.y + dy};
      if (!geometry_.Contains(n)) continue;
      std::uint16_t& count = votes_[geometry_.Flat(n)][k];
      const int add = dx == 0 && dy == 0 ? 2 : 1;
      count = static_cast<std::uint16_t>(
          std::min<int>(count + add, std::numeric_limits<std::uint16_t>::max()));
    }
  }
}

ColourMap ColourVotes::Map() const {
  std::vector<core::ColourClass> cells(geometry_.CellCount(), core::ColourClass::kNone);
  for (const auto& [i, counts] : votes_) {
    const auto best = std::max_element(counts.begin(), counts.end());
    if (*best > 0) cells[i] = static_cast<core::ColourClass>(best - counts.begin());
  }
  return {geometry_, std::move(cells)};
}

}  // namespace pirouette::localize
