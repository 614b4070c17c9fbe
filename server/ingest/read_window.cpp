#include "server/ingest/read_window.hpp"

#include <algorithm>
#include <cstring>

namespace mc::ingest {
namespace {
constexpr std::size_t kFirstRead = 64u << 10;
constexpr std::size_t kMaxRead = 1u << 20;
}  // namespace

ReadWindow::ReadWindow(ByteSource& source) : src(source), buf(kFirstRead), read_size(kFirstRead) {}

bool ReadWindow::fill() {
  if (eof) return false;
  // Move the unread tail to the front, then grow only if a record needs it.
  if (begin > 0) {
    std::memmove(buf.data(), buf.data() + begin, end - begin);
    base += begin;
    end -= begin;
    begin = 0;
  }
  if (buf.size() - end < read_size) buf.resize(end + read_size);
  const std::size_t got = src.read(buf.data() + end, read_size);
  if (got == 0) {
    eof = true;
    return false;
  }
  if (got == read_size) read_size = std::min(read_size * 2, kMaxRead);
  end += got;
  return true;
}

}  // namespace mc::ingest
