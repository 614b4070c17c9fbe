// A hand-written tokenizer for rcssserver's S-expressions: a cursor over one
// line or datagram. Every read checks the end of the input first, so a cut
// or malformed record fails a call instead of reading past the end. Numbers
// go through a fast decimal path, then mc::from_chars_double (fast_float:
// "-0", exponents; no locale, no copies; proto/float_chars.hpp).
#pragma once

#include <array>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>

#include "proto/float_chars.hpp"

namespace mc::ingest {

class SexpCursor {
  // Character classes, one table lookup instead of a chain of compares.
  static constexpr std::uint8_t kSpace = 1, kDelim = 2;
  static constexpr auto kClass = [] {
    std::array<std::uint8_t, 256> t{};
    for (unsigned char c : {' ', '\t', '\r', '\n', '\0'}) t[c] = kSpace | kDelim;
    t[static_cast<unsigned char>('(')] = kDelim;
    t[static_cast<unsigned char>(')')] = kDelim;
    return t;
  }();

 public:
  explicit SexpCursor(std::string_view text)
      : begin_(text.data()), p_(text.data()), end_(text.data() + text.size()) {}

  // Spaces, tabs, CR, LF and NUL (datagrams end in NUL) separate tokens.
  void skip_ws() {
    while (p_ < end_ && (kClass[static_cast<unsigned char>(*p_)] & kSpace)) ++p_;
  }
  bool at_end() {
    skip_ws();
    return p_ >= end_;
  }
  // Next non-space character, or '\0' at the end.
  char peek() {
    skip_ws();
    return p_ < end_ ? *p_ : '\0';
  }
  // Consumes `c` if it is the next non-space character.
  bool lit(char c) {
    skip_ws();
    if (p_ < end_ && *p_ == c) {
      ++p_;
      return true;
    }
    return false;
  }
  // Consumes `word` if the next token starts with it and ends right after it.
  bool keyword(std::string_view word) {
    skip_ws();
    if (static_cast<std::size_t>(end_ - p_) < word.size() ||
        std::string_view(p_, word.size()) != word)
      return false;
    const char* after = p_ + word.size();
    if (after < end_ && !is_delim(*after)) return false;
    p_ = after;
    return true;
  }
  // A bare token (up to a space or parenthesis). False if empty.
  bool symbol(std::string_view& out) {
    skip_ws();
    const char* s = p_;
    while (p_ < end_ && !is_delim(*p_)) ++p_;
    out = std::string_view(s, static_cast<std::size_t>(p_ - s));
    return !out.empty();
  }
  // A finite decimal real ("-0", "1e-05", "130600").
  bool number(double& v) {
    skip_ws();
    if (p_ < end_ && *p_ == '+') ++p_;  // from_chars refuses a leading '+'
    if (fast_decimal(v)) return true;
    auto [q, ec] = from_chars_double(p_, end_, v);
    if (ec != std::errc() || q == p_ || !std::isfinite(v) || (q < end_ && !is_delim(*q))) return false;
    p_ = q;
    return true;
  }
  // A one-character token such as a side "l"/"r" or a view quality "h".
  bool single_char(char& ch) {
    skip_ws();
    if (end_ - p_ < 1 || is_delim(*p_) || (end_ - p_ >= 2 && !is_delim(p_[1]))) return false;
    ch = *p_++;
    return true;
  }
  // A decimal integer; a real with a zero fraction ("3.0") is accepted too.
  bool integer(std::int64_t& v) {
    skip_ws();
    // Fast path: [-]digits (at most 18, so no overflow) followed by a delimiter.
    const char* q = p_;
    const bool neg = q < end_ && *q == '-';
    if (neg) ++q;
    const char* digits = q;
    std::int64_t x = 0;
    while (q < end_ && q - digits < 18 && static_cast<unsigned>(*q - '0') < 10) x = x * 10 + (*q++ - '0');
    if (q != digits && (q >= end_ || is_delim(*q))) {
      v = neg ? -x : x;
      p_ = q;
      return true;
    }
    double d = 0;
    const char* save = p_;
    if (!number(d) || d != std::floor(d) || std::fabs(d) > 9e15) {
      p_ = save;
      return false;
    }
    v = static_cast<std::int64_t>(d);
    return true;
  }
  template <typename Int>
  bool integer_in(Int& v, std::int64_t lo, std::int64_t hi) {
    std::int64_t x = 0;
    const char* save = p_;
    if (!integer(x) || x < lo || x > hi) {
      p_ = save;
      return false;
    }
    v = static_cast<Int>(x);
    return true;
  }
  // Hexadecimal with an optional "0x" prefix, or a bare "0" (rcssserver's
  // std::showbase prints no prefix for zero).
  bool hex(std::uint32_t& v) {
    skip_ws();
    const char* s = p_;
    if (end_ - s >= 2 && s[0] == '0' && (s[1] == 'x' || s[1] == 'X')) s += 2;
    auto [q, ec] = std::from_chars(s, end_, v, 16);
    if (ec != std::errc() || q == s || (q < end_ && !is_delim(*q))) return false;
    p_ = q;
    return true;
  }
  // Skips one balanced (...) group (the '(' not yet consumed). Bounded by the
  // input length; false if the group is not closed.
  bool skip_group() {
    if (!lit('(')) return false;
    int depth = 1;
    bool in_quote = false;
    while (p_ < end_) {
      const char c = *p_++;
      if (c == '"') in_quote = !in_quote;
      else if (!in_quote && c == '(') ++depth;
      else if (!in_quote && c == ')' && --depth == 0) return true;
    }
    return false;
  }

  std::size_t position() const { return static_cast<std::size_t>(p_ - begin_); }
  const char* ptr() const { return p_; }
  const char* end() const { return end_; }
  void seek(const char* p) { p_ = p; }

  static bool is_delim(char c) { return kClass[static_cast<unsigned char>(c)] & kDelim; }

 private:
  // Clinger's fast path: [-]digits[.digits] with at most 15 significant
  // digits and no exponent is exactly mantissa / 10^k, and one IEEE
  // division of two exact doubles rounds correctly, so the result equals
  // strtod's. Anything else (exponents, long mantissas) goes to fast_float.
  bool fast_decimal(double& v) {
    static constexpr double kPow10[] = {1e0, 1e1, 1e2, 1e3, 1e4, 1e5, 1e6, 1e7, 1e8,
                                        1e9, 1e10, 1e11, 1e12, 1e13, 1e14, 1e15};
    const char* q = p_;
    const bool neg = q < end_ && *q == '-';
    if (neg) ++q;
    std::uint64_t m = 0;
    int digits = 0, frac = 0;
    const char* start = q;
    while (q < end_ && static_cast<unsigned>(*q - '0') < 10) {
      m = m * 10 + static_cast<unsigned>(*q++ - '0');
      if (m != 0) ++digits;  // leading zeros are not significant
    }
    if (q == start) return false;
    if (q < end_ && *q == '.') {
      ++q;
      const char* f = q;
      while (q < end_ && static_cast<unsigned>(*q - '0') < 10) {
        m = m * 10 + static_cast<unsigned>(*q++ - '0');
        if (m != 0) ++digits;
      }
      frac = static_cast<int>(q - f);
      if (frac == 0) return false;
    }
    if (digits > 15 || frac > 15 || (q < end_ && !is_delim(*q))) return false;
    double d = static_cast<double>(m);
    if (frac) d /= kPow10[frac];
    v = neg ? -d : d;
    p_ = q;
    return true;
  }

  const char* begin_;
  const char* p_;
  const char* end_;
};

}  // namespace mc::ingest
