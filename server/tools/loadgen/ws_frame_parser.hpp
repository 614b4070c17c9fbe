// Splits the server -> client bytes of a WebSocket connection into frames
// (RFC 6455 section 5.2), so that a simulated spectator can read a whole
// socket buffer with one recv and take every frame in it, instead of one
// Beast read operation per message. Server frames are never masked; the
// relay never fragments a message.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string_view>

namespace mc::loadgen {

struct WsFrame {
  std::uint8_t opcode = 0;   // 1 text, 2 binary, 8 close, 9 ping, 10 pong
  bool fin = true;
  std::string_view payload;  // points into the parsed bytes
  std::size_t size = 0;      // header + payload: what to consume
};

enum class ParseResult { Frame, NeedMore, Bad };

// Parses the frame at the start of `bytes`. Bad: a masked server frame, a
// reserved bit set, or a length over `max_payload`.
ParseResult parse_frame(std::string_view bytes, WsFrame& out, std::size_t max_payload = 16 << 20);

}  // namespace mc::loadgen
