// Bit-level writer and reader for the pose-frame body, plus the adaptive
// Rice code that carries prediction residuals.
//
// Bit order: LSB first. Bit i of the stream is bit (i % 8) of byte (i / 8);
// a multi-bit field is written least significant bit first. The JavaScript
// decoder (web/lib/proto/decoder.js) mirrors this file exactly.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace mc::proto {

class BitWriter {
 public:
  // Appends the low `bits` bits of `value` (0 <= bits <= 32).
  void put(std::uint32_t value, int bits);
  void put_bit(bool bit) { put(bit ? 1u : 0u, 1); }
  // A small unsigned value: 5 bits giving its bit length L (0..31), then L-1
  // bits below the implicit leading one (nothing for 0). Used for state bits.
  void put_varbits(std::uint32_t value);
  // Flushes the partial byte (zero padded) and returns all bytes written.
  std::string finish();

 private:
  std::string bytes_;
  std::uint64_t acc_ = 0;
  int acc_bits_ = 0;
};

// Reads never go past the end: a read beyond it returns zeros and sets
// overrun(), which the caller checks once at the end of a record.
class BitReader {
 public:
  explicit BitReader(std::string_view bytes)
      : data_(reinterpret_cast<const unsigned char*>(bytes.data())), size_bits_(bytes.size() * 8) {}
  std::uint32_t get(int bits);
  bool get_bit() { return get(1) != 0; }
  std::uint32_t get_varbits();
  bool overrun() const { return overrun_; }
  std::size_t bits_read() const { return pos_; }
  std::size_t bits_total() const { return size_bits_; }

 private:
  const unsigned char* data_;
  std::size_t size_bits_;
  std::size_t pos_ = 0;
  bool overrun_ = false;
};

// Signed <-> unsigned so that small magnitudes of either sign give small codes.
inline std::uint32_t zigzag(std::int32_t v) {
  return v >= 0 ? static_cast<std::uint32_t>(v) << 1 : (static_cast<std::uint32_t>(-(v + 1)) << 1) | 1u;
}
inline std::int64_t unzigzag(std::uint32_t u) {
  return (u & 1u) ? -static_cast<std::int64_t>(u >> 1) - 1 : static_cast<std::int64_t>(u >> 1);
}

// Adaptive Golomb-Rice coder for one context (after LOCO-I / JPEG-LS): the
// parameter k follows the running mean of the coded magnitudes, so neither
// side sends it. Encoder and decoder update it identically after each value.
//   code(u): q = u >> k; q ones, a zero, then the low k bits of u.
//   If q >= kEscapeRun: kEscapeRun ones, then u in 32 raw bits.
class RiceContext {
 public:
  static constexpr int kEscapeRun = 16;
  static constexpr int kMaxK = 24;
  static constexpr std::uint32_t kHalveAt = 32;  // adaptation window (values)

  void reset() { sum_ = 4; count_ = 1; }
  int k() const;
  void update(std::uint32_t u);

  void write(BitWriter& w, std::int32_t residual);
  // Returns the residual; on malformed input the reader's overrun() is set or
  // the value is whatever the bits say (callers range-check what they decode).
  std::int64_t read(BitReader& r);

 private:
  std::uint64_t sum_ = 4;
  std::uint32_t count_ = 1;
};

}  // namespace mc::proto
