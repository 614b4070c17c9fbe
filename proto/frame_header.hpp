// The fixed 26-byte header at the start of every encoded pose frame
// (SPEC.md "Frame header"). It is byte-aligned and little-endian so that the
// relay and the recorder read it without decoding the frame.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>

namespace mc::proto {

inline constexpr std::uint8_t kFrameMagic = 0x4D;  // 'M'
inline constexpr std::uint8_t kProtocolMajor = 1;  // a decoder refuses any other major
inline constexpr std::uint8_t kProtocolMinor = 0;  // newer minors only append data
inline constexpr std::size_t kFrameHeaderSize = 26;

struct FrameHeader {
  std::uint8_t major = kProtocolMajor;
  std::uint8_t minor = kProtocolMinor;
  bool keyframe = false;
  std::uint32_t seq = 0;            // frame number; deltas need seq == previous + 1
  int time = 0;                     // simulation cycle
  int stoppage = 0;                 // WorldState::stoppage (0..65535)
  std::uint8_t substep = 0;         // 0 at the cycle, 1 half-way to the next
  std::uint8_t play_mode = 0;       // mc::PlayMode value
  std::uint8_t score_left = 0, score_right = 0;
  std::uint64_t server_time_ms = 0; // Unix ms when the frame left the server
};

void write_header(const FrameHeader& header, std::string& out);  // appends 26 bytes

// Reads the header of any encoded frame. False, with `error` saying why,
// when the bytes are shorter than a header, the magic byte is wrong, or the
// major version is not kProtocolMajor (`out` is still filled in that last
// case, so a caller may report the version it saw).
bool peek_header(std::string_view bytes, FrameHeader& out, std::string& error);

// Overwrites the server timestamp of an already-encoded frame in place, so a
// sender can stamp shared bytes just before they leave. False when `bytes`
// is shorter than a header.
bool stamp_server_time(std::string& bytes, std::uint64_t server_time_ms);

}  // namespace mc::proto
