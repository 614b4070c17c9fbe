#include "anim/mocap/motion_graph.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "synthetic_motion.hpp"

using namespace mc::anim::mocap;

namespace {
void csr(const std::vector<std::vector<std::uint32_t>>& adj, std::vector<std::uint32_t>& first,
         std::vector<std::uint32_t>& targets) {
  first.assign(1, 0);
  targets.clear();
  for (const auto& a : adj) {
    targets.insert(targets.end(), a.begin(), a.end());
    first.push_back(static_cast<std::uint32_t>(targets.size()));
  }
}
}  // namespace

TEST(MotionGraph, TarjanFindsKnownComponents) {
  // {0,1,2} cycle -> {3,4} cycle; 5 alone; 6 -> 0.
  std::vector<std::uint32_t> first, targets;
  csr({{1}, {2}, {0, 3}, {4}, {3}, {}, {0}}, first, targets);
  std::vector<int> comp;
  EXPECT_EQ(strongly_connected_components(first, targets, comp), 4);
  EXPECT_EQ(comp[0], comp[1]);
  EXPECT_EQ(comp[1], comp[2]);
  EXPECT_EQ(comp[3], comp[4]);
  EXPECT_NE(comp[0], comp[3]);
  EXPECT_NE(comp[5], comp[0]);
  EXPECT_NE(comp[6], comp[0]);

  MotionGraph g;
  g.nodes.resize(7);
  g.first_edge = first;
  g.targets = targets;
  g.transition.assign(targets.size(), 0);
  keep_largest_scc(g);
  EXPECT_EQ(g.size(), 3);
  EXPECT_EQ(g.stats.edges_after, 3);  // 2 -> 3 and 6 -> 0 are gone
  for (int n = 0; n < 3; ++n) EXPECT_EQ(g.degree(n), 1);
}

TEST(MotionGraph, TarjanIsIterativeOnALongCycle) {
  // 300 000 nodes in one ring: a recursive DFS would overflow the stack.
  const std::uint32_t n = 300000;
  std::vector<std::uint32_t> first(n + 1), targets(n);
  for (std::uint32_t i = 0; i < n; ++i) { first[i] = i; targets[i] = (i + 1) % n; }
  first[n] = n;
  std::vector<int> comp;
  EXPECT_EQ(strongly_connected_components(first, targets, comp), 1);
  targets[n - 1] = n - 1;  // cut the ring: every node is its own component
  EXPECT_EQ(strongly_connected_components(first, targets, comp), static_cast<int>(n));
}

TEST(MotionGraph, GroundMotionOfAWalkerTurningRight) {
  const MocapClip c = test::synthetic_walker(31, 30, 1.5f, 90);
  const auto gm = clip_ground_motion(c, 3);
  EXPECT_EQ(gm[0].fwd, 0);
  for (int f = 1; f < 31; ++f) {
    EXPECT_NEAR(gm[static_cast<std::size_t>(f)].fwd, 1.5 / 30, 1e-4);
    EXPECT_NEAR(gm[static_cast<std::size_t>(f)].right, 0, 1e-4);
    EXPECT_NEAR(gm[static_cast<std::size_t>(f)].dyaw, glm::radians(3.0f), 1e-4);  // +: to the right
    EXPECT_EQ(gm[static_cast<std::size_t>(f)].clip, 3);
  }
  EXPECT_NEAR(gm[15].speed, 1.5, 0.05);
}

TEST(MotionGraph, PeriodicMotionLinksFramesOfTheSamePhase) {
  // A 24-frame gait cycle: windows one period apart are identical after the
  // floor alignment, so transitions join frames of equal phase. A second
  // clip with no match (legs spread wide and still) is pruned as dead ends.
  const int period = 24;
  std::vector<MocapClip> clips = {test::synthetic_walker(120, period),
                                  test::synthetic_walker(60, 1000, 0.2f, 0, 80)};
  GraphBuildParams p;
  p.threshold_rms = 0.02f;
  const MotionGraph g = build_motion_graph(clips, p);
  EXPECT_EQ(g.stats.frames, 180);
  EXPECT_EQ(g.stats.natural_edges, 119 + 59);
  EXPECT_GT(g.stats.transition_edges, 0);
  EXPECT_GT(g.size(), 40);
  int transitions = 0;
  for (int n = 0; n < g.size(); ++n) {
    EXPECT_EQ(g.nodes[static_cast<std::size_t>(n)].clip, 0);
    for (auto e = g.first_edge[static_cast<std::size_t>(n)]; e < g.first_edge[static_cast<std::size_t>(n) + 1]; ++e) {
      if (!g.transition[e]) continue;
      ++transitions;
      // i -> j+1 with j one or more periods from i.
      const int i = g.nodes[static_cast<std::size_t>(n)].frame, j1 = g.nodes[g.targets[e]].frame;
      const int gap = std::abs(j1 - 1 - i);
      EXPECT_EQ(gap % period, 0) << i << " -> " << j1;
    }
  }
  EXPECT_GT(transitions, 0);
  // Every node keeps an exit: the largest strongly connected component has no dead end.
  for (int n = 0; n < g.size(); ++n) EXPECT_GE(g.degree(n), 1);
}
