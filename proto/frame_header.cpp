#include "proto/frame_header.hpp"

namespace mc::proto {
namespace {

void put_le(std::string& out, std::uint64_t v, int bytes) {
  for (int i = 0; i < bytes; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xffu));
}
std::uint64_t get_le(std::string_view in, std::size_t at, int bytes) {
  std::uint64_t v = 0;
  for (int i = 0; i < bytes; ++i) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(in[at + static_cast<std::size_t>(i)])) << (8 * i);
  return v;
}

}  // namespace

void write_header(const FrameHeader& h, std::string& out) {
  out.push_back(static_cast<char>(kFrameMagic));
  out.push_back(static_cast<char>(h.major));
  out.push_back(static_cast<char>(h.minor));
  out.push_back(static_cast<char>(h.keyframe ? 1 : 0));
  put_le(out, h.seq, 4);
  put_le(out, static_cast<std::uint32_t>(h.time), 4);
  put_le(out, static_cast<std::uint16_t>(h.stoppage < 0 ? 0 : h.stoppage > 65535 ? 65535 : h.stoppage), 2);
  out.push_back(static_cast<char>(h.substep));
  out.push_back(static_cast<char>(h.play_mode));
  out.push_back(static_cast<char>(h.score_left));
  out.push_back(static_cast<char>(h.score_right));
  put_le(out, h.server_time_ms, 8);
}

bool peek_header(std::string_view bytes, FrameHeader& out, std::string& error) {
  if (bytes.size() < kFrameHeaderSize) {
    error = "pose frame truncated: " + std::to_string(bytes.size()) + " bytes, the header alone is " +
            std::to_string(kFrameHeaderSize);
    return false;
  }
  if (static_cast<unsigned char>(bytes[0]) != kFrameMagic) {
    error = "not a pose frame: bad magic byte " + std::to_string(static_cast<unsigned char>(bytes[0]));
    return false;
  }
  out.major = static_cast<std::uint8_t>(bytes[1]);
  out.minor = static_cast<std::uint8_t>(bytes[2]);
  out.keyframe = (static_cast<unsigned char>(bytes[3]) & 1u) != 0;
  out.seq = static_cast<std::uint32_t>(get_le(bytes, 4, 4));
  out.time = static_cast<int>(static_cast<std::int32_t>(get_le(bytes, 8, 4)));
  out.stoppage = static_cast<int>(get_le(bytes, 12, 2));
  out.substep = static_cast<std::uint8_t>(bytes[14]);
  out.play_mode = static_cast<std::uint8_t>(bytes[15]);
  out.score_left = static_cast<std::uint8_t>(bytes[16]);
  out.score_right = static_cast<std::uint8_t>(bytes[17]);
  out.server_time_ms = get_le(bytes, 18, 8);
  if (out.major != kProtocolMajor) {
    error = "unsupported pose-frame protocol major version " + std::to_string(out.major) +
            " (this decoder reads version " + std::to_string(kProtocolMajor) + ")";
    return false;
  }
  return true;
}

bool stamp_server_time(std::string& bytes, std::uint64_t server_time_ms) {
  if (bytes.size() < kFrameHeaderSize) return false;
  for (int i = 0; i < 8; ++i) bytes[18 + static_cast<std::size_t>(i)] = static_cast<char>((server_time_ms >> (8 * i)) & 0xffu);
  return true;
}

}  // namespace mc::proto
