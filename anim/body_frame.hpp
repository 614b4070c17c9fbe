// Small helpers between field space and a player's body space.
//
// Field space: rcssserver's (x, y) in metres, angles in degrees from +x
// towards +y, plus a height h above the grass. Body space (model space,
// proto/skeleton.hpp): X forward along the heading, Y up, Z to the right.
// Because the field's +y side is the right of a player facing +x, a field
// angle a maps to the body yaw -a (the body's yaw grows to the left).
#pragma once

#include <cmath>

#include "anim/portable_math.hpp"
#include "anim/sincos_deg.hpp"

namespace mc::anim {

inline constexpr float kPi = 3.14159265358979f;
inline constexpr float kDeg = kPi / 180.0f;

// Angle wrapped into [-180, 180). Most angles are in range already, and
// then fmod(a + 180, 360) is a + 180 itself: the same result without the
// library call (1.3 % of the animation's instructions).
inline float wrap_deg(float a) {
  const float shifted = a + 180.0f;
  if (shifted >= 0.0f && shifted < 360.0f) return shifted - 180.0f;
  a = std::fmod(shifted, 360.0f);
  if (a < 0) a += 360.0f;
  return a - 180.0f;
}

// std::remainder(a, 360), the same bits, without the library call for the
// angles the animation turns by: a in [-180, 180] is its own remainder, and
// a in (180, 540) or (-540, -180) is a -/+ 360, exactly (the remainder is
// representable and 360 a multiple of a's last place there). +-360 (whose
// zero takes a's sign) and the rest go to the library. The legs' turns in
// the clients' step took 1 % of the animation's instructions in it.
inline float remainder_360(float a) {
  const float m = std::fabs(a);
  if (m <= 180.0f) return a;
  if (m < 540.0f && m != 360.0f) return a > 0.0f ? a - 360.0f : a + 360.0f;
  return std::remainder(a, 360.0f);
}

// Shortest signed difference a - b, degrees.
inline float delta_deg(float a, float b) { return wrap_deg(a - b); }

// Interpolates angles along the shorter arc.
inline float lerp_deg(float a, float b, float t) { return wrap_deg(a + delta_deg(b, a) * t); }

inline float clampf(float v, float lo, float hi) { return v < lo ? lo : (v > hi ? hi : v); }

inline float smoothstep(float t) {
  t = clampf(t, 0.0f, 1.0f);
  return t * t * (3.0f - 2.0f * t);
}

// A player's body frame on the field: origin under the pelvis, heading in
// field degrees.
struct BodyFrame {
  float x = 0, y = 0;      // field m
  float heading = 0;       // field deg
  float c = 1, s = 0;      // cos/sin of heading

  BodyFrame() = default;
  BodyFrame(float px, float py, float heading_deg) : x(px), y(py), heading(heading_deg) {
    sincos_deg(heading_deg, s, c);
  }

  // Field point (fx, fy) -> body (forward X, right Z).
  void to_body(float fx, float fy, float& bx, float& bz) const {
    const float dx = fx - x, dy = fy - y;
    bx = dx * c + dy * s;
    bz = -dx * s + dy * c;
  }
  // Body (forward X, right Z) -> field point.
  void to_field(float bx, float bz, float& fx, float& fy) const {
    fx = x + bx * c - bz * s;
    fy = y + bx * s + bz * c;
  }
  // Field direction (dx, dy) -> body direction.
  void dir_to_body(float dx, float dy, float& bx, float& bz) const {
    bx = dx * c + dy * s;
    bz = -dx * s + dy * c;
  }
};

}  // namespace mc::anim
