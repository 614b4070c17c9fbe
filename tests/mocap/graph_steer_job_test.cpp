#include "anim/mocap/graph_steer_job.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "synthetic_motion.hpp"

using namespace mc::anim::mocap;

namespace {
// Two clips built by the real graph builder: a straight walk and the same gait
// turning right at 60 deg/s; equal phases join them by transitions.
MotionGraph two_walks() {
  GraphBuildParams p;
  p.threshold_rms = 0.05f;
  return build_motion_graph({test::synthetic_walker(150, 24, 1.2f, 0), test::synthetic_walker(150, 24, 1.2f, 60)}, p);
}
}  // namespace

TEST(GraphSteer, FollowsTheWantedTurnThroughTransitions) {
  const MotionGraph g = two_walks();
  ASSERT_GT(g.stats.transitions_after, 0);
  for (const float want : {0.0f, 1.047f}) {
    // Start on the straight clip and steer for 200 frames.
    int node = -1;
    for (int i = 0; i < g.size() && node < 0; ++i)
      if (g.nodes[static_cast<std::size_t>(i)].clip == 0) node = i;
    ASSERT_GE(node, 0);
    double turned = 0;
    int transitions = 0;
    for (int k = 0; k < 200; ++k) {
      int next = -1;
      bool tr = false;
      GraphSteerJob job;
      job.graph = &g;
      job.node = node;
      job.want_speed = 1.2f;
      job.want_turn = want;
      job.next = &next;
      job.transition = &tr;
      ASSERT_TRUE(job.Run());
      node = next;
      transitions += tr ? 1 : 0;
      turned += g.nodes[static_cast<std::size_t>(node)].dyaw;
    }
    const double rate = turned / (200 / 30.0);
    if (want == 0.0f) {
      EXPECT_NEAR(rate, 0, 0.15);
    } else {
      EXPECT_NEAR(rate, want, 0.2);
      EXPECT_GT(transitions, 0);  // it had to leave the straight clip
    }
  }
}

TEST(GraphSteer, DeterministicAndValidated) {
  const MotionGraph g = two_walks();
  int a = -1, b = -1;
  GraphSteerJob job;
  job.graph = &g;
  job.node = 3;
  job.want_turn = 0.5f;
  job.next = &a;
  ASSERT_TRUE(job.Run());
  job.next = &b;
  ASSERT_TRUE(job.Run());
  EXPECT_EQ(a, b);
  job.node = g.size();
  EXPECT_FALSE(job.Run());
  job.node = 0;
  job.lookahead = 0;
  EXPECT_FALSE(job.Validate());
  job.lookahead = 15;
  job.next = nullptr;
  EXPECT_FALSE(job.Validate());
}
