#include "server/relay/message.hpp"

namespace mc::relay {

std::string websocket_frame_header(bool binary, std::size_t size) {
  return websocket_frame_header_op(binary ? 0x2 : 0x1, size);
}

std::string websocket_frame_header_op(std::uint8_t opcode, std::size_t size) {
  std::string h;
  h.push_back(static_cast<char>(0x80 | (opcode & 0x0F)));  // FIN + opcode
  if (size < 126) {
    h.push_back(static_cast<char>(size));
  } else if (size <= 0xFFFF) {
    h.push_back(static_cast<char>(126));
    h.push_back(static_cast<char>(size >> 8));
    h.push_back(static_cast<char>(size & 0xFF));
  } else {
    h.push_back(static_cast<char>(127));
    for (int shift = 56; shift >= 0; shift -= 8)
      h.push_back(static_cast<char>((static_cast<std::uint64_t>(size) >> shift) & 0xFF));
  }
  return h;
}

}  // namespace mc::relay
