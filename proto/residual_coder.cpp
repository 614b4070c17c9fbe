#include "proto/residual_coder.hpp"

#include <algorithm>

namespace mc::proto {

void encode_signed(RangeEncoder& enc, SignedModel& m, std::int64_t value, int zero_ctx, int act) {
  enc.encode_bit(m.zero[static_cast<std::size_t>(zero_ctx)], value != 0);
  if (value == 0) return;
  const auto a = static_cast<std::size_t>(act);
  enc.encode_bit(m.sign[a], value < 0);
  const auto mag = static_cast<std::uint32_t>(value < 0 ? -value : value);
  int b = 31;
  while (((mag >> b) & 1u) == 0) --b;
  for (int i = 0; i < b; ++i) enc.encode_bit(m.bucket[a][static_cast<std::size_t>(std::min(i, kBucketContexts - 1))], true);
  if (b < 31) enc.encode_bit(m.bucket[a][static_cast<std::size_t>(std::min(b, kBucketContexts - 1))], false);
  if (b >= 1) {
    enc.encode_bit(m.mant[a][static_cast<std::size_t>(std::min(b, kBucketContexts - 1))], ((mag >> (b - 1)) & 1u) != 0);
    if (b >= 2) enc.encode_direct(mag & ((1u << (b - 1)) - 1u), b - 1);
  }
}

std::int64_t decode_signed(RangeDecoder& dec, SignedModel& m, int zero_ctx, int act) {
  if (!dec.decode_bit(m.zero[static_cast<std::size_t>(zero_ctx)])) return 0;
  const auto a = static_cast<std::size_t>(act);
  const bool negative = dec.decode_bit(m.sign[a]);
  int b = 0;
  while (b < 31 && dec.decode_bit(m.bucket[a][static_cast<std::size_t>(std::min(b, kBucketContexts - 1))])) ++b;
  std::uint32_t mag = 1u << b;
  if (b >= 1) {
    if (dec.decode_bit(m.mant[a][static_cast<std::size_t>(std::min(b, kBucketContexts - 1))])) mag |= 1u << (b - 1);
    if (b >= 2) mag |= dec.decode_direct(b - 1);
  }
  return negative ? -static_cast<std::int64_t>(mag) : static_cast<std::int64_t>(mag);
}

}  // namespace mc::proto
