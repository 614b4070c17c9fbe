#include "anim/locomotion.hpp"

#include <cmath>
#include <vector>

#include <gtest/gtest.h>

#include "anim/body_frame.hpp"

namespace mc::anim {
namespace {

struct Trip {
  int touchdowns = 0;
  double max_planted_drift = 0;  // m a planted foot moved on the grass
  std::vector<float> touchdown_times;
};

// Drives one player along +x: `speed_of(frame)` m/s, 20 frames per second.
template <class SpeedFn>
Trip drive(LocomotionState& s, int frames, SpeedFn speed_of, float stamina = 1, LocomotionOutput* last = nullptr) {
  Trip r;
  LocomotionParams prm;
  float x = s.initialized ? s.x : 0;
  if (!s.initialized) {  // put the feet down where the player stands first
    LocomotionInput in;
    LocomotionOutput out;
    step_locomotion(s, in, prm, out);
  }
  FootState before[2] = {s.feet[0], s.feet[1]};
  for (int f = 0; f < frames; ++f) {
    const float v = speed_of(f);
    x += v * 0.05f;
    LocomotionInput in;
    in.x = x;
    in.heading = 0;
    in.move_dx = v > 0 ? 1.0f : 0.0f;
    in.rest = v < 0.3f;
    in.stamina = stamina;
    LocomotionOutput out;
    step_locomotion(s, in, prm, out);
    for (int i = 0; i < 2; ++i) {
      if (s.feet[i].planted && before[i].planted)
        r.max_planted_drift = std::max(r.max_planted_drift,
                                       static_cast<double>(std::hypot(s.feet[i].x - before[i].x, s.feet[i].y - before[i].y)));
      if (s.feet[i].planted && !before[i].planted) { ++r.touchdowns; r.touchdown_times.push_back(0.05f * static_cast<float>(f)); }
      before[i] = s.feet[i];
    }
    if (last != nullptr) *last = out;
  }
  return r;
}

TEST(Locomotion, StepLengthGrowsWithSpeed) {
  float last = 0;
  for (float v = 0; v <= 11.0f; v += 0.25f) {
    const float l = human_step_length(v);
    EXPECT_GT(l, last);
    last = l;
  }
}

TEST(Locomotion, PlantedFeetDoNotSlide) {
  LocomotionState s;
  const Trip r = drive(s, 200, [](int) { return 5.0f; });
  EXPECT_GT(r.touchdowns, 20);
  EXPECT_EQ(r.max_planted_drift, 0.0);
}

TEST(Locomotion, CadenceStaysHumanAtTopSpeed) {
  for (float v : {3.0f, 7.0f, 10.5f}) {
    LocomotionState s;
    const Trip r = drive(s, 400, [v](int) { return v; });
    // Over any three touch-downs (a stride), at most 4.5 steps per second.
    for (std::size_t i = 2; i < r.touchdown_times.size(); ++i)
      EXPECT_LE(2.0f / (r.touchdown_times[i] - r.touchdown_times[i - 2]), 4.5f + 1e-3f) << v;
    // At top speed the stride grew instead: about 2 m per step or more.
    if (v > 10) {
      EXPECT_GT(s.cycle_m, 4.0f);
    }
  }
}

TEST(Locomotion, ComesToAStandstillWithBothFeetDown) {
  LocomotionState s;
  LocomotionOutput out;
  drive(s, 60, [](int) { return 4.0f; });
  drive(s, 60, [](int) { return 0.0f; }, 1, &out);
  ASSERT_TRUE(s.feet[0].planted);
  ASSERT_TRUE(s.feet[1].planted);
  EXPECT_TRUE(out.planted[0] && out.planted[1]);
  // Under the hips, on their own sides, and no more steps.
  const BodyFrame body(s.x, s.y, 0);
  for (int i = 0; i < 2; ++i) {
    float bx, bz;
    body.to_body(s.feet[i].x, s.feet[i].y, bx, bz);
    EXPECT_LT(std::fabs(bx), 0.1f);
    EXPECT_NEAR(bz, i == 0 ? 0.11f : -0.11f, 0.08f);
  }
  const float posture = s.posture_m;
  const Trip still = drive(s, 40, [](int) { return 0.0f; });
  EXPECT_EQ(still.touchdowns, 0);
  EXPECT_EQ(s.posture_m, posture);
}

TEST(Locomotion, TiredPlayersTakeShorterStridesAndRunLower) {
  LocomotionState fresh, tired;
  LocomotionOutput a, b;
  drive(fresh, 80, [](int) { return 6.0f; }, 1.0f, &a);
  drive(tired, 80, [](int) { return 6.0f; }, 0.1f, &b);
  EXPECT_LT(tired.cycle_m, fresh.cycle_m);
}

TEST(Locomotion, PostureIndexAdvancesWithDistance) {
  LocomotionState s;
  drive(s, 1, [](int) { return 0.0f; });
  const float p0 = s.posture_m;
  drive(s, 1, [](int) { return 4.0f; });  // 0.2 m covered
  const float expected = advance_posture(p0, 0.2f, s.cycle_m);
  EXPECT_NEAR(s.posture_m, expected, 0.05f);  // (plus at most a small phase correction)
  EXPECT_NE(s.posture_m, p0);
}

}  // namespace
}  // namespace mc::anim
