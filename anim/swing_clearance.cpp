#include "anim/swing_clearance.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

// The foot's box (human_skeleton.cpp): its centre and half sides, in the
// foot joint's space (X forward, Y up).
const glm::vec3 kFootCentre((dims::kFootFront - dims::kFootBack) / 2, -dims::kAnkleHeight / 2, 0);
const glm::vec3 kFootHalf(0.5f * (dims::kFootFront + dims::kFootBack), 0.5f * dims::kAnkleHeight, 0.05f);

}  // namespace

bool may_skim(float ankle_height, float travel_m) {
  static const float reach = glm::length(kFootCentre) + glm::length(kFootHalf);
  return travel_m > kSkimStepM && ankle_height - reach < kSwingClearM;
}

float swing_lift(float ankle_height, float pitch_deg) {
  // Pitched about Z, the box's X axis leans up by sin, its Y axis by cos
  // (Z stays level): the lowest corner is the centre's height less each
  // half side times its axis's lean.
  float s, c;
  pm::sincos(pitch_deg * kDeg, s, c);
  const float sole = ankle_height + kFootCentre.x * s + kFootCentre.y * c - kFootHalf.x * std::fabs(s) -
                     kFootHalf.y * std::fabs(c);
  return std::max(0.0f, kSwingClearM - sole);
}

}  // namespace mc::anim
