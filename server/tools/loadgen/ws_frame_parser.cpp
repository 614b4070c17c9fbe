#include "server/tools/loadgen/ws_frame_parser.hpp"

namespace mc::loadgen {

ParseResult parse_frame(std::string_view bytes, WsFrame& out, std::size_t max_payload) {
  if (bytes.size() < 2) return ParseResult::NeedMore;
  const auto b0 = static_cast<std::uint8_t>(bytes[0]);
  const auto b1 = static_cast<std::uint8_t>(bytes[1]);
  if ((b0 & 0x70) != 0 || (b1 & 0x80) != 0) return ParseResult::Bad;  // RSV bits, or masked
  std::uint64_t length = b1 & 0x7F;
  std::size_t header = 2;
  if (length == 126) {
    header = 4;
    if (bytes.size() < header) return ParseResult::NeedMore;
    length = (static_cast<std::uint64_t>(static_cast<std::uint8_t>(bytes[2])) << 8) |
             static_cast<std::uint8_t>(bytes[3]);
  } else if (length == 127) {
    header = 10;
    if (bytes.size() < header) return ParseResult::NeedMore;
    length = 0;
    for (int i = 2; i < 10; ++i) length = (length << 8) | static_cast<std::uint8_t>(bytes[i]);
  }
  if (length > max_payload) return ParseResult::Bad;
  if (bytes.size() < header + length) return ParseResult::NeedMore;
  out.fin = (b0 & 0x80) != 0;
  out.opcode = b0 & 0x0F;
  out.payload = bytes.substr(header, static_cast<std::size_t>(length));
  out.size = header + static_cast<std::size_t>(length);
  return ParseResult::Frame;
}

}  // namespace mc::loadgen
