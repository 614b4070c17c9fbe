#include "anim/classifier.hpp"

#include <vector>

#include <gtest/gtest.h>

namespace mc::anim {
namespace {

TEST(SmoothAction, OneNoisyCycleDoesNotFlipTheDecision) {
  const std::vector<Action> w{Action::Walk, Action::Run, Action::Walk};
  EXPECT_EQ(smooth_action(w, 1), Action::Walk);
  const std::vector<Action> k{Action::Walk, Action::Kick, Action::Walk};
  EXPECT_EQ(smooth_action(k, 1), Action::Kick);
}

}  // namespace
}  // namespace mc::anim
