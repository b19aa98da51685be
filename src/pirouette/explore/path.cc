#include "pirouette/explore/path.h"

#include <array>
#include <stdexcept>

namespace pirouette::explore {
namespace {

struct Step {
  int dx;
  int dy;
  std::int32_t weight;
};

// Orthogonal steps first: they win ties.
constexpr std::array<Step, 8> kSteps = {{
    {1, 0, kChamferOrthogonal},
    {0, 1, kChamferOrthogonal},
    {-1, 0, kChamferOrthogonal},
    {0, -1, kChamferOrthogonal},
    {1, 1, kChamferDiagonal},
    {-1, 1, kChamferDiagonal},
    {-1, -1, kChamferDiagonal},
    {1, -1, kChamferDiagonal},
}};

std::int32_t DistanceAt(const DistanceField& field, const core::CellIndex& c) {
  if (c.x < 0 || c.y < 0 || c.x >= field.width() || c.y >= field.height()) return kUnreachable;
  return field.At(c);
}

// The index in kSteps of the neighbour of `c` with the smallest distance
// (ties: lower weight, then `previous`, then kSteps' order), or -1 if every
// neighbour is unreachable.
int BestStep(const DistanceField& field, const core::CellIndex& c, int previous) {
  int best = -1;
  std::int32_t best_distance = kUnreachable;
  for (int i = 0; i < static_cast<int>(kSteps.size()); ++i) {
    const Step& s = kSteps[static_cast<std::size_t>(i)];
    const std::int32_t d = DistanceAt(field, {c.x + s.dx, c.y + s.dy});
    if (d >= kUnreachable) continue;
    const bool better =
        best < 0 || d < best_distance ||
        (d == best_distance && s.weight < kSteps[static_cast<std::size_t>(best)].weight) ||
        (d == best_distance && s.weight == kSteps[static_cast<std::size_t>(best)].weight &&
         i == previous);
    if (better) {
      best = i;
      best_distance = d;
    }
  }
  return best;
}

}  // namespace

std::optional<Path> SteepestDescent(const CoarseGrid& grid, const DistanceField& field,
                                    const core::CellIndex& start) {
  if (!grid.geometry().Contains(start) || field.width() != grid.width() ||
      field.height() != grid.height()) {
    throw std::out_of_range("SteepestDescent: the start cell is off the grid");
  }
  Path path;
  core::CellIndex c = start;
  if (field.At(c) >= kUnreachable) {
    const int step = BestStep(field, c, -1);
    if (step < 0) return std::nullopt;
    const Step& s = kSteps[static_cast<std::size_t>(step)];
    c = {c.x + s.dx, c.y + s.dy};
  }
  int previous = -1;
  while (field.At(c) > 0) {
    path.cells.push_back(c);
    const int step = BestStep(field, c, previous);
    const Step& s = kSteps[static_cast<std::size_t>(step)];
    const core::CellIndex next{c.x + s.dx, c.y + s.dy};
    // In a converged field every reachable cell but a goal has a neighbour
    // lower by the step's weight; anything else is a broken invariant.
    if (field.At(next) + s.weight != field.At(c)) {
      throw std::logic_error("SteepestDescent: the distance field is not converged");
    }
    c = next;
    previous = step;
  }
  path.goal = c;
  return path;
}

}  // namespace pirouette::explore
