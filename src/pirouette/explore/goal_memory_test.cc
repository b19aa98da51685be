#include "pirouette/explore/goal_memory.h"

#include <gtest/gtest.h>

namespace pirouette::explore {
namespace {

TEST(GoalMemoryTest, StallsOnlyWhereItWasToldToStay) {
  GoalMemory goals;
  EXPECT_FALSE(goals.Stalled({0.0, 0.0}, 0.01));
  goals.Remember({0.0, 0.0}, {1.0, 0.0}, /*stay=*/false);
  EXPECT_FALSE(goals.Stalled({0.0, 0.0}, 0.01));
  goals.Remember({0.0, 0.0}, {1.0, 0.0}, /*stay=*/true);
  EXPECT_TRUE(goals.Stalled({0.005, 0.0}, 0.01));
  EXPECT_FALSE(goals.Stalled({0.02, 0.0}, 0.01));
  goals.Forget();
  EXPECT_FALSE(goals.Stalled({0.0, 0.0}, 0.01));
}

TEST(GoalMemoryTest, TheLastGoalExactlyOrNear) {
  GoalMemory goals;
  EXPECT_FALSE(goals.IsLastGoal({1.0, 0.0}));
  goals.Remember({0.0, 0.0}, {1.0, 0.0}, true);
  EXPECT_TRUE(goals.IsLastGoal({1.0, 0.0}));
  EXPECT_FALSE(goals.IsLastGoal({1.0, 1e-9}));
  EXPECT_TRUE(goals.NearLastGoal({1.0, 0.01}, 0.02));
  EXPECT_FALSE(goals.NearLastGoal({1.0, 0.03}, 0.02));
}

TEST(GoalMemoryTest, GoalsGivenUpAreKeptInOrderAndFoundWithinATolerance) {
  GoalMemory goals;
  goals.GiveUp({1.0, 2.0});
  goals.GiveUp({3.0, 4.0});
  ASSERT_EQ(goals.given_up().size(), 2U);
  EXPECT_EQ(goals.given_up()[1], Eigen::Vector2d(3.0, 4.0));
  EXPECT_TRUE(goals.GaveUp({1.01, 1.99}, 0.02));
  EXPECT_FALSE(goals.GaveUp({1.03, 2.0}, 0.02));
}

}  // namespace
}  // namespace pirouette::explore
