// Closest points of two line segments (Ericson, Real-Time Collision
// Detection, 5.1.9): how near two limbs' centre lines come. Used to keep the
// legs apart in the animator (limb_clearance.cpp) and in the clients' blend
// (leg_blend.cpp), and by anim-quality to measure it, so that all three
// agree on what "too close" is.
#pragma once

#include <algorithm>

#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

namespace mc::anim {

struct ClosestPoints {
  float distance = 0;
  glm::vec3 on_first{0.0f}, on_second{0.0f};
};

inline ClosestPoints closest_points(glm::vec3 p1, glm::vec3 q1, glm::vec3 p2, glm::vec3 q2) {
  const glm::vec3 d1 = q1 - p1, d2 = q2 - p2, r = p1 - p2;
  const float a = glm::dot(d1, d1), e = glm::dot(d2, d2), f = glm::dot(d2, r);
  float s = 0, t = 0;
  if (a <= 1e-9f && e > 1e-9f) {
    t = std::clamp(f / e, 0.0f, 1.0f);
  } else if (a > 1e-9f) {
    const float c = glm::dot(d1, r);
    if (e <= 1e-9f) {
      s = std::clamp(-c / a, 0.0f, 1.0f);
    } else {
      const float b = glm::dot(d1, d2), denom = a * e - b * b;
      s = denom > 1e-9f ? std::clamp((b * f - c * e) / denom, 0.0f, 1.0f) : 0.0f;
      t = (b * s + f) / e;
      if (t < 0) {
        t = 0;
        s = std::clamp(-c / a, 0.0f, 1.0f);
      } else if (t > 1) {
        t = 1;
        s = std::clamp((b - c) / a, 0.0f, 1.0f);
      }
    }
  }
  ClosestPoints out;
  out.on_first = p1 + d1 * s;
  out.on_second = p2 + d2 * t;
  out.distance = glm::length(out.on_first - out.on_second);
  return out;
}

inline float segment_distance(glm::vec3 p1, glm::vec3 q1, glm::vec3 p2, glm::vec3 q2) {
  return closest_points(p1, q1, p2, q2).distance;
}

}  // namespace mc::anim
