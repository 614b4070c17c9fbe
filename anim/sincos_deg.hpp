// sin and cos of an angle in degrees, remembered per thread.
//
// One frame of one player evaluates the same angles many times over: the
// legs' solver, the hands' clearance, the grass check and the speed limit
// all run forward kinematics on them, and a planted foot's yaw and pitch,
// or a player's heading, stay the same from frame to frame. pm::sincos is
// most of a joint's rotation. A small direct-mapped table per thread, keyed
// by the angle's bits: a hit gives exactly what pm::sincos(deg * kDeg)
// would, so the frames do not change (anim_sincos_deg_test holds it to
// that). Zeroed entries hold +0 degrees, whose sine and cosine are 0 and 1.
#pragma once

#include <array>
#include <cstdint>
#include <cstring>

#include "anim/portable_math.hpp"

namespace mc::anim {

inline void sincos_deg(float deg, float& s, float& c) {
  struct Entry {
    std::uint32_t bits = 0;
    float s = 0, c = 1;
  };
  // pi / 180 rounded to float: the same bits as body_frame.hpp's kDeg.
  constexpr float kDegToRad = 0.017453292519943295f;
  constexpr unsigned kBits = 10;
  thread_local std::array<Entry, 1u << kBits> table{};
  std::uint32_t bits = 0;
  std::memcpy(&bits, &deg, sizeof bits);
  Entry& e = table[(bits * 2654435761u) >> (32 - kBits)];
  if (e.bits != bits) {
    e.bits = bits;
    pm::sincos(deg * kDegToRad, e.s, e.c);
  }
  s = e.s;
  c = e.c;
}

}  // namespace mc::anim
