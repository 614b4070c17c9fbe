// Small synthetic clips whose answers are known, shared by the mocap tests.
#pragma once

#include <cmath>
#include <numbers>

#include "anim/mocap/mocap_clip.hpp"

namespace mc::anim::mocap::test {

// A walker at 30 Hz: root at 1 m height moving `speed` m/s along its facing,
// turning `turn_deg_per_s` to the RIGHT, legs swinging with period `period`
// frames (left and right in antiphase). Left hip at +X at rest (faces +Z).
inline MocapClip synthetic_walker(int frames, int period, float speed = 1.0f, float turn_deg_per_s = 0,
                                  float swing_deg = 30) {
  MocapClip c;
  c.name = "synthetic";
  c.skeleton.names = {"Hips", "LeftUpLeg", "LeftLeg", "LeftFoot", "RightUpLeg", "RightLeg", "RightFoot", "Head"};
  c.skeleton.parents = {-1, 0, 1, 2, 0, 4, 5, 0};
  c.skeleton.offsets = {glm::vec3(0), glm::vec3(0.1f, -0.1f, 0), glm::vec3(0, -0.45f, 0), glm::vec3(0, -0.45f, 0),
                        glm::vec3(-0.1f, -0.1f, 0), glm::vec3(0, -0.45f, 0), glm::vec3(0, -0.45f, 0),
                        glm::vec3(0, 0.6f, 0)};
  c.skeleton.end_site.assign(8, false);
  c.frame_time = 1.0 / 30;
  c.frames = frames;
  glm::vec3 pos(0, 1, 0);
  float yaw = 0;  // rad about +Y; turning right is negative
  for (int f = 0; f < frames; ++f) {
    const glm::quat root = glm::angleAxis(yaw, glm::vec3(0, 1, 0));
    c.root_position.push_back(pos);
    const float ph = static_cast<float>(2 * std::numbers::pi * f / period);
    const float s = glm::radians(swing_deg) * std::sin(ph);
    const glm::quat l = glm::angleAxis(-s, glm::vec3(1, 0, 0)), r = glm::angleAxis(s, glm::vec3(1, 0, 0));
    const glm::quat id(1, 0, 0, 0);
    const glm::quat knee = glm::angleAxis(0.3f * (1 + std::cos(ph)), glm::vec3(1, 0, 0));
    for (const glm::quat& q : {root, l, knee, id, r, knee, id, id}) c.local.push_back(q);
    const glm::vec3 fwd = root * glm::vec3(0, 0, 1);
    pos += fwd * (speed / 30.0f);
    yaw -= glm::radians(turn_deg_per_s) / 30.0f;
  }
  return c;
}

}  // namespace mc::anim::mocap::test
