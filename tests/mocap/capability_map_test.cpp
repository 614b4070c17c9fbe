#include "anim/mocap/capability_map.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace mc::anim::mocap;

namespace {

// A hand-made graph: adjacency per node, ground motion per node.
MotionGraph graph(const std::vector<GraphNode>& nodes, const std::vector<std::vector<std::uint32_t>>& adj) {
  MotionGraph g;
  g.nodes = nodes;
  g.first_edge.assign(1, 0);
  for (const auto& a : adj) {
    g.targets.insert(g.targets.end(), a.begin(), a.end());
    g.first_edge.push_back(static_cast<std::uint32_t>(g.targets.size()));
  }
  g.transition.assign(g.targets.size(), 0);
  return g;
}
GraphNode move(float fwd, float right, float dyaw, float speed = 1) {
  GraphNode n;
  n.fwd = fwd; n.right = right; n.dyaw = dyaw; n.speed = speed;
  return n;
}
CapabilityParams params(int iterations, int depth) {
  CapabilityParams p;
  p.grid = MapGrid{16, 16, 0.25f, -2.0f, -2.0f};
  p.iterations = iterations;
  p.max_depth = depth;
  return p;
}

}  // namespace

TEST(CapabilityMap, StraightWalkerCostsFramesAheadAndNothingBehind) {
  // One node looping on itself: 0.1 m forward per frame.
  const MotionGraph g = graph({move(0.1f, 0, 0)}, {{0}});
  CapabilityParams p = params(3, 30);
  const CapabilityMap m = compute_capability_map(g, p);
  // x = 1.0 is reached at frame 10, in the cell [1.0, 1.25) x [0, 0.25).
  EXPECT_FLOAT_EQ(m.cost[static_cast<std::size_t>(p.grid.index(1.05f, 0.01f))], 10);
  EXPECT_FLOAT_EQ(m.cost[static_cast<std::size_t>(p.grid.index(0.15f, 0.01f))], 1);
  EXPECT_EQ(m.cost[static_cast<std::size_t>(p.grid.index(-1.0f, 0.01f))], kUnreached);
  EXPECT_EQ(m.cost[static_cast<std::size_t>(p.grid.index(0.5f, 1.0f))], kUnreached);
  EXPECT_EQ(m.reached(), 8);  // x in [0.1, 1.9]: 8 cells of the row
  EXPECT_EQ(m.iterations, 3);
}

TEST(CapabilityMap, TurningRightGoesToPositiveY) {
  // Forward 0.1 m while turning 9 deg right per frame: a circle on the +y side.
  const MotionGraph g = graph({move(0.1f, 0, static_cast<float>(std::numbers::pi / 20))}, {{0}});
  const CapabilityMap m = compute_capability_map(g, params(1, 20));
  int plus = 0, minus = 0;
  for (int i = 0; i < m.grid.cells(); ++i)
    if (m.cost[static_cast<std::size_t>(i)] != kUnreached) (m.grid.center_y(i) > 0 ? plus : minus)++;
  EXPECT_GT(plus, 4);
  EXPECT_LE(minus, 1);
}

TEST(CapabilityMap, RandomWalksAreDeterministicForASeed) {
  // Start node 0 branches to "forward" (1) or "turn" (2); both branch again.
  const MotionGraph g = graph({move(0, 0, 0), move(0.08f, 0, 0), move(0.05f, 0, 0.3f)}, {{1, 2}, {1, 2}, {1, 2}});
  CapabilityParams p = params(200, 40);
  const CapabilityMap a = compute_capability_map(g, p), b = compute_capability_map(g, p);
  EXPECT_EQ(a.cost, b.cost);
  EXPECT_EQ(a.best_iteration, b.best_iteration);
  p.seed = 2;
  const CapabilityMap c = compute_capability_map(g, p);
  EXPECT_NE(a.best_iteration, c.best_iteration);
  // Convergence samples: every 100 iterations; improvements add up to at least the reached cells.
  EXPECT_EQ(a.checkpoint_iteration, (std::vector<int>{100, 200}));
  int improved = 0;
  for (int v : a.checkpoint_improved) improved += v;
  EXPECT_GE(improved, a.reached());
  EXPECT_LE(a.converged_iteration(0.99), 200);
  EXPECT_LE(a.converged_iteration(0.5), a.converged_iteration(0.99));
}

TEST(CapabilityMap, SavedPathReplaysToItsCell) {
  const MotionGraph g = graph({move(0, 0, 0), move(0.08f, 0, 0), move(0.05f, 0, 0.3f)}, {{1, 2}, {1, 2}, {1, 2}});
  const CapabilityParams p = params(100, 40);
  const CapabilityMap m = compute_capability_map(g, p);
  int checked = 0;
  for (int cell = 0; cell < m.grid.cells(); ++cell) {
    if (m.cost[static_cast<std::size_t>(cell)] == kUnreached) continue;
    const auto path = cell_path(g, p, m, cell);
    ASSERT_EQ(path.size(), static_cast<std::size_t>(m.best_step[static_cast<std::size_t>(cell)]) + 1);
    // Integrate the path's ground motion: it ends in the cell.
    float x = 0, y = 0, h = 0;
    for (std::size_t k = 1; k < path.size(); ++k) {
      const auto& n = g.nodes[static_cast<std::size_t>(path[k])];
      x += n.fwd * std::cos(h) - n.right * std::sin(h);
      y += n.fwd * std::sin(h) + n.right * std::cos(h);
      h += n.dyaw;
    }
    EXPECT_EQ(m.grid.index(x, y), cell);
    ++checked;
  }
  EXPECT_GT(checked, 5);
}

TEST(CapabilityMap, ObstaclesPrunePathsThatEnterThem) {
  const MotionGraph g = graph({move(0.1f, 0, 0)}, {{0}});
  CapabilityParams p = params(2, 30);
  p.obstacles.assign(static_cast<std::size_t>(p.grid.cells()), 0);
  p.obstacles[static_cast<std::size_t>(p.grid.index(1.05f, 0.01f))] = 1;
  const CapabilityMap m = compute_capability_map(g, p);
  EXPECT_FLOAT_EQ(m.cost[static_cast<std::size_t>(p.grid.index(0.9f, 0.01f))], 8);
  EXPECT_EQ(m.cost[static_cast<std::size_t>(p.grid.index(1.05f, 0.01f))], kUnreached);
  EXPECT_EQ(m.cost[static_cast<std::size_t>(p.grid.index(1.5f, 0.01f))], kUnreached);  // behind the wall
  EXPECT_EQ(m.pruned_by_obstacles, 2);
}

TEST(CapabilityMap, ConstraintsDisableFastEdges) {
  // From the start: a fast loop going forward or a slow loop going right.
  const MotionGraph g = graph({move(0, 0, 0, 0), move(0.2f, 0, 0, 6), move(0, 0.05f, 0, 1.5f)}, {{1, 2}, {1}, {2}});
  CapabilityParams p = params(50, 20);
  const CapabilityMap free = compute_capability_map(g, p);
  p.max_speed = 2;
  const CapabilityMap limited = compute_capability_map(g, p);
  const auto ahead = static_cast<std::size_t>(p.grid.index(1.1f, 0.01f));
  const auto right = static_cast<std::size_t>(p.grid.index(0.01f, 0.6f));
  EXPECT_NE(free.cost[ahead], kUnreached);
  EXPECT_NE(free.cost[right], kUnreached);
  EXPECT_EQ(limited.cost[ahead], kUnreached);
  EXPECT_NE(limited.cost[right], kUnreached);
}

TEST(CapabilityMap, GoalTermAddsSquaredDistanceToTheCellCentre) {
  const MotionGraph g = graph({move(0.1f, 0, 0)}, {{0}});
  CapabilityParams p = params(1, 30);
  p.alpha = 100;
  const CapabilityMap m = compute_capability_map(g, p);
  // Frame 10 at x = 1.0; the cell centre is (1.125, 0.125).
  const float d2 = 0.125f * 0.125f * 2;
  EXPECT_NEAR(m.cost[static_cast<std::size_t>(p.grid.index(1.05f, 0.01f))], std::min(10 + 100 * d2, 11 + 100 * (0.025f * 0.025f + 0.125f * 0.125f)), 1e-4);
}

TEST(Grassfire, DistancesAndDetoursAroundObstacles) {
  const MapGrid grid{16, 16, 0.25f, -2.0f, -2.0f};
  const auto free = grassfire(grid, {});
  const int start = grid.index(0.01f, 0.01f);
  EXPECT_EQ(free[static_cast<std::size_t>(start)], 0);
  EXPECT_NEAR(free[static_cast<std::size_t>(grid.index(1.1f, 0.1f))], 1.0f, 1e-5);   // 4 cells right
  EXPECT_NEAR(free[static_cast<std::size_t>(grid.index(-0.9f, 0.1f))], 1.0f, 1e-5);  // symmetric behind
  EXPECT_NEAR(free[static_cast<std::size_t>(grid.index(0.6f, 0.6f))], 2 * 0.25f * std::sqrt(2.0f), 1e-5);
  // A wall at x in [0.5, 0.75) from y = -1 to 1: going to x = 1.1 needs a detour.
  std::vector<std::uint8_t> wall(static_cast<std::size_t>(grid.cells()), 0);
  for (float y = -0.9f; y < 1.0f; y += 0.25f) wall[static_cast<std::size_t>(grid.index(0.6f, y))] = 1;
  const auto around = grassfire(grid, wall);
  EXPECT_GT(around[static_cast<std::size_t>(grid.index(1.1f, 0.1f))], 2.0f);
  EXPECT_EQ(around[static_cast<std::size_t>(grid.index(0.6f, 0.1f))], kUnreached);
}

TEST(CapabilityMap, IterationsWithinToleranceReplayTheWalks) {
  const MotionGraph g = graph({move(0, 0, 0), move(0.08f, 0, 0), move(0.05f, 0, 0.3f)}, {{1, 2}, {1, 2}, {1, 2}});
  const CapabilityParams p = params(300, 40);
  const CapabilityMap m = compute_capability_map(g, p);
  const auto exact = iterations_within(g, p, m, 0);
  const auto loose = iterations_within(g, p, m, 0.5f);
  for (std::size_t i = 0; i < m.cost.size(); ++i) {
    if (m.cost[i] == kUnreached) { EXPECT_EQ(exact[i], 0u); continue; }
    EXPECT_EQ(exact[i], m.best_iteration[i] + 1);  // exact = the last improvement
    EXPECT_LE(loose[i], exact[i]);
    EXPECT_GE(loose[i], 1u);
  }
  EXPECT_LE(iteration_quantile(loose, 0.9), iteration_quantile(exact, 0.9));
  EXPECT_EQ(iteration_quantile(exact, 1.0), static_cast<std::uint32_t>(m.converged_iteration(1.0)));
}
