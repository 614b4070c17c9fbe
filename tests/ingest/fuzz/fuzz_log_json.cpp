// libFuzzer target: the JSON log reader (element splitter + record decoder).
#include <cstddef>
#include <cstdint>
#include <string>

#include "server/ingest/state_source.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::string bytes = "[\n";
  bytes.append(reinterpret_cast<const char*>(data), size);
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
