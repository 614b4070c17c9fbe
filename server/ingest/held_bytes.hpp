// Bytes read ahead of a stream's reader (a sniffed file head, the magic
// bytes that chose the decoder), handed out again before the stream goes on:
// the reader sees the input whole, and the input is opened and read once.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstring>
#include <string>

namespace mc::ingest {

struct HeldBytes {
  std::string bytes;
  std::size_t pos = 0;

  // Copies up to `n` of the bytes not yet handed out into `dst` and returns
  // how many: 0 once all of them are, and the stream itself goes on.
  std::size_t take(char* dst, std::size_t n) {
    const std::size_t k = std::min(n, bytes.size() - pos);
    std::memcpy(dst, bytes.data() + pos, k);
    pos += k;
    return k;
  }
};

}  // namespace mc::ingest
