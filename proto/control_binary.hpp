// Binary forms of the two control messages a recording holds most of: the
// stamina update (every second, 22 numbers) and the kick event. Recording
// format 3 stores them so instead of as JSON text; a reader gets the text
// back byte for byte. On a full game they were 197 KB of the 208 KB of
// control text; with them in binary the chunks' deflated control blocks
// went from 67 KB to 40 KB. Every other message stays text. SPEC.md section
// 6 has the layout.
#pragma once

#include <string>
#include <string_view>

namespace mc::proto::rec {

// The binary form of `json_text`, or "" when it is not a stamina update or a
// kick, or when its binary form would not give back this very text (other
// spacing or key order, a value outside what the form holds).
std::string compact_control(std::string_view json_text);

// The JSON text of a binary form. False when the bytes are malformed
// (unknown tag, a number cut short or out of range, bytes left over).
bool expand_control(std::string_view bytes, std::string& json_text);

}  // namespace mc::proto::rec
