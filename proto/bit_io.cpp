#include "proto/bit_io.hpp"

#include <algorithm>

namespace mc::proto {

void BitWriter::put(std::uint32_t value, int bits) {
  if (bits <= 0) return;
  if (bits < 32) value &= (1u << bits) - 1u;
  acc_ |= static_cast<std::uint64_t>(value) << acc_bits_;
  acc_bits_ += bits;
  while (acc_bits_ >= 8) {
    bytes_.push_back(static_cast<char>(acc_ & 0xffu));
    acc_ >>= 8;
    acc_bits_ -= 8;
  }
}

void BitWriter::put_varbits(std::uint32_t value) {
  int len = 0;
  while (len < 32 && (value >> len) != 0) ++len;
  if (len == 32) len = 31, value = 0x7fffffffu;  // state bits never use bit 31
  put(static_cast<std::uint32_t>(len), 5);
  if (len > 1) put(value, len - 1);
}

std::string BitWriter::finish() {
  if (acc_bits_ > 0) bytes_.push_back(static_cast<char>(acc_ & 0xffu));
  acc_ = 0;
  acc_bits_ = 0;
  return std::move(bytes_);
}

std::uint32_t BitReader::get(int bits) {
  std::uint32_t value = 0;
  for (int i = 0; i < bits;) {
    if (pos_ >= size_bits_) {
      overrun_ = true;
      return 0;
    }
    // Take as many bits as remain in the current byte at once.
    const int bit_in_byte = static_cast<int>(pos_ & 7u);
    const int take = std::min(8 - bit_in_byte, bits - i);
    const std::uint32_t chunk = (static_cast<std::uint32_t>(data_[pos_ >> 3]) >> bit_in_byte) & ((1u << take) - 1u);
    value |= chunk << i;
    i += take;
    pos_ += static_cast<std::size_t>(take);
  }
  return value;
}

std::uint32_t BitReader::get_varbits() {
  const std::uint32_t len = get(5);
  if (len == 0) return 0;
  if (len == 1) return 1;
  return (1u << (len - 1)) | get(static_cast<int>(len - 1));
}

int RiceContext::k() const {
  int k = 0;
  while (k < kMaxK && (static_cast<std::uint64_t>(count_) << k) < sum_) ++k;
  return k;
}

void RiceContext::update(std::uint32_t u) {
  sum_ += u;
  if (++count_ >= kHalveAt) {
    sum_ = (sum_ + 1) >> 1;
    count_ >>= 1;
  }
}

void RiceContext::write(BitWriter& w, std::int32_t residual) {
  const std::uint32_t u = zigzag(residual);
  const int kk = k();
  const std::uint32_t q = u >> kk;
  if (q >= static_cast<std::uint32_t>(kEscapeRun)) {
    w.put((1u << kEscapeRun) - 1u, kEscapeRun);
    w.put(u, 32);
  } else {
    // q ones then a zero: q + 1 <= 16 bits.
    w.put((1u << q) - 1u, static_cast<int>(q) + 1);
    w.put(u, kk);
  }
  update(u);
}

std::int64_t RiceContext::read(BitReader& r) {
  const int kk = k();
  std::uint32_t q = 0;
  while (q < static_cast<std::uint32_t>(kEscapeRun) && r.get_bit()) ++q;
  std::uint32_t u;
  if (q == static_cast<std::uint32_t>(kEscapeRun)) {
    u = r.get(32);
  } else {
    u = (q << kk) | r.get(kk);
  }
  update(u);
  return unzigzag(u);
}

}  // namespace mc::proto
