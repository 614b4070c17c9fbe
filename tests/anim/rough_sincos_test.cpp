// anim/rough_sincos.hpp: the gates' quick sine and cosine are within 3e-7
// of the true ones over every angle a joint takes and far beyond it, in
// every quadrant and at the quadrants' edges; out of range they are NaN,
// which sends a gate to the exact figure.
#include "anim/rough_sincos.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

constexpr double kBound = 3e-7;

// The largest error of either against sin and cos of `deg` taken in double.
double error_at(float deg) {
  float s = 0, c = 0;
  rough_sincos_deg(deg, s, c);
  double ws = 0, wc = 0;
  pm::sincos(static_cast<double>(deg) * 0.017453292519943295769, ws, wc);
  return std::max(std::fabs(s - ws), std::fabs(c - wc));
}

TEST(RoughSincos, WithinItsBoundOverManyTurns) {
  std::mt19937 rng(39);
  std::uniform_real_distribution<float> deg(-1080.0f, 1080.0f);
  double worst = 0;
  for (int i = 0; i < 200000; ++i) worst = std::max(worst, error_at(deg(rng)));
  EXPECT_LT(worst, kBound);
  EXPECT_GT(worst, 0.0);  // a quick one: not the exact bits everywhere
}

TEST(RoughSincos, WithinItsBoundAtEveryQuadrantsEdgeAndOnTheAxes) {
  for (int q = -12; q <= 12; ++q) {
    for (const float edge : {45.0f * static_cast<float>(q), 90.0f * static_cast<float>(q)}) {
      float at = edge;
      for (int k = 0; k < 64; ++k) at = std::nextafter(at, INFINITY);
      for (int k = 0; k < 128; ++k) {
        EXPECT_LT(error_at(at), kBound) << at;
        at = std::nextafter(at, -INFINITY);
      }
    }
  }
  float s = 1, c = 0;
  rough_sincos_deg(0.0f, s, c);
  EXPECT_EQ(s, 0.0f);
  EXPECT_EQ(c, 1.0f);
  rough_sincos_deg(-90.0f, s, c);
  EXPECT_NEAR(s, -1.0f, kBound);
  EXPECT_NEAR(c, 0.0f, kBound);
  rough_sincos_deg(180.0f, s, c);
  EXPECT_NEAR(s, 0.0f, kBound);
  EXPECT_NEAR(c, -1.0f, kBound);
}

TEST(RoughSincos, OutOfRangeIsNaN) {
  for (const float deg : {1e6f, -1e6f, 3e9f, std::numeric_limits<float>::infinity(),
                          -std::numeric_limits<float>::infinity(), std::numeric_limits<float>::quiet_NaN()}) {
    float s = 0, c = 0;
    rough_sincos_deg(deg, s, c);
    EXPECT_TRUE(std::isnan(s) && std::isnan(c)) << deg;
  }
  float s = 0, c = 0;
  rough_sincos_deg(999999.0f, s, c);
  EXPECT_NEAR(s * s + c * c, 1.0f, 1e-6f);
}

}  // namespace
}  // namespace mc::anim
