#include "anim/locomotion.hpp"

#include <gtest/gtest.h>

namespace mc::anim {
namespace {

TEST(Locomotion, StepLengthGrowsWithSpeed) {
  float last = 0;
  for (float v = 0; v <= 11.0f; v += 0.25f) {
    const float l = human_step_length(v);
    EXPECT_GT(l, last);
    last = l;
  }
}

}  // namespace
}  // namespace mc::anim
