#include "pirouette/sim/clearance_index.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <stdexcept>
#include <string>

#include "pirouette/sim/seeded_random.h"
#include "pirouette/sim/world_generator.h"

// Its own namespace: the unit tests compile together (unity batches).
namespace pirouette::sim::clearance_index_test {
namespace {

// Points over the floor and a little past it: random ones, and a lattice on
// whole centimetres (where the floor's edges and the generated walls' faces lie).
std::vector<Eigen::Vector2d> Points(const World& world, std::uint64_t seed) {
  SeededRandom random(seed);
  const Eigen::Vector2d size = world.floor().size;
  std::vector<Eigen::Vector2d> points;
  for (int i = 0; i < 5000; ++i) {
    const double x = random.Uniform(-0.05, size.x() + 0.05);
    const double y = random.Uniform(-0.05, size.y() + 0.05);
    points.emplace_back(x, y);
  }
  // A lattice of at most 60 × 60 points on whole centimetres.
  const double step = 0.01 * std::ceil(100.0 * std::max(size.x(), size.y()) / 60.0);
  for (double x = 0.0; x <= size.x(); x += step) {
    for (double y = 0.0; y <= size.y(); y += step) points.emplace_back(x, y);
  }
  return points;
}

void ExpectTheWorldsAnswers(const World& world, double reach_m, const std::string& what) {
  const ClearanceIndex index(world, reach_m);
  std::size_t differ = 0;
  for (const Eigen::Vector2d& p : Points(world, 7)) {
    // The same doubles, bit for bit.
    differ += index.Clearance(p) != world.Clearance(p);
    differ += index.IsOccupied(p) != world.IsOccupied(p);
  }
  EXPECT_EQ(differ, 0u) << what << ", reach " << reach_m;
}

TEST(ClearanceIndexTest, AnswersAsTheWorldDoes) {
  for (const WorldKind kind : kWorldKinds) {
    for (std::uint64_t seed = 1; seed <= 2; ++seed) {
      const World world = BuildWorld(GenerateWorld(kind, seed));
      for (const double reach : {0.01, 0.12, 100.0}) {
        ExpectTheWorldsAnswers(world, reach, std::string(WorldKindName(kind)));
      }
    }
  }
}

TEST(ClearanceIndexTest, RefusesANonPositiveReach) {
  const World world = BuildWorld(GenerateWorld(WorldKind::kRooms, 1));
  EXPECT_THROW(ClearanceIndex(world, 0.0), std::invalid_argument);
  EXPECT_THROW(ClearanceIndex(world, -1.0), std::invalid_argument);
}

}  // namespace
}  // namespace pirouette::sim::clearance_index_test
