#include "server/ingest/json_splitter.hpp"

#include <algorithm>
#include <cstring>

namespace mc::ingest {

JsonSplitter::JsonSplitter(ByteSource& src, std::size_t max_object)
    : w_(src), max_object_(max_object) {}

JsonSplitter::Result JsonSplitter::next(std::string_view& obj, std::uint64_t& offset) {
  // Find the opening brace of the next element.
  for (;;) {
    while (w_.begin < w_.end && w_.buf[w_.begin] != '{') ++w_.begin;
    if (w_.begin < w_.end) break;
    if (!w_.fill()) return Result::End;
  }
  offset = w_.base + w_.begin;
  // Scan to the matching close brace. `i` is relative to w_.begin, because
  // fill() moves the buffer.
  std::size_t i = 0;
  int depth = 0;
  bool in_string = false, escaped = false, skipping = false;
  for (;;) {
    while (w_.begin + i < w_.end) {
      const char c = w_.buf[w_.begin + i];
      ++i;
      if (in_string) {
        if (escaped) escaped = false;
        else if (c == '\\') escaped = true;
        else if (c == '"') in_string = false;
      } else if (c == '"') {
        in_string = true;
      } else if (c == '{') {
        ++depth;
      } else if (c == '}' && --depth == 0) {
        const std::size_t start = w_.begin;
        w_.begin += i;
        if (skipping || i > max_object_) return Result::TooLong;
        obj = std::string_view(w_.buf.get() + start, i);
        return Result::Object;
      }
    }
    if (i > max_object_) {
      // Drop what we have and keep scanning for the end of this element.
      skipping = true;
      w_.begin += i;
      i = 0;
    }
    if (!w_.fill()) {
      w_.begin = w_.end;
      return Result::Truncated;
    }
  }
}

}  // namespace mc::ingest
