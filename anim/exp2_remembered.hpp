// 2^x remembered per thread, for the smoothing factors 2^(-dt / tau).
//
// Each frame of each player smooths a few figures (the footsteps' speed
// and run, the upper body's inertialization) by factors 2^(-dt / tau):
// a handful of fixed time constants at the stream's one frame time, so the
// same few arguments every time. pm::exp2 is a 13-term series in double,
// and in those chains its latency showed. A tiny direct-mapped table per
// thread, keyed by the argument's bits: a hit is exactly pm::exp2(x), so
// the frames do not change (anim_sincos_deg_test holds it to that).
#pragma once

#include <array>
#include <cstdint>
#include <cstring>

#include "anim/portable_math.hpp"

namespace mc::anim {

inline float exp2_remembered(float x) {
  struct Entry {
    bool set = false;
    std::uint32_t bits = 0;
    float value = 1;
  };
  constexpr unsigned kBits = 4;
  thread_local std::array<Entry, 1u << kBits> table{};
  std::uint32_t bits = 0;
  std::memcpy(&bits, &x, sizeof bits);
  Entry& e = table[(bits * 2654435761u) >> (32 - kBits)];
  if (!e.set || e.bits != bits) {
    e.set = true;
    e.bits = bits;
    e.value = pm::exp2(x);
  }
  return e.value;
}

}  // namespace mc::anim
