// libFuzzer target: the streaming gunzip byte source and log sniffing on
// arbitrary (often gzip-looking) bytes.
#include <cstddef>
#include <cstdint>
#include <string>

#include "server/ingest/byte_source.hpp"
#include "server/ingest/state_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes("\x1f\x8b", 2);
  bytes.append(reinterpret_cast<const char*>(data), size);
  auto src = mc::ingest::open_memory_source(bytes);
  char buf[4096];
  std::size_t total = 0;
  while (std::size_t n = src->read(buf, sizeof buf)) {
    total += n;
    if (total > (64u << 20)) break;  // a zip bomb is not a crash
  }
  std::string err;
  auto log = mc::ingest::open_log_memory(bytes, err);
  mc::WorldState s;
  for (int i = 0; log && i < 1000 && log->next(s); ++i) {
  }
  return 0;
}
