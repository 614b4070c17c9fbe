// Binary adaptive range coder for the pose-frame body (the LZMA "rc" design:
// 11-bit probabilities, adaptation shift 4, 32-bit range, byte-wise carry).
// Integer-only, so the JavaScript decoder (web/lib/proto/decoder.js) follows
// it bit for bit. SPEC.md section 4.2 is the normative description.
//
// Why arithmetic coding and not fixed bit fields: most residuals of a pose
// stream are zero or tiny (players stand, bones follow their prediction),
// and an adaptive binary coder spends ~0.05 bit on a near-certain zero
// where any bit-packing spends at least 1.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace mc::proto {

// P(bit = 0) in 1/2048ths; starts at one half.
using Prob = std::uint16_t;
inline constexpr int kProbBits = 11;
inline constexpr Prob kProbInit = 1u << (kProbBits - 1);
inline constexpr int kProbShift = 4;  // adaptation speed: ~16 symbols of memory

class RangeEncoder {
 public:
  void encode_bit(Prob& p, bool bit);
  // `bits` (<= 32) equiprobable bits of `value`, most significant first.
  void encode_direct(std::uint32_t value, int bits);
  // Flushes and returns the bytes (4 + one per renormalization).
  std::string finish();

 private:
  void shift_low();
  std::uint64_t low_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint8_t cache_ = 0;
  std::uint64_t cache_size_ = 1;
  bool first_ = true;  // the first byte out is always 0 and is not sent
  std::string out_;
};

// Never reads outside its input: reading past the end yields zero bytes and
// sets overrun(), which means the input was truncated.
class RangeDecoder {
 public:
  explicit RangeDecoder(std::string_view bytes);
  bool decode_bit(Prob& p);
  std::uint32_t decode_direct(int bits);
  bool overrun() const { return overrun_; }
  // Bytes consumed so far; a complete valid stream is consumed exactly.
  std::size_t consumed() const { return pos_; }

 private:
  std::uint8_t next_byte();
  void normalize();
  const unsigned char* data_;
  std::size_t size_;
  std::size_t pos_ = 0;
  std::uint32_t range_ = 0xFFFFFFFFu;
  std::uint32_t code_ = 0;
  bool overrun_ = false;
};

}  // namespace mc::proto
