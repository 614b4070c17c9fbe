// anim/sincos_deg.hpp: what the table gives is what pm::sincos(deg * kDeg)
// gives, to the bit, whether the angle was there (a hit), was not (a
// miss), or was pushed out by another angle of the same slot; with the
// sign of zero, NaN and angles far out. The callers that took
// pm::sincos(x * kDeg) before (the body frame, the planted foot, the
// grass checks) rely on that: the frames must not change. The same for
// exp2_remembered.hpp against pm::exp2.
#include "anim/sincos_deg.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <vector>

#include "anim/body_frame.hpp"
#include "anim/exp2_remembered.hpp"

namespace mc::anim {
namespace {

// sincos_deg against pm::sincos(deg * kDeg), bit for bit (NaN as NaN).
void expect_exact(float deg) {
  float s = 0, c = 0, ws = 0, wc = 0;
  sincos_deg(deg, s, c);
  pm::sincos(deg * kDeg, ws, wc);
  if (std::isnan(ws)) {
    EXPECT_TRUE(std::isnan(s) && std::isnan(c)) << deg;
    return;
  }
  EXPECT_EQ(std::bit_cast<std::uint32_t>(s), std::bit_cast<std::uint32_t>(ws)) << deg;
  EXPECT_EQ(std::bit_cast<std::uint32_t>(c), std::bit_cast<std::uint32_t>(wc)) << deg;
}

TEST(SincosDeg, ItsRadianIsTheBodyFramesDegree) {
  // The table turns degrees into radians with its own constant; the callers
  // it replaced multiplied by kDeg. The same float, or the frames move.
  EXPECT_EQ(std::bit_cast<std::uint32_t>(kDeg), std::bit_cast<std::uint32_t>(0.017453292519943295f));
}

TEST(SincosDeg, HitsMissesAndEvictionsGiveThePortableBits) {
  std::mt19937 rng(23);
  std::uniform_real_distribution<float> joint(-180.0f, 180.0f);
  std::vector<float> angles;
  for (int i = 0; i < 5000; ++i) angles.push_back(joint(rng));
  // First sight (misses), then again in the same order (hits for those
  // still in the table, misses for those another angle pushed out), then
  // in reverse order.
  for (float a : angles) expect_exact(a);
  for (float a : angles) expect_exact(a);
  for (auto it = angles.rbegin(); it != angles.rend(); ++it) expect_exact(*it);
}

TEST(SincosDeg, ZerosNanAndFarAngles) {
  for (int round = 0; round < 2; ++round) {  // a miss, then a hit
    for (float a : {0.0f, -0.0f, 45.0f, -45.0f, 90.0f, 180.0f, -180.0f, 360.0f, 720.5f, -1e5f, 1e7f,
                    std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity()})
      expect_exact(a);
  }
  float s = 1, c = 0;
  sincos_deg(-0.0f, s, c);
  EXPECT_TRUE(std::signbit(s));  // keeps the sign of zero, as pm::sincos does
  EXPECT_EQ(c, 1.0f);
}

TEST(Exp2Remembered, IsPmExp2ToTheBitOnHitsMissesAndEvictions) {
  // The smoothing factors 2^(-dt / tau) come from a small table
  // (exp2_remembered.hpp): first sightings, repeats, and arguments that
  // push each other out of a slot all give pm::exp2's own bits.
  std::vector<float> args = {-0.625f, -1.25f, -0.5f, -0.41666666f, -1.0f, 0.0f, -0.0f, 3.5f, -149.0f, 128.0f};
  std::mt19937 rng(40);
  std::uniform_real_distribution<float> x(-20.0f, 20.0f);
  for (int i = 0; i < 200; ++i) args.push_back(x(rng));  // more than the table holds: evictions
  for (int round = 0; round < 3; ++round)
    for (const float a : args)
      EXPECT_EQ(std::bit_cast<std::uint32_t>(exp2_remembered(a)), std::bit_cast<std::uint32_t>(pm::exp2(a))) << a;
  EXPECT_TRUE(std::isnan(exp2_remembered(NAN)));
  EXPECT_EQ(exp2_remembered(-INFINITY), pm::exp2(-INFINITY));
}

}  // namespace
}  // namespace mc::anim
