#include "server/ingest/json_splitter.hpp"

#include <algorithm>
#include <array>
#include <cstring>

namespace mc::ingest {

JsonSplitter::JsonSplitter(ByteSource& src, std::size_t max_object)
    : w_(src), max_object_(max_object) {}

namespace {

// The bytes that can change the scan's state: quotes, a string's escape and
// braces (a backslash outside a string means nothing, and is passed over).
constexpr std::array<bool, 256> kSpecial = [] {
  std::array<bool, 256> t{};
  for (unsigned char c : {'"', '\\', '{', '}'}) t[c] = true;
  return t;
}();

// The fuzz build traces every comparison and branch for coverage. This loop
// decides nothing (it passes the bytes that change no state), and tracing
// its two tests a byte was a third of ingest_fuzz_log_json's time; the
// states it returns to are traced as before. Not inlined, so that the
// attribute stays on this loop alone.
#if defined(__clang__)
#define MC_UNTRACED __attribute__((no_sanitize("coverage"), noinline))
#else
#define MC_UNTRACED
#endif
MC_UNTRACED std::size_t skip_plain(const char* buf, std::size_t i, std::size_t end) {
  while (i < end && !kSpecial[static_cast<unsigned char>(buf[i])]) ++i;
  return i;
}

}  // namespace

JsonSplitter::Result JsonSplitter::next(std::string_view& obj, std::uint64_t& offset) {
  // Find the opening brace of the next element.
  for (;;) {
    const void* brace = w_.begin < w_.end ? std::memchr(w_.buf.get() + w_.begin, '{', w_.end - w_.begin) : nullptr;
    if (brace) {
      w_.begin = static_cast<std::size_t>(static_cast<const char*>(brace) - w_.buf.get());
      break;
    }
    w_.begin = w_.end;
    if (!w_.fill()) return Result::End;
  }
  offset = w_.base + w_.begin;
  // Scan to the matching close brace. `i` is relative to w_.begin, because
  // fill() moves the buffer.
  std::size_t i = 0;
  int depth = 0;
  bool in_string = false, escaped = false, skipping = false;
  for (;;) {
    if (escaped && w_.begin + i < w_.end) {  // a backslash ended the last window
      ++i;
      escaped = false;
    }
    for (;;) {
      // Most bytes (digits, names, commas) change nothing: a table look-up
      // passes them, not a test for each of the four that matter.
      i = skip_plain(w_.buf.get() + w_.begin, i, w_.end - w_.begin);
      if (w_.begin + i >= w_.end) break;
      const char c = w_.buf[w_.begin + i];
      ++i;
      if (in_string) {
        if (c == '\\') {  // the escaped byte is passed over, whatever it is
          if (w_.begin + i < w_.end) ++i;
          else escaped = true;
        } else if (c == '"') in_string = false;
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
