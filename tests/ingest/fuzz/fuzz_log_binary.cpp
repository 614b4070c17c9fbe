// libFuzzer target: the binary log readers. The first input byte picks the
// version (v1 headerless, "ULG\x02", "ULG\x03"); the rest is the body.
#include <cstddef>
#include <cstdint>
#include <string>

#include "server/ingest/state_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size < 1) return 0;
  std::string bytes;
  switch (data[0] % 3) {
    case 0: bytes.assign("\x00\x01", 2); break;  // v1 starts with a SHOW_MODE record
    case 1: bytes.assign("ULG\x02", 4); break;
    default: bytes.assign("ULG\x03", 4); break;
  }
  bytes.append(reinterpret_cast<const char*>(data + 1), size - 1);
  std::string err;
  auto src = mc::ingest::open_log_memory(bytes, err);
  if (!src) return 0;
  mc::WorldState s;
  mc::ingest::SourceEvent ev;
  while (src->next(s))
    while (src->poll_event(ev)) {
    }
  return 0;
}
