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
#include <cstddef>
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

namespace detail {
template <std::size_t N>
constexpr std::array<Prob, N> initial_probs() {
  std::array<Prob, N> a{};
  for (Prob& p : a) p = kProbInit;
  return a;
}
// Every context at kProbInit, as compile-time constants: construction and
// reset() are plain copies of these. (A fill loop per context was the
// costliest part of decoding a short keyframe in the coverage-instrumented
// fuzz build: a keyframe resets ~28,000 contexts.)
inline constexpr std::array<Prob, kZeroContexts> kInitZero = initial_probs<kZeroContexts>();
inline constexpr std::array<Prob, kActivityClasses> kInitSign = initial_probs<kActivityClasses>();
inline constexpr std::array<Prob, kBucketContexts> kInitRow = initial_probs<kBucketContexts>();
inline constexpr auto kInitRows = [] {
  std::array<std::array<Prob, kBucketContexts>, kActivityClasses> a{};
  for (auto& row : a) row = kInitRow;
  return a;
}();
}  // namespace detail

struct SignedModel {
  std::array<Prob, kZeroContexts> zero = detail::kInitZero;
  std::array<Prob, kActivityClasses> sign = detail::kInitSign;
  std::array<std::array<Prob, kBucketContexts>, kActivityClasses> bucket = detail::kInitRows;
  std::array<std::array<Prob, kBucketContexts>, kActivityClasses> mant = detail::kInitRows;

  void reset();
};
inline constexpr SignedModel kInitialSignedModel{};
inline void SignedModel::reset() { *this = kInitialSignedModel; }

void encode_signed(RangeEncoder& enc, SignedModel& m, std::int64_t value, int zero_ctx, int act);
// Any bit pattern decodes to some value in [-(2^32 - 1), 2^32 - 1]: callers
// range-check what they get.
std::int64_t decode_signed(RangeDecoder& dec, SignedModel& m, int zero_ctx, int act);

}  // namespace mc::proto
