// A whitespace tokenizer over text in memory for the mocap parsers: tracks
// row and column for error messages ("12:5: expected OFFSET") and treats
// CR, LF, CRLF, tabs and spaces alike, so mixed line endings need no care.
#pragma once

#include <string>
#include <string_view>

namespace mc::anim::mocap {

class TextCursor {
 public:
  explicit TextCursor(std::string_view text) : text_(text) {}

  // The next whitespace-separated token, or "" at the end.
  std::string_view next();
  // The next token without consuming it.
  std::string_view peek();
  // The rest of the current line (trimmed), consumed with its line end.
  std::string_view rest_of_line();
  bool at_end();
  // True when the next token parses as a number.
  bool next_is_number();

  // Parses the next token as a number; false (and `error` set) when it is not.
  bool number(double& out, std::string& error);
  // "row:col: message" at the start of the last token.
  std::string error_at(const std::string& message) const;

 private:
  void skip_space();
  std::string_view text_;
  std::size_t pos_ = 0;
  int row_ = 1, col_ = 1;
  int tok_row_ = 1, tok_col_ = 1;
};

// Parses a whole token as a double ("-.5", "1e-016"); false for anything else.
bool parse_double(std::string_view token, double& out);

}  // namespace mc::anim::mocap
