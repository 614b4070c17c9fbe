#include "anim/mocap/opponent_model.hpp"

#include <gtest/gtest.h>

#include <numbers>

using namespace mc::anim::mocap;

TEST(OpponentModel, SafeCellsFollowTheInequality) {
  const std::vector<float> own = {10, 10, 10, 10, kUnreached, 5};
  const std::vector<float> opp = {30, 20, 19.9f, kUnreached, 100, 1};
  // Co > Cd + Ts + eps with Ts = 8, eps = 2: the bound is 20.
  const auto safe = safe_cells(own, opp, 8, 2);
  EXPECT_EQ(safe, (std::vector<std::uint8_t>{1, 0, 0, 1, 0, 0}));  // equal is not safe
  const std::vector<float> goal_score = {1, 9, 9, 3, 9, 9};
  EXPECT_EQ(best_safe_cell(safe, [&](int c) { return goal_score[static_cast<std::size_t>(c)]; }), 3);
  EXPECT_EQ(best_safe_cell(std::vector<std::uint8_t>(6, 0), [](int) { return 1.0f; }), -1);
}

TEST(OpponentModel, MapsArePlacedAtTheAgentsPose) {
  CapabilityMap m;
  m.grid = MapGrid{8, 8, 0.5f, -2, -2};
  m.cost.assign(64, kUnreached);
  m.cost[static_cast<std::size_t>(m.grid.index(1.1f, 0.1f))] = 7;  // 1 m ahead
  // Facing +y (90 deg): "ahead" is world +y and its right is world -x.
  const AgentPose pose{10, 5, static_cast<float>(std::numbers::pi / 2)};
  EXPECT_EQ(cost_at(m, pose, 9.9f, 6.1f), 7);
  EXPECT_EQ(cost_at(m, pose, 11.1f, 5.1f), kUnreached);
  EXPECT_EQ(cost_at(m, pose, 50, 50), kUnreached);
  const MapGrid world{4, 4, 0.5f, 8.5f, 5};  // the cell of (9.9, 6.1) is centred at (9.75, 6.25)
  const auto placed = place_map(m, pose, world);
  EXPECT_EQ(placed[static_cast<std::size_t>(world.index(9.9f, 6.1f))], 7);
}
