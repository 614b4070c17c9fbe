#include "anim/gait_timing.hpp"

#include <algorithm>
#include <array>
#include <cstddef>

namespace mc::anim {
namespace {

// Speed (m/s) -> step length (m), cadence = speed / step length.
constexpr std::array<float, 12> kV{0.0f, 0.3f, 0.6f, 1.0f, 1.5f, 2.0f, 2.5f, 3.5f, 5.2f, 7.0f, 8.95f, 11.0f};
constexpr std::array<float, 12> kStep{0.20f, 0.24f, 0.38f, 0.55f, 0.72f, 0.85f, 0.95f, 1.25f, 1.65f, 1.95f, 2.05f, 2.50f};
// Duty factor: a foot's share of the stride on the ground.
constexpr std::array<float, 12> kDuty{0.72f, 0.70f, 0.67f, 0.64f, 0.61f, 0.59f, 0.42f, 0.37f, 0.29f, 0.25f, 0.23f, 0.21f};

float interp(const std::array<float, 12>& y, float v) {
  if (v <= kV[0]) return y[0];
  for (std::size_t i = 1; i < kV.size(); ++i)
    if (v <= kV[i]) return y[i - 1] + (y[i] - y[i - 1]) * (v - kV[i - 1]) / (kV[i] - kV[i - 1]);
  return y.back();
}

}  // namespace

float gait_step_length(float v) {
  if (v > kV.back()) return kStep.back() * v / kV.back();
  return interp(kStep, v);
}

GaitTiming human_gait(float v, float cadence_cap, float stamina) {
  GaitTiming g;
  v = std::max(v, 0.0f);
  const float tired = 0.85f + 0.15f * std::clamp(stamina, 0.0f, 1.0f);
  g.step_length = gait_step_length(v) * tired;
  // Below a shuffle the cadence does not fall further: settling steps.
  g.cadence = std::max(v / g.step_length, 1.3f);
  if (g.cadence > cadence_cap) {
    g.cadence = cadence_cap;
    g.step_length = v / cadence_cap;
  }
  g.duty = interp(kDuty, v);
  g.run = std::clamp((v - 2.0f) / 0.5f, 0.0f, 1.0f);
  g.stance_s = 2.0f * g.duty / g.cadence;
  g.swing_s = 2.0f / g.cadence - g.stance_s;
  return g;
}

}  // namespace mc::anim
