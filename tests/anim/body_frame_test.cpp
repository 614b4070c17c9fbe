// anim/body_frame.hpp's remainder_360: std::remainder(a, 360) to the bit
// (the sign of a zero, the tie at +-540, NaN and infinities included), as
// the clients' step and the drawn-leg check took it before (their frames
// must not change).
#include "anim/body_frame.hpp"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>

namespace mc::anim {
namespace {

void expect_library_bits(float a) {
  const float want = std::remainder(a, 360.0f), got = remainder_360(a);
  if (std::isnan(want)) {
    EXPECT_TRUE(std::isnan(got)) << a;
    return;
  }
  EXPECT_EQ(std::bit_cast<std::uint32_t>(got), std::bit_cast<std::uint32_t>(want)) << a;
}

TEST(Remainder360, TheLibrarysBitsOverEveryTurnTheAnimationMakes) {
  std::mt19937 rng(38);
  std::uniform_real_distribution<float> turn(-1000.0f, 1000.0f);
  for (int i = 0; i < 200000; ++i) expect_library_bits(turn(rng));
  // Every float near the edges of the fast path, both signs.
  for (float edge : {0.0f, 180.0f, 360.0f, 540.0f}) {
    float below = edge, above = edge;
    for (int k = 0; k < 64; ++k) {
      for (float v : {below, above, -below, -above}) expect_library_bits(v);
      below = std::nextafter(below, -1.0f);
      above = std::nextafter(above, 1e9f);
    }
  }
}

TEST(Remainder360, ZerosTiesAndWhatIsNotANumber) {
  for (float v : {0.0f, -0.0f, 180.0f, -180.0f, 360.0f, -360.0f, 540.0f, -540.0f, 720.0f, -720.0f, 1e7f,
                  std::numeric_limits<float>::quiet_NaN(), std::numeric_limits<float>::infinity(),
                  -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::denorm_min()})
    expect_library_bits(v);
  EXPECT_TRUE(std::signbit(remainder_360(-360.0f)));  // a zero takes a's sign
  EXPECT_EQ(remainder_360(540.0f), -180.0f);          // the tie goes to the even multiple
}

}  // namespace
}  // namespace mc::anim
