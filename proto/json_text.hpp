// JSON text written elsewhere (a spectator, a log, a recording), checked
// before it reaches nlohmann's parser. The parser's lexer takes a NUL byte
// for the end of the input, so `{"type":"replay"}` followed by a NUL and any
// junk parsed as one valid value. No JSON text holds a raw NUL (a string
// writes it \u0000): a text with one is refused before it is parsed.
#pragma once

#include <string_view>

#include <nlohmann/json.hpp>

namespace mc::proto {

inline bool may_be_json_text(std::string_view text) { return text.find('\0') == std::string_view::npos; }

// The parsed value of `text`, or a discarded value when it is not one JSON
// value (nlohmann's json::parse without exceptions, NUL refused first).
inline nlohmann::json parse_json_text(std::string_view text) {
  if (!may_be_json_text(text)) return nlohmann::json(nlohmann::json::value_t::discarded);
  return nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
}

}  // namespace mc::proto
