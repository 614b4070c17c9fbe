// The sliding buffer shared by the streaming readers (lines, JSON objects):
// unread bytes stay in buf[begin, end), and fill() moves them to the front
// and appends the next read. Reads start small (a datagram-sized input, a
// fuzz case) and double while they fill the buffer, up to 1 MiB per read for
// whole game logs. Memory stays bounded by the longest record plus one read.
// The buffer is not zeroed (only bytes read are ever looked at), and it
// grows only when less than half a read fits: the read that finds the end
// of a short input costs no new buffer.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>

#include "server/ingest/byte_source.hpp"

namespace mc::ingest {

struct ReadWindow {
  explicit ReadWindow(ByteSource& source);

  // Compacts and appends one read. False (and eof set) at the end of input.
  bool fill();
  // Decoded offset of buf[begin]: how far the reader has consumed.
  std::uint64_t consumed() const { return base + begin; }

  ByteSource& src;
  std::unique_ptr<char[]> buf;     // `capacity` bytes
  std::size_t capacity;
  std::size_t read_size;           // bytes asked of the source per read
  std::size_t begin = 0, end = 0;  // unread bytes are buf[begin, end)
  std::uint64_t base = 0;          // decoded offset of buf[0]
  bool eof = false;
};

}  // namespace mc::ingest
