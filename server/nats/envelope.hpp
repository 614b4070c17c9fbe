// The bytes Matchcast puts on NATS (server/nats/README.md, "Wire"): each
// relay message travels in an envelope that keeps its kind and numbers it,
// so an edge rebuilds exactly the channel the origin has, notices a lost
// message, and merges the latest keyframe with the live subject without
// duplicates.
//
//   envelope: u8 kind | u64 number (little-endian) | payload
//   kind:     'H' hello (JSON), 'K' keyframe, 'D' delta (proto/SPEC.md frames),
//             'C' control (JSON event or status), 'S' snapshot
//   snapshot: payload = u32 hello length | hello | keyframe (may be empty);
//             number = the number of the keyframe (or of the hello alone)
//
// The payload is the relay's own bytes, unchanged: frames are encoded once at
// the origin and the same bytes reach every spectator of every edge.
// Pure functions, no I/O; every decoder refuses malformed input with a reason.
#pragma once

#include <cstddef>
#include <cstdint>
#include <string>
#include <string_view>

namespace mc::nats {

enum class Kind : char {
  Hello = 'H',
  Keyframe = 'K',
  Delta = 'D',
  Control = 'C',
  Snapshot = 'S',
};

inline constexpr std::size_t kEnvelopeHeaderSize = 9;
// Largest payload accepted: a hello with its skeleton is a few KB, a frame
// under 1 KB. NATS' own default max_payload is 1 MB.
inline constexpr std::size_t kMaxPayload = 1 << 20;

struct Envelope {
  Kind kind = Kind::Control;
  std::uint64_t number = 0;  // +1 per message the origin publishes on a game
  std::string_view payload;  // points into the bytes given to unwrap()
};

std::string wrap(Kind kind, std::uint64_t number, std::string_view payload);
// False with `error` when `bytes` is too short, too long, or of unknown kind.
bool unwrap(std::string_view bytes, Envelope& out, std::string& error);

struct Snapshot {
  std::string_view hello;
  std::string_view keyframe;  // empty: the hello alone (no keyframe yet)
};

std::string wrap_snapshot(std::uint64_t number, std::string_view hello, std::string_view keyframe);
// `envelope` must be of kind Snapshot; false with `error` when its payload
// is malformed or its hello is empty.
bool unwrap_snapshot(const Envelope& envelope, Snapshot& out, std::string& error);

const char* kind_name(Kind kind);

}  // namespace mc::nats
