// A built-in 5x7 bitmap font for the HUD and the shirt numbers: no font
// library is in the dependency list, and a scoreboard needs only upper-case
// letters, digits and a little punctuation (lower case is drawn as upper).
#pragma once

#include <array>
#include <cstdint>
#include <string_view>

namespace mc::viewer {

inline constexpr int kGlyphW = 5, kGlyphH = 7;
inline constexpr int kGlyphAdvance = 6;  // columns per character, spacing included

// Rows top to bottom, bit 4 = leftmost column. Unknown characters are a box.
const std::array<std::uint8_t, kGlyphH>& glyph(char c);

// Width in font pixels of a line of text.
inline int text_columns(std::string_view text) {
  return text.empty() ? 0 : static_cast<int>(text.size()) * kGlyphAdvance - 1;
}

}  // namespace mc::viewer
