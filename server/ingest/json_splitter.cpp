#include "server/ingest/json_splitter.hpp"

#include <algorithm>
#include <cstring>

namespace mc::ingest {
namespace {
// Reads start small (a datagram-sized input, a fuzz case) and double while
// they fill the buffer, up to 1 MiB per read for whole game logs.
constexpr std::size_t kFirstRead = 64u << 10;
constexpr std::size_t kMaxRead = 1u << 20;
}

JsonSplitter::JsonSplitter(ByteSource& src, std::size_t max_object)
    : src_(src), max_object_(max_object), buf_(kFirstRead), read_size_(kFirstRead) {}

bool JsonSplitter::fill() {
  if (eof_) return false;
  if (pos_ > 0) {
    std::memmove(buf_.data(), buf_.data() + pos_, end_ - pos_);
    base_ += pos_;
    end_ -= pos_;
    pos_ = 0;
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

JsonSplitter::Result JsonSplitter::next(std::string_view& obj, std::uint64_t& offset) {
  // Find the opening brace of the next element.
  for (;;) {
    while (pos_ < end_ && buf_[pos_] != '{') ++pos_;
    if (pos_ < end_) break;
    if (!fill()) return Result::End;
  }
  offset = base_ + pos_;
  // Scan to the matching close brace. `i` is relative to pos_, because
  // fill() moves the buffer.
  std::size_t i = 0;
  int depth = 0;
  bool in_string = false, escaped = false, skipping = false;
  for (;;) {
    while (pos_ + i < end_) {
      const char c = buf_[pos_ + i];
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
        const std::size_t start = pos_;
        pos_ += i;
        if (skipping || i > max_object_) return Result::TooLong;
        obj = std::string_view(buf_.data() + start, i);
        return Result::Object;
      }
    }
    if (i > max_object_) {
      // Drop what we have and keep scanning for the end of this element.
      skipping = true;
      pos_ += i;
      i = 0;
    }
    if (!fill()) {
      pos_ = end_;
      return Result::Truncated;
    }
  }
}

}  // namespace mc::ingest
