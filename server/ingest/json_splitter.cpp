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

// Where a scan of an element stands: the brace depth, and whether it is in
// a string, just after a string's backslash (which may end a read window).
struct ScanState {
  int depth = 0;
  bool in_string = false, escaped = false;
};

// The fuzz build traces every comparison and branch for coverage. This scan
// decides nothing the fuzzer could steer by (bytes in, one position out),
// and tracing its tests, a few for every quote and brace, was about a tenth
// of ingest_fuzz_log_json's time (perf, 20 s run); what next() does with its answer (an element,
// one too long, the input ending inside one) is traced as before. Not
// inlined, so that the attribute stays on this function alone.
#if defined(__clang__)
#define MC_UNTRACED __attribute__((no_sanitize("coverage"), noinline))
#else
#define MC_UNTRACED
#endif
// Scans buf[i, end) from state `s`. Returns true with `i` just past the
// brace that closes the element, or false with `i == end`.
MC_UNTRACED bool scan_element(const char* buf, std::size_t& i, std::size_t end, ScanState& s) {
  if (s.escaped && i < end) {  // a backslash ended the last window
    ++i;
    s.escaped = false;
  }
  while (i < end) {
    // Most bytes (digits, names, commas) change nothing: a table look-up
    // passes them, not a test for each of the four that matter.
    if (!kSpecial[static_cast<unsigned char>(buf[i])]) {
      ++i;
      continue;
    }
    const char c = buf[i++];
    if (s.in_string) {
      if (c == '\\') {  // the escaped byte is passed over, whatever it is
        if (i < end) ++i;
        else s.escaped = true;
      } else if (c == '"') s.in_string = false;
    } else if (c == '"') {
      s.in_string = true;
    } else if (c == '{') {
      ++s.depth;
    } else if (c == '}' && --s.depth == 0) {
      return true;
    }
  }
  return false;
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
  ScanState state;
  bool skipping = false;
  for (;;) {
    std::size_t at = w_.begin + i;
    const bool closed = scan_element(w_.buf.get(), at, w_.end, state);
    i = at - w_.begin;
    if (closed) {
      const std::size_t start = w_.begin;
      w_.begin += i;
      if (skipping || i > max_object_) return Result::TooLong;
      obj = std::string_view(w_.buf.get() + start, i);
      return Result::Object;
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
