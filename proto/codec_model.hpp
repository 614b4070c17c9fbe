// The state that FrameEncoder and FrameDecoder keep in lockstep: the two
// previous quantized frames (for prediction) and the adaptive Rice contexts.
// Both reset it at every keyframe, so a decoder that starts at any keyframe
// rebuilds exactly the encoder's state. Internal to proto/.
#pragma once

#include <algorithm>
#include <array>
#include <cstdint>

#include "proto/bit_io.hpp"
#include "proto/quantizer.hpp"

namespace mc::proto::detail {

struct CodecModel {
  RiceContext ball_xy, ball_z, pos_xy, pos_z, heading;
  std::array<RiceContext, kMaxDof> angle;
  QuantFrame prev, prev2;  // the last and second-to-last frames, as decoded
  int history = 0;         // how many of prev, prev2 are valid (0..2)

  void start_keyframe(const QuantFrame& key) {
    for (RiceContext* c : {&ball_xy, &ball_z, &pos_xy, &pos_z, &heading}) c->reset();
    for (auto& c : angle) c.reset();
    prev = key;
    history = 1;
  }
  void push(const QuantFrame& f) {
    prev2 = prev;
    prev = f;
    history = std::min(history + 1, 2);
  }

  // Linear extrapolation from the two previous frames (constant velocity);
  // right after a keyframe only one frame is known, so hold it.
  std::int64_t extrapolate(std::int32_t a1, std::int32_t a0) const {
    return history >= 2 ? 2 * static_cast<std::int64_t>(a1) - a0 : a1;
  }
  std::int32_t predict(std::int32_t a1, std::int32_t a0, std::int32_t lo, std::int32_t hi) const {
    return static_cast<std::int32_t>(std::clamp<std::int64_t>(extrapolate(a1, a0), lo, hi));
  }
  // Heading lives on a circle of kHeadingSteps: extrapolate the wrapped turn.
  std::int32_t predict_heading(std::int32_t a1, std::int32_t a0) const {
    if (history < 2) return a1;
    return wrap(a1 + wrap_signed(a1 - a0));
  }
  static std::int32_t wrap(std::int64_t v) {
    const std::int64_t m = v % kHeadingSteps;
    return static_cast<std::int32_t>(m < 0 ? m + kHeadingSteps : m);
  }
  // In [-200, 199].
  static std::int32_t wrap_signed(std::int64_t v) {
    return wrap(v + kHeadingSteps / 2) - kHeadingSteps / 2;
  }
};

}  // namespace mc::proto::detail
