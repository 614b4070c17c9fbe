// libFuzzer: any bytes on a NATS subject go through unwrap / unwrap_snapshot
// without a crash, and what unwraps re-wraps to the same bytes.
#include <cstdint>
#include <cstdlib>
#include <string>

#include "server/nats/envelope.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string bytes(reinterpret_cast<const char*>(data), size);
  mc::nats::Envelope e;
  std::string error;
  if (!mc::nats::unwrap(bytes, e, error)) return 0;
  if (mc::nats::wrap(e.kind, e.number, e.payload) != bytes) std::abort();
  mc::nats::Snapshot s;
  if (e.kind == mc::nats::Kind::Snapshot && mc::nats::unwrap_snapshot(e, s, error)) {
    if (mc::nats::wrap_snapshot(e.number, s.hello, s.keyframe) != bytes) std::abort();
  }
  return 0;
}
