#include "server/nats/envelope.hpp"

namespace mc::nats {
namespace {

void put_u64(std::string& out, std::uint64_t v) {
  for (int i = 0; i < 8; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
void put_u32(std::string& out, std::uint32_t v) {
  for (int i = 0; i < 4; ++i) out.push_back(static_cast<char>((v >> (8 * i)) & 0xFF));
}
std::uint64_t get_le(std::string_view b, std::size_t at, int n) {
  std::uint64_t v = 0;
  for (int i = 0; i < n; ++i) v |= static_cast<std::uint64_t>(static_cast<unsigned char>(b[at + i])) << (8 * i);
  return v;
}

bool known_kind(char c) {
  switch (static_cast<Kind>(c)) {
    case Kind::Hello:
    case Kind::Keyframe:
    case Kind::Delta:
    case Kind::Control:
    case Kind::Snapshot: return true;
  }
  return false;
}

}  // namespace

std::string wrap(Kind kind, std::uint64_t number, std::string_view payload) {
  std::string out;
  out.reserve(kEnvelopeHeaderSize + payload.size());
  out.push_back(static_cast<char>(kind));
  put_u64(out, number);
  out.append(payload);
  return out;
}

bool unwrap(std::string_view bytes, Envelope& out, std::string& error) {
  if (bytes.size() < kEnvelopeHeaderSize) {
    error = "envelope of " + std::to_string(bytes.size()) + " bytes is shorter than its 9-byte header";
    return false;
  }
  if (bytes.size() - kEnvelopeHeaderSize > kMaxPayload) {
    error = "envelope payload of " + std::to_string(bytes.size() - kEnvelopeHeaderSize) + " bytes is too large";
    return false;
  }
  if (!known_kind(bytes[0])) {
    error = "unknown envelope kind byte " + std::to_string(static_cast<unsigned char>(bytes[0]));
    return false;
  }
  out.kind = static_cast<Kind>(bytes[0]);
  out.number = get_le(bytes, 1, 8);
  out.payload = bytes.substr(kEnvelopeHeaderSize);
  return true;
}

std::string wrap_snapshot(std::uint64_t number, std::string_view hello, std::string_view keyframe) {
  std::string payload;
  payload.reserve(4 + hello.size() + keyframe.size());
  put_u32(payload, static_cast<std::uint32_t>(hello.size()));
  payload.append(hello);
  payload.append(keyframe);
  return wrap(Kind::Snapshot, number, payload);
}

bool unwrap_snapshot(const Envelope& envelope, Snapshot& out, std::string& error) {
  if (envelope.kind != Kind::Snapshot) {
    error = std::string("expected a snapshot, got ") + kind_name(envelope.kind);
    return false;
  }
  const std::string_view p = envelope.payload;
  if (p.size() < 4) {
    error = "snapshot shorter than its hello length";
    return false;
  }
  const std::uint64_t hello_size = get_le(p, 0, 4);
  if (hello_size == 0 || hello_size > p.size() - 4) {
    error = "snapshot hello length " + std::to_string(hello_size) + " does not fit its " +
            std::to_string(p.size()) + " bytes";
    return false;
  }
  out.hello = p.substr(4, hello_size);
  out.keyframe = p.substr(4 + hello_size);
  return true;
}

const char* kind_name(Kind kind) {
  switch (kind) {
    case Kind::Hello: return "hello";
    case Kind::Keyframe: return "keyframe";
    case Kind::Delta: return "delta";
    case Kind::Control: return "control";
    case Kind::Snapshot: return "snapshot";
  }
  return "unknown";
}

}  // namespace mc::nats
