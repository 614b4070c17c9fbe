#include "anim/mocap/transition_blend.hpp"

#include <gtest/gtest.h>

#include "synthetic_motion.hpp"

using namespace mc::anim::mocap;

TEST(TransitionBlend, EaseInEaseOutWeights) {
  const int k = 10;
  EXPECT_NEAR(transition_alpha(-1, k), 1, 1e-6);
  EXPECT_NEAR(transition_alpha(k - 1, k), 0, 1e-6);
  float prev = 1;
  for (int p = 0; p < k; ++p) {
    const float a = transition_alpha(p, k);
    EXPECT_LT(a, prev);
    prev = a;
  }
  EXPECT_NEAR(transition_alpha(k / 2 - 1, k), 0.5f, 1e-6);  // symmetric about the middle
  // Slow at both ends: the first and last steps are smaller than the middle one.
  EXPECT_LT(1 - transition_alpha(0, k), transition_alpha(3, k) - transition_alpha(4, k));
}

TEST(TransitionBlend, BlendsFromSourceToAlignedTarget) {
  const MocapClip a = test::synthetic_walker(40, 24);
  MocapClip b = test::synthetic_walker(40, 24, 1.0f, 0, 10);  // a smaller swing
  const int k = 8;
  PlanarAlign align{0.5f, 3, 0};
  std::vector<glm::vec3> root(k);
  std::vector<glm::quat> local(static_cast<std::size_t>(k * a.skeleton.size()));
  TransitionBlendJob job;
  job.from = &a; job.from_frame = 5; job.to = &b; job.to_frame = 7; job.length = k; job.align = align;
  job.root_out = root.data(); job.local_out = local.data();
  ASSERT_TRUE(job.Run());
  // Last frame is the target, placed by the alignment; the first is mostly the source.
  EXPECT_NEAR(glm::length(root[k - 1] - align.apply(b.root_position[7 + k - 1])), 0, 1e-5);
  EXPECT_LT(glm::length(root[0] - a.root_position[5]), 0.1f * glm::length(a.root_position[5] - align.apply(b.root_position[7])));
  const int leg = 1;
  EXPECT_NEAR(std::fabs(glm::dot(local[static_cast<std::size_t>((k - 1) * a.skeleton.size() + leg)], b.pose(7 + k - 1)[leg])), 1, 1e-5);
  // Out-of-range windows are refused.
  job.from_frame = 35;
  EXPECT_FALSE(job.Validate());
  EXPECT_FALSE(job.Run());
}
