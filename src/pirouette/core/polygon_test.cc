#include "pirouette/core/polygon.h"

#include <gtest/gtest.h>

namespace pirouette::core {
namespace {

using Points = std::vector<Eigen::Vector2d>;

TEST(PolygonProblemTest, TakesATriangleEitherWayRound) {
  EXPECT_EQ(PolygonProblem(Points{{0.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}}), std::nullopt);
  EXPECT_EQ(PolygonProblem(Points{{0.0, 0.0}, {0.0, 1.0}, {1.0, 0.0}}), std::nullopt);
}

TEST(PolygonProblemTest, TakesAConcavePolygon) {
  EXPECT_EQ(PolygonProblem(Points{{0.0, 0.0}, {2.0, 0.0}, {1.0, 1.0}, {2.0, 2.0}, {0.0, 2.0}}),
            std::nullopt);
}

TEST(PolygonProblemTest, RefusesABowTieNamingTheEdgesThatMeet) {
  EXPECT_EQ(PolygonProblem(Points{{0.0, 0.0}, {1.0, 1.0}, {1.0, 0.0}, {0.0, 1.0}}),
            "the polygon is not simple: the edge from point 1 to point 2 meets the edge from "
            "point 3 to point 4");
}

TEST(PolygonProblemTest, RefusesPointsOnOneLine) {
  EXPECT_EQ(PolygonProblem(Points{{0.0, 0.0}, {1.0, 0.0}, {2.0, 0.0}}),
            "the points lie on one line: the polygon has no area");
}

TEST(PolygonProblemTest, RefusesAPolygonWithNoArea) {
  EXPECT_EQ(PolygonProblem(Points{{0.0, 0.0}, {1e-7, 0.0}, {0.0, 1e-7}}),
            "the polygon has no area");
}

TEST(PolygonProblemTest, RefusesARepeatedPoint) {
  EXPECT_EQ(PolygonProblem(Points{{0.0, 0.0}, {1.0, 0.0}, {1.0, 0.0}, {0.0, 1.0}}),
            "points 2 and 3 are the same point");
}

TEST(PolygonProblemTest, RefusesAnEdgeThatFoldsBack) {
  EXPECT_EQ(PolygonProblem(Points{{0.0, 0.0}, {2.0, 0.0}, {1.0, 0.0}, {1.0, 1.0}}),
            "the polygon folds back on itself at point 2");
}

}  // namespace
}  // namespace pirouette::core
