#include "server/ingest/capture_source.hpp"

#include <cstring>
#include <vector>

#include "server/ingest/byte_source.hpp"
#include "server/ingest/monitor_stream.hpp"

namespace mc::ingest {
namespace {

// A capture record longer than this cannot be a UDP datagram at all; the
// file is then corrupt and reading stops (there is no way to resync).
constexpr std::uint32_t kMaxRecord = 65536;

class CaptureSource final : public StateSource {
 public:
  explicit CaptureSource(std::unique_ptr<ByteSource> src) : src_(std::move(src)), buf_(kMaxRecord) {}

  bool next(WorldState& out) override {
    while (!done_) {
      unsigned char hdr[14];
      const std::uint64_t at = offset_;
      if (!read_exact(reinterpret_cast<char*>(hdr), sizeof hdr)) break;
      const std::uint32_t len = std::uint32_t{hdr[10]} | std::uint32_t{hdr[11]} << 8 |
                                std::uint32_t{hdr[12]} << 16 | std::uint32_t{hdr[13]} << 24;
      if (len > kMaxRecord) {
        record_skip(stream_.stats(), "capture record at offset " + std::to_string(at) +
                                         ": length " + std::to_string(len) + " too large, stopping");
        break;
      }
      if (!read_exact(buf_.data(), len)) break;
      if (stream_.push(std::string_view(buf_.data(), len), out)) return true;
    }
    done_ = true;
    return false;
  }
  const GameParams& params() const override { return stream_.params(); }
  const IngestStats& stats() const override { return stream_.stats(); }
  bool poll_event(SourceEvent& out) override { return stream_.poll_event(out); }

 private:
  bool read_exact(char* dst, std::size_t n) {
    std::size_t got = 0;
    while (got < n) {
      const std::size_t k = src_->read(dst + got, n - got);
      if (k == 0) break;
      got += k;
    }
    offset_ += got;
    if (got == n) return true;
    if (got != 0)
      record_skip(stream_.stats(), "capture truncated at offset " + std::to_string(offset_));
    if (!src_->error().empty()) record_skip(stream_.stats(), "input ends badly: " + src_->error());
    return false;
  }

  std::unique_ptr<ByteSource> src_;
  std::vector<char> buf_;
  MonitorStream stream_;
  std::uint64_t offset_ = 0;
  bool done_ = false;
};

}  // namespace

std::unique_ptr<StateSource> open_monitor_capture(const std::string& path, std::string& error) {
  auto src = open_file_source(path, error);
  if (!src) return nullptr;
  return std::make_unique<CaptureSource>(std::move(src));
}

}  // namespace mc::ingest
