// server/ingest/byte_source.cpp for the WebAssembly build, without zlib
// (Debian's emscripten has no zlib port; the page inflates gzip with the
// browser's DecompressionStream before the bytes get here). No files
// either: the page hands bytes in (push_byte_source.hpp).
#include <algorithm>
#include <cstring>

#include "server/ingest/byte_source.hpp"

namespace mc::ingest {
namespace {

class MemorySource : public ByteSource {
 public:
  explicit MemorySource(std::string_view bytes) : bytes_(bytes) {
    if (bytes.size() >= 2 && static_cast<unsigned char>(bytes[0]) == 0x1f &&
        static_cast<unsigned char>(bytes[1]) == 0x8b) {
      error_ = "gzip input: this build reads inflated bytes only";
      bytes_ = {};
    }
  }
  std::size_t read(char* dst, std::size_t n) override {
    const std::size_t k = std::min(n, bytes_.size() - pos_);
    if (k) std::memcpy(dst, bytes_.data() + pos_, k);
    pos_ += k;
    return k;
  }
  const std::string& error() const override { return error_; }
  std::uint64_t raw_offset() const override { return pos_; }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
  std::string error_;
};

}  // namespace

std::unique_ptr<ByteSource> open_file_source(const std::string& path, std::string& error) {
  error = path + ": no files in the WebAssembly build";
  return nullptr;
}

std::unique_ptr<ByteSource> open_memory_source(std::string_view bytes) {
  return std::make_unique<MemorySource>(bytes);
}

}  // namespace mc::ingest
