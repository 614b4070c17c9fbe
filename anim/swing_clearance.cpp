#include "anim/swing_clearance.hpp"

#include <algorithm>
#include <cmath>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/portable_math.hpp"
#include "anim/sincos_deg.hpp"

namespace mc::anim {
namespace {

// The foot's box, as human_skeleton() defines it: its centre and half
// sides, in the foot joint's space (X forward, Y up).
struct FootBox {
  glm::vec3 centre, half;
};
const FootBox& foot_box() {
  static const FootBox box = [] {
    const Segment& sg = human_skeleton().joints[kRFoot].segment;
    return FootBox{glm::vec3(sg.center[0], sg.center[1], sg.center[2]),
                   0.5f * glm::vec3(sg.size[0], sg.size[1], sg.size[2])};
  }();
  return box;
}

}  // namespace

float swing_clear(float travel_m, float root_m) {
  if (!(travel_m > kSkimStepM)) return 0.0f;
  return std::clamp(kSwingClearPerM * std::min(travel_m, kSwingTravelPerRoot * root_m), kSwingClearM, kSwingClearMaxM);
}

bool may_skim(float ankle_height, float travel_m, float clear_m) {
  static const float reach = glm::length(foot_box().centre) + glm::length(foot_box().half);
  return travel_m > kSkimStepM && ankle_height - reach < clear_m;
}

float swing_lift(float ankle_height, float pitch_deg, float clear_m) {
  // Pitched about Z, the box's X axis leans up by sin, its Y axis by cos
  // (Z stays level): the lowest corner is the centre's height less each
  // half side times its axis's lean.
  float s, c;
  sincos_deg(pitch_deg, s, c);
  const FootBox& box = foot_box();
  const float sole = ankle_height + box.centre.x * s + box.centre.y * c - box.half.x * std::fabs(s) - box.half.y * std::fabs(c);
  return std::max(0.0f, clear_m - sole);
}

}  // namespace mc::anim
