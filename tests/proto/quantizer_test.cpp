#include "proto/quantizer.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/proto/support/synthetic.hpp"

namespace mc::proto {
namespace {

TEST(Quantizer, AngleGridFollowsLimitsAndErrorBudget) {
  const SkeletonDef s = testing::humanoid_skeleton();
  const Quantizer q(s);
  ASSERT_EQ(q.dof_count(), s.dof_count());
  // The knee is [-150, 0]: 150 / 0.99 = 151.5 -> 153 points.
  const int knee = 27;  // l_knee's only dof
  EXPECT_EQ(q.grid(knee).lo_mdeg, -150000);
  EXPECT_EQ(q.grid(knee).steps, 153);
  EXPECT_EQ(q.grid(knee).bits, 8);
  for (int d = 0; d < q.dof_count(); ++d) {
    const auto& g = q.grid(d);
    for (double a = g.lo_mdeg / 1000.0; a <= g.hi_mdeg / 1000.0; a += 0.0137) {
      const float back = q.angle_value(d, q.angle_q(d, static_cast<float>(a)));
      ASSERT_LE(std::abs(back - a), 0.495 + 1e-4) << "dof " << d << " angle " << a;
    }
  }
}

TEST(Quantizer, OutOfRangeAnglesClampToTheLimit) {
  const Quantizer q(testing::humanoid_skeleton());
  EXPECT_EQ(q.angle_value(27, q.angle_q(27, 50.0f)), 0.0f);
  EXPECT_EQ(q.angle_value(27, q.angle_q(27, -500.0f)), -150.0f);
  EXPECT_EQ(q.angle_q(27, std::nanf("")), 0);
}

TEST(Quantizer, PositionsAreCentimetresAndHeadingWraps) {
  EXPECT_EQ(Quantizer::position_q(1.234f), 123);
  EXPECT_EQ(Quantizer::position_q(-52.5f), -5250);
  EXPECT_EQ(Quantizer::position_q(1e9f), kPositionMax);
  EXPECT_EQ(Quantizer::heading_q(0.0f), 0);
  EXPECT_EQ(Quantizer::heading_q(-0.9f), 363);
  EXPECT_EQ(Quantizer::heading_q(180.0f), 182);
  EXPECT_EQ(Quantizer::heading_q(-180.0f), 182);
  EXPECT_FLOAT_EQ(Quantizer::heading_value(182), 180.0f);
  EXPECT_NEAR(Quantizer::heading_value(363), -360.0 / 364, 1e-5);
  for (double h = -180; h <= 180; h += 0.31) {
    const double back = Quantizer::heading_value(Quantizer::heading_q(static_cast<float>(h)));
    double diff = std::fmod(std::abs(back - h), 360.0);
    if (diff > 180) diff = 360 - diff;
    ASSERT_LE(diff, 0.495 + 1e-4) << h;
  }
}

TEST(Quantizer, FingerprintChangesWithTheSkeleton) {
  SkeletonDef s = testing::humanoid_skeleton();
  const std::uint32_t a = Quantizer(s).fingerprint();
  EXPECT_EQ(a, Quantizer(s).fingerprint());
  s.joints[1].limits[0][0] = -46;
  EXPECT_NE(a, Quantizer(s).fingerprint());
}

}  // namespace
}  // namespace mc::proto
