// open_log(): sniff the decoded first bytes, then hand the same byte stream,
// those bytes included, to the reader for that format.
#include <memory>

#include "server/ingest/binary_log_source.hpp"
#include "server/ingest/byte_source.hpp"
#include "server/ingest/held_bytes.hpp"
#include "server/ingest/json_log_source.hpp"
#include "server/ingest/log_format.hpp"
#include "server/ingest/state_source.hpp"
#include "server/ingest/text_log_source.hpp"

namespace mc::ingest {

void record_skip(IngestStats& stats, std::string message) {
  ++stats.skipped;
  if (stats.errors.size() < IngestStats::kMaxErrors) stats.errors.push_back(std::move(message));
}

namespace {

// The source after its sniffed head: the head's bytes again, then the rest
// of the same stream. Sniffing then opens, and for gzip inflates, the input
// once, not twice, and a file that changes after the sniff cannot hand the
// parser other bytes than the ones sniffed.
class HeadReplaySource final : public ByteSource {
 public:
  HeadReplaySource(std::string head, std::unique_ptr<ByteSource> rest)
      : head_{std::move(head)}, rest_(std::move(rest)) {}
  std::size_t read(char* dst, std::size_t n) override {
    if (const std::size_t k = head_.take(dst, n)) return k;
    return rest_->read(dst, n);
  }
  const std::string& error() const override { return rest_->error(); }
  std::uint64_t raw_offset() const override { return rest_->raw_offset(); }

 private:
  HeldBytes head_;
  std::unique_ptr<ByteSource> rest_;
};

std::unique_ptr<StateSource> open_with(std::unique_ptr<ByteSource> probe, const std::string& what,
                                       std::string& error) {
  if (!probe) return nullptr;
  // Enough to see past a "ULG6\n" header to the first record.
  std::string head(512, '\0');
  std::size_t got = 0;
  while (got < head.size()) {
    const std::size_t k = probe->read(head.data() + got, head.size() - got);
    if (k == 0) break;
    got += k;
  }
  head.resize(got);
  if (got == 0) {
    error = what + ": empty input" + (probe->error().empty() ? "" : " (" + probe->error() + ")");
    return nullptr;
  }
  const LogFormat fmt = sniff_log_format(head);
  auto src = std::make_unique<HeadReplaySource>(std::move(head), std::move(probe));
  switch (fmt) {
    case LogFormat::TextV4:
    case LogFormat::TextV5:
    case LogFormat::TextV6:
      return make_text_log_source(std::move(src));
    case LogFormat::BinaryV1:
    case LogFormat::BinaryV2:
    case LogFormat::BinaryV3:
      return make_binary_log_source(std::move(src), fmt);
    case LogFormat::Json17:
    case LogFormat::Json18:
    case LogFormat::Json19:
      return make_json_log_source(std::move(src));
    case LogFormat::Unknown:
      break;
  }
  error = what + ": not a game log (unrecognised first bytes)";
  return nullptr;
}

}  // namespace

std::unique_ptr<StateSource> open_log(const std::string& path, std::string& error) {
  return open_with(open_file_source(path, error), path, error);
}

std::unique_ptr<StateSource> open_log_memory(std::string_view bytes, std::string& error) {
  return open_with(open_memory_source(bytes), "memory", error);
}

}  // namespace mc::ingest
