// What a spectator sends, as WebSocket messages: RFC 6455 frames from a
// client (always masked), reassembled from fragments, with control frames
// (ping, pong, close) taken out between them. Pure byte logic, no sockets, so
// it is unit-tested and fuzzed on its own; the session feeds it whatever the
// socket had and acts on the events.
//
// Spectators only ever send small JSON control messages, so the reader
// refuses early and says why: an unmasked frame, reserved bits (the relay
// negotiates no extension), an unknown opcode, a fragmented or oversized
// control frame, a continuation with nothing to continue, a message over
// `max_message` bytes.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace mc::relay {

// RFC 6455 section 7.4.1 close codes the relay sends.
enum class CloseCode : std::uint16_t {
  Normal = 1000,
  GoingAway = 1001,
  ProtocolError = 1002,
  Policy = 1008,
  TooBig = 1009,
};

class WsInbound {
 public:
  enum class Kind { Text, Binary, Ping, Pong, Close, Error };
  struct Event {
    Kind kind = Kind::Error;
    std::string_view data;  // message, ping payload or close reason; valid until the next call
    std::uint16_t code = 0;  // Close: the peer's code (1005 if none); Error: the code to close with
  };

  explicit WsInbound(std::size_t max_message) : max_message_(max_message) {}

  // Appends bytes that arrived (they may end mid-frame).
  void feed(std::string_view bytes) {
    if (pos_ > 0) {  // what was parsed already goes first: the buffer holds one frame at most
      in_.erase(0, pos_);
      pos_ = 0;
    }
    in_.append(bytes);
  }
  // The next complete event, or false when more bytes are needed. After an
  // Error event the reader is done: further calls return false.
  bool next(Event& out);
  // Bytes held for an unfinished frame or message: a session's only buffer.
  std::size_t buffered() const { return in_.size() - pos_ + message_.size(); }
  // Frees the buffers' memory when nothing is pending (an idle spectator
  // then costs no buffer at all).
  void shrink();

 private:
  bool fail(Event& out, CloseCode code, std::string_view why);

  std::size_t max_message_;
  std::string in_;        // received bytes; [pos_, end) not yet parsed
  std::size_t pos_ = 0;
  std::string message_;   // fragments of the message being assembled
  std::string control_;   // the last control frame's payload (unmasked)
  std::uint8_t message_opcode_ = 0;  // 1 or 2 while assembling, else 0
  bool failed_ = false;
};

}  // namespace mc::relay
