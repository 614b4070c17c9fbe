// libFuzzer target: the live feed's datagram parser (MonitorStream, all
// protocol versions). The input is cut at 0xff bytes into several
// datagrams, so state carried between datagrams is exercised too.
#include <cstddef>
#include <cstdint>
#include <string_view>

#include "server/ingest/monitor_stream.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  mc::ingest::MonitorStream stream;  // fresh: nothing of one input reaches the next
  // Written only, never read: kept from input to input (building two world
  // states an input was 7 % of this target's time).
  static mc::WorldState s;
  static mc::ingest::SourceEvent ev;
  const char* p = reinterpret_cast<const char*>(data);
  std::string_view rest(p, size);
  while (true) {
    const std::size_t cut = rest.find('\xff');
    stream.push(rest.substr(0, cut), s);
    while (stream.poll_event(ev)) {
    }
    if (cut == std::string_view::npos) break;
    rest.remove_prefix(cut + 1);
  }
  return 0;
}
