#include "server/relay/ws_inbound.hpp"

namespace mc::relay {
namespace {

void unmask(char* data, std::size_t n, const unsigned char key[4], std::size_t offset = 0) {
  for (std::size_t i = 0; i < n; ++i) data[i] = static_cast<char>(data[i] ^ key[(offset + i) & 3]);
}

}  // namespace

bool WsInbound::fail(Event& out, CloseCode code, std::string_view why) {
  failed_ = true;
  in_.clear();
  pos_ = 0;
  message_.clear();
  out = {Kind::Error, why, static_cast<std::uint16_t>(code)};
  return true;
}

void WsInbound::shrink() {
  if (pos_ == in_.size()) {
    std::string().swap(in_);
    pos_ = 0;
  }
  if (message_.empty()) std::string().swap(message_);
  if (control_.size() > 0) std::string().swap(control_);
}

bool WsInbound::next(Event& out) {
  for (;;) {
    if (failed_) return false;
    const std::string_view b(in_.data() + pos_, in_.size() - pos_);
    if (b.size() < 2) return false;
    const auto b0 = static_cast<unsigned char>(b[0]), b1 = static_cast<unsigned char>(b[1]);
    const bool fin = b0 & 0x80;
    const std::uint8_t opcode = b0 & 0x0F;
    if (b0 & 0x70) return fail(out, CloseCode::ProtocolError, "reserved bits set (no extension was negotiated)");
    if (!(b1 & 0x80)) return fail(out, CloseCode::ProtocolError, "unmasked frame from a client");
    std::uint64_t len = b1 & 0x7F;
    std::size_t header = 2;
    if (len == 126) {
      if (b.size() < 4) return false;
      len = (static_cast<std::uint64_t>(static_cast<unsigned char>(b[2])) << 8) | static_cast<unsigned char>(b[3]);
      header = 4;
    } else if (len == 127) {
      if (b.size() < 10) return false;
      len = 0;
      for (int i = 0; i < 8; ++i) len = (len << 8) | static_cast<unsigned char>(b[2 + static_cast<std::size_t>(i)]);
      header = 10;
      if (len >> 63) return fail(out, CloseCode::ProtocolError, "frame length with its top bit set");
    }
    const bool control = opcode & 0x8;
    if (control) {
      if (opcode != 0x8 && opcode != 0x9 && opcode != 0xA) return fail(out, CloseCode::ProtocolError, "unknown opcode");
      if (!fin) return fail(out, CloseCode::ProtocolError, "fragmented control frame");
      if (len > 125) return fail(out, CloseCode::ProtocolError, "control frame over 125 bytes");
    } else {
      if (opcode != 0x0 && opcode != 0x1 && opcode != 0x2) return fail(out, CloseCode::ProtocolError, "unknown opcode");
      if (opcode == 0x0 && message_opcode_ == 0) return fail(out, CloseCode::ProtocolError, "continuation with no message to continue");
      if (opcode != 0x0 && message_opcode_ != 0) return fail(out, CloseCode::ProtocolError, "new message inside a fragmented one");
      // Refused before the bytes arrive: a hostile length never grows a buffer.
      if (len > max_message_ || message_.size() + len > max_message_) return fail(out, CloseCode::TooBig, "message too big");
    }
    if (b.size() < header + 4 + len) return false;
    unsigned char key[4];
    for (int i = 0; i < 4; ++i) key[i] = static_cast<unsigned char>(b[header + static_cast<std::size_t>(i)]);
    const std::size_t n = static_cast<std::size_t>(len);
    const char* payload = b.data() + header + 4;
    pos_ += header + 4 + n;
    if (control) {
      control_.assign(payload, n);
      unmask(control_.data(), n, key);
      if (pos_ == in_.size()) { in_.clear(); pos_ = 0; }
      if (opcode == 0x9) { out = {Kind::Ping, control_, 0}; return true; }
      if (opcode == 0xA) { out = {Kind::Pong, control_, 0}; return true; }
      if (n == 1) return fail(out, CloseCode::ProtocolError, "close frame with a one-byte payload");
      std::uint16_t code = 1005;  // no status code present
      std::string_view reason;
      if (n >= 2) {
        code = static_cast<std::uint16_t>((static_cast<unsigned char>(control_[0]) << 8) | static_cast<unsigned char>(control_[1]));
        reason = std::string_view(control_).substr(2);
      }
      out = {Kind::Close, reason, code};
      return true;
    }
    const std::size_t at = message_.size();
    message_.append(payload, n);
    unmask(message_.data() + at, n, key);
    if (opcode != 0x0) message_opcode_ = opcode;
    // Drop consumed input once it is all used, so `in_` never grows with a long session.
    if (pos_ == in_.size()) { in_.clear(); pos_ = 0; }
    if (!fin) continue;
    const Kind kind = message_opcode_ == 0x1 ? Kind::Text : Kind::Binary;
    message_opcode_ = 0;
    control_.swap(message_);  // hand the message out through control_, valid until the next call
    message_.clear();
    out = {kind, control_, 0};
    return true;
  }
}

}  // namespace mc::relay
