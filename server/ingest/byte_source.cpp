#include "server/ingest/byte_source.hpp"

#include <zlib.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <vector>

#include "server/ingest/held_bytes.hpp"

namespace mc::ingest {
namespace {

// Where the raw (possibly compressed) bytes come from.
class RawInput {
 public:
  virtual ~RawInput() = default;
  // Returns bytes read; 0 at end or on error (error() non-empty).
  virtual std::size_t read(char* dst, std::size_t n) = 0;
  virtual const std::string& error() const = 0;
  // Bytes left to read, when known (memory): a buffer need not be larger.
  virtual std::size_t remaining() const { return SIZE_MAX; }
};

class FileInput final : public RawInput {
 public:
  explicit FileInput(std::FILE* f) : f_(f) {}
  ~FileInput() override { std::fclose(f_); }
  FileInput(const FileInput&) = delete;
  FileInput& operator=(const FileInput&) = delete;
  std::size_t read(char* dst, std::size_t n) override {
    const std::size_t got = std::fread(dst, 1, n, f_);
    if (got == 0 && std::ferror(f_) && error_.empty()) error_ = "read error";
    return got;
  }
  const std::string& error() const override { return error_; }

 private:
  std::FILE* f_;
  std::string error_;
};

class MemoryInput final : public RawInput {
 public:
  explicit MemoryInput(std::string_view bytes) : bytes_(bytes) {}
  std::size_t read(char* dst, std::size_t n) override {
    const std::size_t k = std::min(n, bytes_.size() - pos_);
    if (k != 0) std::memcpy(dst, bytes_.data() + pos_, k);
    pos_ += k;
    return k;
  }
  const std::string& error() const override { return error_; }
  std::size_t remaining() const override { return bytes_.size() - pos_; }

 private:
  std::string_view bytes_;
  std::size_t pos_ = 0;
  std::string error_;
};

// Bytes passed through unchanged; `prefix` holds the bytes read for sniffing.
class PlainSource final : public ByteSource {
 public:
  PlainSource(std::unique_ptr<RawInput> in, std::string prefix)
      : in_(std::move(in)), prefix_{std::move(prefix)} {}
  std::size_t read(char* dst, std::size_t n) override {
    std::size_t k = prefix_.take(dst, n);
    if (k == 0) k = in_->read(dst, n);
    offset_ += k;
    return k;
  }
  const std::string& error() const override { return in_->error(); }
  std::uint64_t raw_offset() const override { return offset_; }

 private:
  std::unique_ptr<RawInput> in_;
  HeldBytes prefix_;  // the magic bytes read to choose this source
  std::uint64_t offset_ = 0;
};

// Streaming gunzip. Concatenated gzip members are read one after another (as
// gzip(1) does); input that ends inside a member is reported as truncated.
class GzipSource final : public ByteSource {
 public:
  GzipSource(std::unique_ptr<RawInput> in, std::string prefix)
      : in_(std::move(in)),
        inbuf_size_(std::max(prefix.size(), std::min(kChunk, prefix.size() + std::min(kChunk, in_->remaining())))),
        inbuf_(new char[inbuf_size_]) {
    std::memcpy(inbuf_.get(), prefix.data(), prefix.size());
    avail_ = prefix.size();
    inbuf_used_ = prefix.size();
    std::memset(&zs_, 0, sizeof zs_);
    // 15 + 16: gzip wrapper only, maximum window.
    if (inflateInit2(&zs_, 15 + 16) != Z_OK) {
      error_ = "zlib init failed";
      done_ = true;
    }
  }
  ~GzipSource() override { inflateEnd(&zs_); }
  GzipSource(const GzipSource&) = delete;
  GzipSource& operator=(const GzipSource&) = delete;

  std::size_t read(char* dst, std::size_t n) override {
    std::size_t produced = 0;
    while (produced == 0 && !done_) {
      if (avail_ == 0 && !eof_) refill();
      if (avail_ == 0 && eof_) {
        if (in_member_) error_ = "truncated gzip stream at offset " + std::to_string(offset_);
        if (!in_->error().empty() && error_.empty()) error_ = in_->error();
        done_ = true;
        break;
      }
      zs_.next_in = reinterpret_cast<Bytef*>(inbuf_.get() + (inbuf_used_ - avail_));
      zs_.avail_in = static_cast<uInt>(avail_);
      zs_.next_out = reinterpret_cast<Bytef*>(dst);
      zs_.avail_out = static_cast<uInt>(std::min<std::size_t>(n, 1u << 30));
      in_member_ = true;
      const int rc = inflate(&zs_, Z_NO_FLUSH);
      const std::size_t consumed = avail_ - zs_.avail_in;
      offset_ += consumed;
      avail_ = zs_.avail_in;
      produced = n - zs_.avail_out;
      if (rc == Z_STREAM_END) {
        in_member_ = false;
        inflateReset(&zs_);
        // Another member may follow; anything else (padding) ends the data.
        if (avail_ > 0 && static_cast<unsigned char>(inbuf_[inbuf_used_ - avail_]) != 0x1f) {
          done_ = true;
        }
      } else if (rc != Z_OK && rc != Z_BUF_ERROR) {
        error_ = "corrupt gzip data at offset " + std::to_string(offset_) +
                 (zs_.msg ? std::string(": ") + zs_.msg : std::string());
        done_ = true;
      }
    }
    return produced;
  }
  const std::string& error() const override { return error_; }
  std::uint64_t raw_offset() const override { return offset_; }

 private:
  static constexpr std::size_t kChunk = 256 * 1024;
  void refill() {
    const std::size_t got = in_->read(inbuf_.get(), inbuf_size_);
    inbuf_used_ = got;
    avail_ = got;
    if (got == 0) eof_ = true;
  }

  std::unique_ptr<RawInput> in_;
  // Not zeroed, and no larger than an input in memory: a small input costs
  // a small buffer.
  std::size_t inbuf_size_;
  std::unique_ptr<char[]> inbuf_;
  std::size_t inbuf_used_ = 0;
  std::size_t avail_ = 0;
  bool eof_ = false, done_ = false, in_member_ = false;
  std::uint64_t offset_ = 0;
  z_stream zs_;
  std::string error_;
};

std::unique_ptr<ByteSource> make_source(std::unique_ptr<RawInput> in) {
  std::string prefix(2, '\0');
  std::size_t got = 0;
  while (got < 2) {
    const std::size_t k = in->read(prefix.data() + got, 2 - got);
    if (k == 0) break;
    got += k;
  }
  prefix.resize(got);
  if (got == 2 && static_cast<unsigned char>(prefix[0]) == 0x1f &&
      static_cast<unsigned char>(prefix[1]) == 0x8b) {
    auto g = std::make_unique<GzipSource>(std::move(in), std::move(prefix));
    // GzipSource copies the prefix into its input buffer as pending input.
    return g;
  }
  return std::make_unique<PlainSource>(std::move(in), std::move(prefix));
}

}  // namespace

std::unique_ptr<ByteSource> open_file_source(const std::string& path, std::string& error) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (f == nullptr) {
    error = "cannot open " + path + ": " + std::strerror(errno);
    return nullptr;
  }
  return make_source(std::make_unique<FileInput>(f));
}

std::unique_ptr<ByteSource> open_memory_source(std::string_view bytes) {
  return make_source(std::make_unique<MemoryInput>(bytes));
}

}  // namespace mc::ingest
