// A hand-written tokenizer for rcssserver's S-expressions: a cursor over one
// line or datagram. Every read checks the end of the input first, so a cut
// or malformed record fails a call instead of reading past the end. Numbers
// go through std::from_chars (handles "-0", exponents; no locale, no copies).
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <string_view>

namespace mc::ingest {

class SexpCursor {
 public:
  explicit SexpCursor(std::string_view text)
      : begin_(text.data()), p_(text.data()), end_(text.data() + text.size()) {}

  // Spaces, tabs, CR, LF and NUL (datagrams end in NUL) separate tokens.
  void skip_ws() {
    while (p_ < end_ && (*p_ == ' ' || *p_ == '\t' || *p_ == '\r' || *p_ == '\n' || *p_ == '\0')) ++p_;
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
    auto [q, ec] = std::from_chars(p_, end_, v);
    if (ec != std::errc() || q == p_ || !std::isfinite(v) || (q < end_ && !is_delim(*q))) return false;
    p_ = q;
    return true;
  }
  // A decimal integer; a real with a zero fraction ("3.0") is accepted too.
  bool integer(std::int64_t& v) {
    skip_ws();
    auto [q, ec] = std::from_chars(p_, end_, v);
    if (ec == std::errc() && q != p_ && (q >= end_ || is_delim(*q))) {
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

  static bool is_delim(char c) {
    return c == ' ' || c == '(' || c == ')' || c == '\t' || c == '\r' || c == '\n' || c == '\0';
  }

 private:
  const char* begin_;
  const char* p_;
  const char* end_;
};

}  // namespace mc::ingest
