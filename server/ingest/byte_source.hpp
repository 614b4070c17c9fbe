// Byte sources for the log readers: a plain file, a gzip file (streamed
// through zlib, never inflated whole), or a memory span. The log readers pull
// fixed-size chunks from one of these into a reusable buffer, so a 20 MB game
// never sits in memory at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>

namespace mc::ingest {

class ByteSource {
 public:
  virtual ~ByteSource() = default;
  // Copies up to `n` decoded bytes into `dst` and returns how many. 0 means
  // the end of the input; error() then says whether it ended badly (a
  // truncated or corrupt gzip stream, a read error). Never throws.
  virtual std::size_t read(char* dst, std::size_t n) = 0;
  // "" while all is well; otherwise what went wrong and at which raw offset.
  virtual const std::string& error() const = 0;
  // Bytes consumed from the underlying file so far (compressed bytes for gzip).
  virtual std::uint64_t raw_offset() const = 0;
};

// Opens `path`; if its first two bytes are the gzip magic (1f 8b) the bytes
// are inflated on the fly, whatever the file name says. nullptr + `error`
// when the file cannot be opened.
std::unique_ptr<ByteSource> open_file_source(const std::string& path, std::string& error);

// Reads from memory the caller keeps alive. Gzip is sniffed as for files.
std::unique_ptr<ByteSource> open_memory_source(std::string_view bytes);

}  // namespace mc::ingest
