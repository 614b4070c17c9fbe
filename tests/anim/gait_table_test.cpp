#include "anim/gait_table.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

namespace mc::anim {
namespace {

TEST(GaitTable, GainsIncreaseWithinTheReferenceCycle) {
  const auto keys = gait_keys();
  ASSERT_GE(keys.size(), 10u);
  EXPECT_EQ(keys[0].gain_m, 0.0f);
  for (std::size_t i = 1; i < keys.size(); ++i) EXPECT_GT(keys[i].gain_m, keys[i - 1].gain_m);
  EXPECT_LT(keys.back().gain_m, kReferenceCycleM);
  GaitSample out;
  EXPECT_TRUE((SampleGaitJob{keys, 0, &out}.Validate()));
}

TEST(PostureIndex, AdvancesByDistanceScaledToTheCycle) {
  // A 2.05 m cycle: 1 m covered is half of it, i.e. half the reference cycle.
  EXPECT_NEAR(advance_posture(0, 1.025f, 2.05f), kReferenceCycleM / 2, 1e-5f);
  // Wraps around, never reaching the cycle length.
  EXPECT_NEAR(advance_posture(4.0f, 0.2f, kReferenceCycleM), 0.1f, 1e-5f);
  const float p = advance_posture(kReferenceCycleM - 1e-7f, 0, kReferenceCycleM);
  EXPECT_GE(p, 0.0f);
  EXPECT_LT(p, kReferenceCycleM);
  // Backwards distance goes back; a zero cycle leaves it.
  EXPECT_NEAR(advance_posture(0.1f, -0.2f, kReferenceCycleM), kReferenceCycleM - 0.1f, 1e-5f);
  EXPECT_NEAR(advance_posture(1.0f, 5.0f, 0.0f), 1.0f, 1e-6f);
  EXPECT_NEAR(posture_phase(2.05f), 0.5f, 1e-6f);
}

TEST(SampleGaitJob, InbetweensTheTwoNearestKeys) {
  const auto keys = gait_keys();
  GaitSample out;
  int before = -1;
  float w = -1;
  // Exactly on a key: that key, weight 0.
  ASSERT_TRUE((SampleGaitJob{keys, keys[3].gain_m, &out, &before, &w}.Run()));
  EXPECT_EQ(before, 3);
  EXPECT_NEAR(w, 0.0f, 1e-6f);
  EXPECT_NEAR(out.r_arm, keys[3].r_arm, 1e-6f);
  // A quarter of the way from key 5 to key 6.
  const float p = keys[5].gain_m + 0.25f * (keys[6].gain_m - keys[5].gain_m);
  ASSERT_TRUE((SampleGaitJob{keys, p, &out, &before, &w}.Run()));
  EXPECT_EQ(before, 5);
  EXPECT_NEAR(w, 0.25f, 1e-5f);
  EXPECT_NEAR(out.bob_walk, 0.75f * keys[5].bob_walk + 0.25f * keys[6].bob_walk, 1e-5f);
  // Past the last key: blends towards key 0 of the next cycle.
  const float last = keys.back().gain_m;
  const float q = last + 0.5f * (kReferenceCycleM - last);
  ASSERT_TRUE((SampleGaitJob{keys, q, &out, &before, &w}.Run()));
  EXPECT_EQ(before, static_cast<int>(keys.size()) - 1);
  EXPECT_NEAR(w, 0.5f, 1e-5f);
  EXPECT_NEAR(out.pelvis_twist, 0.5f * (keys.back().pelvis_twist + keys[0].pelvis_twist), 1e-5f);
}

TEST(SampleGaitJob, IsContinuousAroundTheCycle) {
  const auto keys = gait_keys();
  GaitSample a, b;
  for (float p = 0; p < kReferenceCycleM; p += 0.01f) {
    SampleGaitJob{keys, p, &a}.Run();
    SampleGaitJob{keys, p + 0.01f, &b}.Run();
    EXPECT_LT(std::fabs(a.r_arm - b.r_arm), 0.1f) << p;
    EXPECT_LT(std::fabs(a.bob_walk - b.bob_walk), 0.1f) << p;
  }
}

TEST(SampleGaitJob, RejectsTablesWithoutIncreasingGains) {
  std::vector<GaitKey> bad(gait_keys().begin(), gait_keys().end());
  bad[4].gain_m = bad[3].gain_m;
  GaitSample out;
  EXPECT_FALSE((SampleGaitJob{bad, 0, &out}.Run()));
  EXPECT_FALSE((SampleGaitJob{gait_keys(), 0, nullptr}.Validate()));
}

}  // namespace
}  // namespace mc::anim
