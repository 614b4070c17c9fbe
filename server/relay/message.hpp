// An outbound WebSocket message, encoded once and shared, immutable, by every
// session that sends it (Beast chat-multi's shared_ptr<const std::string>).
//
// Besides the payload it carries its WebSocket frame, built once: a server
// frame is never masked, so the header (FIN, opcode, length) is the same for
// every spectator, and a session writes the framed bytes of a whole batch
// with one gathered write (uWebSockets' corking) instead of one Beast write
// per message. That is only valid without permessage-deflate, which the
// relay never enables.
#pragma once

#include <chrono>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <utility>

namespace mc::relay {

// The header of one unmasked, final WebSocket frame of `size` payload bytes
// (RFC 6455 section 5.2): 2, 4 or 10 bytes.
std::string websocket_frame_header(bool binary, std::size_t size);
// The same for any opcode (8 close, 9 ping, 10 pong).
std::string websocket_frame_header_op(std::uint8_t opcode, std::size_t size);

struct Message {
  // Session: bytes one session sends for itself (the handshake response, a
  // pong, a close frame): wire only, never recorded, never dropped.
  enum class Kind : std::uint8_t { Control, Keyframe, Delta, Session };

  // The payload (what recorders and tests read).
  std::shared_ptr<const std::string> bytes;
  Kind kind = Kind::Control;
  // When the channel published it: the start of the relay's frame delay.
  std::chrono::steady_clock::time_point published{};
  // Header + payload: what goes on the wire as is.
  std::shared_ptr<const std::string> wire;
  // Its number among its channel's published messages (0: none).
  std::uint64_t serial = 0;

  bool binary() const { return kind == Kind::Keyframe || kind == Kind::Delta; }
  // Control messages (JSON) are never dropped; deltas may be, keyframes end a skip.
  bool droppable() const { return kind == Kind::Delta; }
  std::size_t size() const { return bytes ? bytes->size() : 0; }

  static Message make(std::shared_ptr<const std::string> payload, Kind kind) {
    auto framed = std::make_shared<std::string>(websocket_frame_header(kind != Kind::Control, payload->size()));
    framed->append(*payload);
    return {std::move(payload), kind, std::chrono::steady_clock::now(), std::move(framed)};
  }
  static Message control(std::string text) {
    return make(std::make_shared<const std::string>(std::move(text)), Kind::Control);
  }
  // Bytes that go on the wire exactly as given (the 101 response).
  static Message session_bytes(std::string wire) {
    return {nullptr, Kind::Session, std::chrono::steady_clock::now(),
            std::make_shared<const std::string>(std::move(wire))};
  }
  // A control frame of one session: ping, pong or close.
  static Message session_frame(std::uint8_t opcode, std::string_view payload) {
    std::string wire = websocket_frame_header_op(opcode, payload.size());
    wire.append(payload);
    return session_bytes(std::move(wire));
  }
  static Message frame(std::string data, bool keyframe) {
    return make(std::make_shared<const std::string>(std::move(data)), keyframe ? Kind::Keyframe : Kind::Delta);
  }
};

}  // namespace mc::relay
