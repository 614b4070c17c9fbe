// Splits a ByteSource into lines without copying them one by one: lines are
// string_views into one reusable buffer that only grows to the longest line
// (bounded by max_line). This is the streaming core of the text log reader.
#pragma once

#include <cstdint>
#include <string_view>
#include <vector>

#include "server/ingest/byte_source.hpp"
#include "server/ingest/read_window.hpp"

namespace mc::ingest {

class LineReader {
 public:
  // `max_line` bytes: a longer line is skipped whole and reported by next().
  explicit LineReader(ByteSource& src, std::size_t max_line = 8u << 20);

  enum class Result { Line, TooLong, End };
  // The next line without its '\n' (a trailing '\r' is kept; callers treat it
  // as whitespace). `offset` is the decoded byte offset of the line's first
  // byte. The view stays valid until the next call. On TooLong the line was
  // dropped and `offset` says where it started. The last line of the input
  // may lack its '\n' (a truncated file): it is still returned.
  Result next(std::string_view& line, std::uint64_t& offset);

  // Decoded bytes handed out so far.
  std::uint64_t bytes_read() const { return w_.consumed(); }

 private:
  ReadWindow w_;
  std::size_t max_line_;
  std::size_t scan_ = 0;  // bytes from w_.begin known to hold no '\n'
};

}  // namespace mc::ingest
