#include "server/ingest/read_window.hpp"

#include <algorithm>
#include <cstring>

namespace mc::ingest {
namespace {
constexpr std::size_t kFirstRead = 16u << 10;
constexpr std::size_t kMaxRead = 1u << 20;
}  // namespace

ReadWindow::ReadWindow(ByteSource& source)
    : src(source), buf(new char[kFirstRead]), capacity(kFirstRead), read_size(kFirstRead) {}

bool ReadWindow::fill() {
  if (eof) return false;
  // Move the unread tail to the front, then grow only if a record needs it.
  if (begin > 0) {
    std::memmove(buf.get(), buf.get() + begin, end - begin);
    base += begin;
    end -= begin;
    begin = 0;
  }
  if (capacity - end < read_size / 2) {
    const std::size_t grown = std::max(end + read_size, capacity * 2);
    std::unique_ptr<char[]> bigger(new char[grown]);  // not zeroed: only [begin, end) is ever read
    std::memcpy(bigger.get(), buf.get(), end);
    buf = std::move(bigger);
    capacity = grown;
  }
  const std::size_t ask = std::min(read_size, capacity - end);
  const std::size_t got = src.read(buf.get() + end, ask);
  if (got == 0) {
    eof = true;
    return false;
  }
  if (got == read_size) read_size = std::min(read_size * 2, kMaxRead);
  end += got;
  return true;
}

}  // namespace mc::ingest
