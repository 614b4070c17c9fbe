#include "anim/mocap/text_cursor.hpp"

#include <charconv>
#include <cmath>
#include <string>

#include "proto/float_chars.hpp"

namespace mc::anim::mocap {

bool parse_double(std::string_view token, double& out) {
  if (token.empty() || token.size() > 64) return false;
  std::string_view t = token;
  if (t.front() == '+') t.remove_prefix(1);
  // from_chars rejects a leading '+', accepts ".5" and "-.5".
  const auto* end = t.data() + t.size();
  auto [ptr, ec] = from_chars_double(t.data(), end, out);
  return ec == std::errc() && ptr == end && std::isfinite(out);
}

void TextCursor::skip_space() {
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == '\n') {
      ++row_; col_ = 1;
    } else if (c == '\r') {
      // CR alone or CRLF: one line end either way.
      if (pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
      ++row_; col_ = 1;
    } else if (c == ' ' || c == '\t' || c == '\f' || c == '\v') {
      ++col_;
    } else {
      return;
    }
    ++pos_;
  }
}

std::string_view TextCursor::next() {
  skip_space();
  tok_row_ = row_; tok_col_ = col_;
  const std::size_t start = pos_;
  while (pos_ < text_.size()) {
    const char c = text_[pos_];
    if (c == ' ' || c == '\t' || c == '\n' || c == '\r' || c == '\f' || c == '\v') break;
    ++pos_; ++col_;
  }
  return text_.substr(start, pos_ - start);
}

std::string_view TextCursor::peek() {
  const std::size_t p = pos_;
  const int r = row_, c = col_, tr = tok_row_, tc = tok_col_;
  const auto t = next();
  pos_ = p; row_ = r; col_ = c; tok_row_ = tr; tok_col_ = tc;
  return t;
}

std::string_view TextCursor::rest_of_line() {
  while (pos_ < text_.size() && (text_[pos_] == ' ' || text_[pos_] == '\t')) { ++pos_; ++col_; }
  tok_row_ = row_; tok_col_ = col_;
  const std::size_t start = pos_;
  while (pos_ < text_.size() && text_[pos_] != '\n' && text_[pos_] != '\r') { ++pos_; ++col_; }
  std::size_t end = pos_;
  while (end > start && (text_[end - 1] == ' ' || text_[end - 1] == '\t')) --end;
  if (pos_ < text_.size()) {
    if (text_[pos_] == '\r' && pos_ + 1 < text_.size() && text_[pos_ + 1] == '\n') ++pos_;
    ++pos_; ++row_; col_ = 1;
  }
  return text_.substr(start, end - start);
}

bool TextCursor::at_end() {
  skip_space();
  return pos_ >= text_.size();
}

bool TextCursor::next_is_number() {
  double v = 0;
  return parse_double(peek(), v);
}

bool TextCursor::number(double& out, std::string& error) {
  const auto t = next();
  if (parse_double(t, out)) return true;
  error = error_at(t.empty() ? "expected a number, found the end of the text"
                             : "expected a number, found '" + std::string(t.substr(0, 32)) + "'");
  return false;
}

std::string TextCursor::error_at(const std::string& message) const {
  return std::to_string(tok_row_) + ":" + std::to_string(tok_col_) + ": " + message;
}

}  // namespace mc::anim::mocap
