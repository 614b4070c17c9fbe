#include "server/ingest/line_reader.hpp"

#include <algorithm>
#include <cstring>

namespace mc::ingest {

LineReader::LineReader(ByteSource& src, std::size_t max_line)
    : w_(src), max_line_(max_line) {}

LineReader::Result LineReader::next(std::string_view& line, std::uint64_t& offset) {
  bool skipping = false;  // inside an over-long line being dropped
  std::uint64_t skip_start = 0;
  for (;;) {
    const char* base = w_.buf.get() + w_.begin;
    const std::size_t avail = w_.end - w_.begin;
    const void* nl = avail > scan_ ? std::memchr(base + scan_, '\n', avail - scan_) : nullptr;
    if (nl != nullptr) {
      const std::size_t len = static_cast<std::size_t>(static_cast<const char*>(nl) - base);
      offset = w_.base + w_.begin;
      w_.begin += len + 1;
      scan_ = 0;
      if (skipping) {
        offset = skip_start;
        return Result::TooLong;
      }
      if (len > max_line_) return Result::TooLong;
      line = std::string_view(base, len);
      return Result::Line;
    }
    scan_ = avail;
    if (avail > max_line_) {
      // Drop what we have of this line and keep scanning for its end.
      if (!skipping) skip_start = w_.base + w_.begin;
      skipping = true;
      w_.begin = w_.end;
      scan_ = 0;
    }
    if (!w_.fill()) {
      const std::size_t rest = w_.end - w_.begin;
      if (skipping) {
        w_.begin = w_.end;  // the tail of the dropped line
        scan_ = 0;
        offset = skip_start;
        return Result::TooLong;
      }
      if (rest == 0) return Result::End;
      offset = w_.base + w_.begin;
      line = std::string_view(w_.buf.get() + w_.begin, rest);
      w_.begin = w_.end;
      scan_ = 0;
      return Result::Line;
    }
  }
}

}  // namespace mc::ingest
