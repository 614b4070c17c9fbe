#include "server/ingest/line_reader.hpp"

#include <algorithm>
#include <cstring>

namespace mc::ingest {
namespace {
// Reads start small (a datagram-sized input, a fuzz case) and double while
// they fill the buffer, up to 1 MiB per read for whole game logs.
constexpr std::size_t kFirstRead = 64u << 10;
constexpr std::size_t kMaxRead = 1u << 20;
}

LineReader::LineReader(ByteSource& src, std::size_t max_line)
    : src_(src), max_line_(max_line), buf_(kFirstRead), read_size_(kFirstRead) {}

bool LineReader::fill() {
  if (eof_) return false;
  // Move the unread tail to the front, then grow only if a line needs it.
  if (begin_ > 0) {
    std::memmove(buf_.data(), buf_.data() + begin_, end_ - begin_);
    consumed_base_ += begin_;
    end_ -= begin_;
    begin_ = 0;
  }
  if (buf_.size() - end_ < read_size_) buf_.resize(end_ + read_size_);
  const std::size_t got = src_.read(buf_.data() + end_, read_size_);
  if (got == 0) {
    eof_ = true;
    return false;
  }
  if (got == read_size_) read_size_ = std::min(read_size_ * 2, kMaxRead);
  end_ += got;
  return true;
}

LineReader::Result LineReader::next(std::string_view& line, std::uint64_t& offset) {
  bool skipping = false;  // inside an over-long line being dropped
  std::uint64_t skip_start = 0;
  for (;;) {
    const char* base = buf_.data() + begin_;
    const std::size_t avail = end_ - begin_;
    const void* nl = avail > scan_ ? std::memchr(base + scan_, '\n', avail - scan_) : nullptr;
    if (nl != nullptr) {
      const std::size_t len = static_cast<std::size_t>(static_cast<const char*>(nl) - base);
      offset = consumed_base_ + begin_;
      begin_ += len + 1;
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
      if (!skipping) skip_start = consumed_base_ + begin_;
      skipping = true;
      begin_ = end_;
      scan_ = 0;
    }
    if (!fill()) {
      const std::size_t rest = end_ - begin_;
      if (skipping) {
        begin_ = end_;  // the tail of the dropped line
        scan_ = 0;
        offset = skip_start;
        return Result::TooLong;
      }
      if (rest == 0) return Result::End;
      offset = consumed_base_ + begin_;
      line = std::string_view(buf_.data() + begin_, rest);
      begin_ = end_;
      scan_ = 0;
      return Result::Line;
    }
  }
}

}  // namespace mc::ingest
