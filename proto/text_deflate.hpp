// Raw DEFLATE (RFC 1951, through zlib) of a recording chunk's control
// messages, with a preset dictionary of the messages' usual text (SPEC.md
// section 6). The messages are short JSON lines, a few per second: alone,
// deflate finds little to reuse in them, while the dictionary gives it every
// key and the common values from the first byte (a full game's 208 KB of
// control messages take ~70 KB in one-second chunks, ~115 KB without it).
// Pure computation: no files here.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace mc::proto::rec {

// The dictionary is part of recording formats 2 and 3: never change it.
std::string_view control_dictionary();

std::string deflate_text(std::string_view text);
// Inflates `z` into exactly `size` bytes (the caller knows the size from
// the chunk's entries). False for anything else: corrupt or truncated data,
// a stream that ends early or runs on.
bool inflate_text(std::string_view z, std::size_t size, std::string& out);

}  // namespace mc::proto::rec
