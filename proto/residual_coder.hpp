// How one signed integer (a prediction residual, or a keyframe value) is
// turned into binary decisions for the range coder, with adaptive contexts.
// SPEC.md section 4.3 "Signed values" is the normative description.
//
//   zero?      1 bit, context zero[ctx]                     (ctx: 0..7)
//   sign       1 bit, context sign[act]                     (1 = negative)
//   bucket b   = floor(log2 |v|), in unary: b one-bits then a zero-bit
//              (no zero-bit when b = 31), bit i in context bucket[act][min(i, 23)]
//   mantissa   the b bits of |v| below its leading one, most significant
//              first: the first in context mant[act][min(b, 23)], the rest direct.
//
// `act` (0..3) is an activity class, `ctx` a zero context chosen by the
// caller from what both sides already know (see frame_codec.hpp).
#pragma once

#include <array>
#include <cstdint>

#include "proto/range_coder.hpp"

namespace mc::proto {

inline constexpr int kActivityClasses = 4;
inline constexpr int kZeroContexts = 8;
inline constexpr int kBucketContexts = 24;

// Activity class of a magnitude: 0 -> 0, 1 -> 1, 2..4 -> 2, 5+ -> 3.
inline int activity_class(std::int64_t value) {
  const std::int64_t m = value < 0 ? -value : value;
  return m == 0 ? 0 : m == 1 ? 1 : m <= 4 ? 2 : 3;
}

struct SignedModel {
  std::array<Prob, kZeroContexts> zero;
  std::array<Prob, kActivityClasses> sign;
  std::array<std::array<Prob, kBucketContexts>, kActivityClasses> bucket;
  std::array<std::array<Prob, kBucketContexts>, kActivityClasses> mant;

  SignedModel() { reset(); }
  void reset();
};

void encode_signed(RangeEncoder& enc, SignedModel& m, std::int64_t value, int zero_ctx, int act);
// Any bit pattern decodes to some value in [-(2^32 - 1), 2^32 - 1]: callers
// range-check what they get.
std::int64_t decode_signed(RangeDecoder& dec, SignedModel& m, int zero_ctx, int act);

}  // namespace mc::proto
