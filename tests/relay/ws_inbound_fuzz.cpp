// libFuzzer: whatever a hostile spectator sends over its WebSocket, split at
// any point. The reader must never crash, never hand out more than
// max_message bytes, and stop for good after an error.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string_view>

#include "server/relay/ws_inbound.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  constexpr std::size_t kMax = 4096;
  mc::relay::WsInbound in(kMax);
  // The first byte chooses the chunk size: the same bytes arrive in pieces.
  const std::size_t chunk = 1 + data[0] % 64;
  const std::string_view bytes(reinterpret_cast<const char*>(data + 1), size - 1);
  bool failed = false;
  for (std::size_t at = 0; at < bytes.size(); at += chunk) {
    in.feed(bytes.substr(at, chunk));
    mc::relay::WsInbound::Event ev;
    while (in.next(ev)) {
      if (failed) std::abort();  // nothing after an error
      if (ev.kind == mc::relay::WsInbound::Kind::Error) failed = true;
      if (ev.data.size() > kMax) std::abort();
    }
    if (in.buffered() > 2 * kMax + 14 + 64 && !failed) std::abort();  // a frame and a message at most
    in.shrink();
  }
  return 0;
}
