// anim/portable_math.hpp: close to the C library (within a few ulp in
// double, an ulp in float) over the ranges the animation uses, and the
// special cases of C's functions (signs of zero, the quadrants of atan2,
// acos at the ends, NaN). That it gives the same bits in the WebAssembly
// build is what tests/web/wasm_frames.test.mjs shows, frame by frame.
#include "anim/portable_math.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace mc::anim {
namespace {

// |a - b| in units of b's last place (double).
double ulps(double a, double b) {
  if (a == b) return 0;
  const double ulp = std::nextafter(std::fabs(b), std::numeric_limits<double>::infinity()) - std::fabs(b);
  return std::fabs(a - b) / ulp;
}

float float_ulps(float a, float b) {
  if (a == b) return 0;
  const float ulp = std::nextafter(std::fabs(b), std::numeric_limits<float>::infinity()) - std::fabs(b);
  return std::fabs(a - b) / ulp;
}

TEST(PortableMath, SinCosWithinTwoUlpOfTheCLibrary) {
  std::mt19937_64 rng(1);
  std::uniform_real_distribution<double> any(-40.0, 40.0);
  for (int i = 0; i < 200000; ++i) {
    const double x = any(rng);
    // Near a zero of sin or cos the relative error grows: compare absolutely there.
    EXPECT_LE(std::fabs(pm::sin(x) - std::sin(x)), 4e-16 * std::max(1e-3, std::fabs(std::sin(x))) + 1e-18) << x;
    EXPECT_LE(std::fabs(pm::cos(x) - std::cos(x)), 4e-16 * std::max(1e-3, std::fabs(std::cos(x))) + 1e-18) << x;
    const auto xf = static_cast<float>(x);
    ASSERT_LE(float_ulps(pm::sin(xf), std::sin(xf)), 1.0f) << xf;
    ASSERT_LE(float_ulps(pm::cos(xf), std::cos(xf)), 1.0f) << xf;
  }
  EXPECT_EQ(pm::sin(0.0), 0.0);
  EXPECT_TRUE(std::signbit(pm::sin(-0.0)));
  EXPECT_EQ(pm::cos(0.0), 1.0);
  EXPECT_TRUE(std::isnan(pm::sin(std::numeric_limits<double>::infinity())));
  EXPECT_TRUE(std::isnan(pm::cos(std::numeric_limits<double>::quiet_NaN())));
  EXPECT_NEAR(pm::sin(1e7), std::sin(1e7), 1e-6);  // far out: wrapped into one turn first
}

TEST(PortableMath, SincosIsSinAndCosBitForBit) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> any(-40.0, 40.0);
  for (int i = 0; i < 100000; ++i) {
    const double x = any(rng);
    double s = 0, c = 0;
    pm::sincos(x, s, c);
    ASSERT_EQ(s, pm::sin(x)) << x;
    ASSERT_EQ(c, pm::cos(x)) << x;
    const auto xf = static_cast<float>(x);
    float sf = 0, cf = 0;
    pm::sincos(xf, sf, cf);
    ASSERT_EQ(sf, pm::sin(xf)) << xf;
    ASSERT_EQ(cf, pm::cos(xf)) << xf;
  }
  double s = 1, c = 0;
  pm::sincos(-0.0, s, c);
  EXPECT_TRUE(std::signbit(s));
  EXPECT_EQ(c, 1.0);
}

TEST(PortableMath, Atan2WithinTwoUlpAndCsSpecialCases) {
  std::mt19937_64 rng(2);
  std::uniform_real_distribution<double> any(-100.0, 100.0);
  for (int i = 0; i < 200000; ++i) {
    const double y = any(rng), x = any(rng);
    ASSERT_LE(ulps(pm::atan2(y, x), std::atan2(y, x)), 2.0) << y << ' ' << x;
    const auto yf = static_cast<float>(y), xf = static_cast<float>(x);
    ASSERT_LE(float_ulps(pm::atan2(yf, xf), std::atan2(yf, xf)), 1.0f) << yf << ' ' << xf;
  }
  const double inf = std::numeric_limits<double>::infinity();
  for (double y : {0.0, -0.0, 1.0, -1.0, 1e-300, inf, -inf})
    for (double x : {0.0, -0.0, 1.0, -1.0, 1e300, inf, -inf}) {
      const double want = std::atan2(y, x), got = pm::atan2(y, x);
      EXPECT_LE(ulps(got, want), 1.0) << y << ' ' << x;
      EXPECT_EQ(std::signbit(got), std::signbit(want)) << y << ' ' << x;
    }
  EXPECT_TRUE(std::isnan(pm::atan2(std::nan(""), 1.0)));
}

TEST(PortableMath, AcosHypotExp2) {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> unit(-1.0, 1.0), len(-50.0, 50.0), power(-30.0, 30.0);
  for (int i = 0; i < 100000; ++i) {
    const double c = unit(rng);
    ASSERT_LE(std::fabs(pm::acos(c) - std::acos(c)), 1e-15) << c;
    ASSERT_LE(float_ulps(pm::acos(static_cast<float>(c)), std::acos(static_cast<float>(c))), 1.0f) << c;
    const double x = len(rng), y = len(rng);
    ASSERT_LE(ulps(pm::hypot(x, y), std::hypot(x, y)), 1.0) << x << ' ' << y;
    ASSERT_LE(float_ulps(pm::hypot(static_cast<float>(x), static_cast<float>(y)),
                         std::hypot(static_cast<float>(x), static_cast<float>(y))), 1.0f);
    const double e = power(rng);
    ASSERT_LE(ulps(pm::exp2(e), std::exp2(e)), 2.0) << e;
    ASSERT_LE(float_ulps(pm::exp2(static_cast<float>(e)), std::exp2(static_cast<float>(e))), 1.0f) << e;
  }
  EXPECT_EQ(pm::acos(1.0), 0.0);
  EXPECT_DOUBLE_EQ(pm::acos(-1.0), std::acos(-1.0));
  EXPECT_TRUE(std::isnan(pm::acos(1.0000001)));
  EXPECT_EQ(pm::exp2(0.0), 1.0);
  EXPECT_EQ(pm::exp2(10.0), 1024.0);
  EXPECT_EQ(pm::exp2(-3.0), 0.125);
  EXPECT_EQ(pm::hypot(3.0f, 4.0f), 5.0f);
}

}  // namespace
}  // namespace mc::anim
