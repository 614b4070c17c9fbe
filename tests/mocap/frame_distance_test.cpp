#include "anim/mocap/frame_distance.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace mc::anim::mocap;

namespace {
struct Cloud {
  std::vector<float> x, y, z, w;
  CloudView view() const { return {x.data(), y.data(), z.data(), w.data(), static_cast<int>(x.size())}; }
};
Cloud random_cloud(int n, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(-1, 1);
  Cloud c;
  for (int i = 0; i < n; ++i) {
    c.x.push_back(u(rng)); c.y.push_back(1 + u(rng)); c.z.push_back(u(rng)); c.w.push_back(0.5f + 0.5f * (u(rng) + 1));
  }
  return c;
}
Cloud transformed(const Cloud& c, const PlanarAlign& t) {
  Cloud o = c;
  for (std::size_t i = 0; i < c.x.size(); ++i) {
    const glm::vec3 p = t.apply({c.x[i], c.y[i], c.z[i]});
    o.x[i] = p.x; o.y[i] = p.y; o.z[i] = p.z;
  }
  return o;
}
}  // namespace

TEST(FrameDistance, AlignmentRecoversAKnownFloorTransform) {
  const Cloud b = random_cloud(50, 1);
  const PlanarAlign truth{0.7f, 2.5f, -1.25f};
  const Cloud a = transformed(b, truth);  // a = T b
  const PlanarAlign t = align_planar(a.view(), b.view());
  EXPECT_NEAR(t.theta, truth.theta, 1e-4);
  EXPECT_NEAR(t.x0, truth.x0, 1e-4);
  EXPECT_NEAR(t.z0, truth.z0, 1e-4);
  EXPECT_NEAR(cloud_distance(a.view(), b.view(), t), 0, 1e-6);
  // A vertical offset cannot be aligned away: it stays in the distance.
  Cloud up = a;
  for (auto& y : up.y) y += 0.1f;
  const PlanarAlign t2 = align_planar(up.view(), b.view());
  double wsum = 0;
  for (float w : b.w) wsum += w;
  EXPECT_NEAR(cloud_distance(up.view(), b.view(), t2), 0.01 * wsum, 1e-4);
}

TEST(FrameDistance, AlignmentIsOptimal) {
  const Cloud a = random_cloud(40, 2), b = random_cloud(40, 3);
  const PlanarAlign t = align_planar(a.view(), b.view());
  const double best = cloud_distance(a.view(), b.view(), t);
  for (float d : {-0.05f, 0.05f}) {
    PlanarAlign p = t; p.theta += d;
    EXPECT_GT(cloud_distance(a.view(), b.view(), p), best);
    p = t; p.x0 += d;
    EXPECT_GT(cloud_distance(a.view(), b.view(), p), best);
    p = t; p.z0 += d;
    EXPECT_GT(cloud_distance(a.view(), b.view(), p), best);
  }
}

TEST(FrameDistance, WindowSumsGiveTheDirectDistance) {
  // Two windows in one SoA array; the closed form equals the definition.
  const Cloud a = random_cloud(60, 4), b = random_cloud(60, 5);
  Cloud both = a;
  both.x.insert(both.x.end(), b.x.begin(), b.x.end());
  both.y.insert(both.y.end(), b.y.begin(), b.y.end());
  both.z.insert(both.z.end(), b.z.begin(), b.z.end());
  const auto sa = window_sums(both.x.data(), both.y.data(), both.z.data(), a.w.data(), 0, 60);
  const auto sb = window_sums(both.x.data(), both.y.data(), both.z.data(), a.w.data(), 60, 60);
  PlanarAlign t;
  const double fast = window_distance(both.x.data(), both.y.data(), both.z.data(), a.w.data(), 0, 60, 60, sa, sb, &t);
  Cloud bw = b;
  bw.w = a.w;
  const PlanarAlign direct = align_planar(a.view(), bw.view());
  EXPECT_NEAR(fast, cloud_distance(a.view(), bw.view(), direct), 1e-3);
  EXPECT_NEAR(t.theta, direct.theta, 1e-4);
  EXPECT_NEAR(t.x0, direct.x0, 1e-4);
  // Same window against itself: zero.
  EXPECT_NEAR(window_distance(both.x.data(), both.y.data(), both.z.data(), a.w.data(), 0, 0, 60, sa, sa), 0, 1e-3);
}

TEST(FrameDistance, CloudJointsSkipDuplicatesAndFingers) {
  MocapSkeleton s;
  s.names = {"Hips", "LHipJoint", "LeftUpLeg", "LeftHand", "LeftFingerBase", "LeftHandIndex1"};
  s.parents = {-1, 0, 1, 0, 3, 4};
  s.offsets = {glm::vec3(0), glm::vec3(0), glm::vec3(0.1f, -0.1f, 0), glm::vec3(0.5f, 0, 0), glm::vec3(0.1f, 0, 0),
               glm::vec3(0.03f, 0, 0)};
  s.end_site.assign(6, false);
  EXPECT_EQ(cloud_joints(s), (std::vector<int>{0, 2, 3}));
}
