#include "proto/range_coder.hpp"

namespace mc::proto {

namespace {
constexpr std::uint32_t kTop = 1u << 24;
}

void RangeEncoder::shift_low() {
  if (static_cast<std::uint32_t>(low_) < 0xFF000000u || (low_ >> 32) != 0) {
    const auto carry = static_cast<std::uint8_t>(low_ >> 32);
    std::uint8_t temp = cache_;
    do {
      if (first_) {
        first_ = false;  // always 0 (LZMA's decoders check it); we skip it
      } else {
        out_.push_back(static_cast<char>(static_cast<std::uint8_t>(temp + carry)));
      }
      temp = 0xFF;
    } while (--cache_size_ != 0);
    cache_ = static_cast<std::uint8_t>(low_ >> 24);
  }
  ++cache_size_;
  low_ = (low_ & 0x00FFFFFFu) << 8;
}

void RangeEncoder::encode_bit(Prob& p, bool bit) {
  const std::uint32_t bound = (range_ >> kProbBits) * p;
  if (!bit) {
    range_ = bound;
    p = static_cast<Prob>(p + (((1u << kProbBits) - p) >> kProbShift));
  } else {
    low_ += bound;
    range_ -= bound;
    p = static_cast<Prob>(p - (p >> kProbShift));
  }
  while (range_ < kTop) {
    range_ <<= 8;
    shift_low();
  }
}

void RangeEncoder::encode_direct(std::uint32_t value, int bits) {
  for (int i = bits - 1; i >= 0; --i) {
    range_ >>= 1;
    if ((value >> i) & 1u) low_ += range_;
    while (range_ < kTop) {
      range_ <<= 8;
      shift_low();
    }
  }
}

std::string RangeEncoder::finish() {
  for (int i = 0; i < 5; ++i) shift_low();
  return std::move(out_);
}

RangeDecoder::RangeDecoder(std::string_view bytes)
    : data_(reinterpret_cast<const unsigned char*>(bytes.data())), size_(bytes.size()) {
  for (int i = 0; i < 4; ++i) code_ = (code_ << 8) | next_byte();
}

std::uint8_t RangeDecoder::next_byte() {
  if (pos_ >= size_) {
    overrun_ = true;
    return 0;
  }
  return data_[pos_++];
}

void RangeDecoder::normalize() {
  while (range_ < kTop) {
    range_ <<= 8;
    code_ = (code_ << 8) | next_byte();
  }
}

bool RangeDecoder::decode_bit(Prob& p) {
  const std::uint32_t bound = (range_ >> kProbBits) * p;
  bool bit;
  if (code_ < bound) {
    range_ = bound;
    p = static_cast<Prob>(p + (((1u << kProbBits) - p) >> kProbShift));
    bit = false;
  } else {
    range_ -= bound;
    code_ -= bound;
    p = static_cast<Prob>(p - (p >> kProbShift));
    bit = true;
  }
  normalize();
  return bit;
}

std::uint32_t RangeDecoder::decode_direct(int bits) {
  std::uint32_t value = 0;
  for (int i = 0; i < bits; ++i) {
    range_ >>= 1;
    std::uint32_t bit = 0;
    if (code_ >= range_) {
      code_ -= range_;
      bit = 1;
    }
    value = (value << 1) | bit;
    normalize();
  }
  return value;
}

}  // namespace mc::proto
