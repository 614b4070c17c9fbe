#include "proto/control_binary.hpp"

#include <cstdint>
#include <limits>
#include <variant>

#include "proto/control_messages.hpp"
#include "proto/pose_frame.hpp"

namespace mc::proto::rec {
namespace {

constexpr std::uint8_t kTagStamina = 1, kTagKick = 2;
// Stamina is stored as its distance below the usual maximum (rcssserver's
// stamina_max), so that rested players cost one byte.
constexpr std::int64_t kStaminaTop = 8000;

void put_varint(std::string& out, std::uint64_t v) {
  while (v >= 0x80) {
    out.push_back(static_cast<char>((v & 0x7f) | 0x80));
    v >>= 7;
  }
  out.push_back(static_cast<char>(v));
}
void put_signed(std::string& out, std::int64_t v) {
  put_varint(out, v >= 0 ? static_cast<std::uint64_t>(v) << 1 : (static_cast<std::uint64_t>(-(v + 1)) << 1) | 1u);
}

// Reads numbers off the front of the bytes; any fault sticks.
struct Reader {
  std::string_view in;
  bool ok = true;
  std::uint64_t varint() {
    std::uint64_t v = 0;
    for (int shift = 0; shift < 64; shift += 7) {
      if (in.empty()) break;
      const auto b = static_cast<unsigned char>(in.front());
      in.remove_prefix(1);
      v |= static_cast<std::uint64_t>(b & 0x7f) << shift;
      if ((b & 0x80) == 0) return v;
    }
    ok = false;
    return 0;
  }
  std::int64_t signed_value() {
    const std::uint64_t u = varint();
    return (u & 1u) ? -static_cast<std::int64_t>(u >> 1) - 1 : static_cast<std::int64_t>(u >> 1);
  }
  // A signed value that must lie in [lo, hi].
  std::int64_t in_range(std::int64_t lo, std::int64_t hi) {
    const std::int64_t v = signed_value();
    if (v < lo || v > hi) ok = false;
    return ok ? v : lo;
  }
};

std::string encode(const StaminaUpdate& e) {
  std::string out(1, static_cast<char>(kTagStamina));
  put_varint(out, e.seq);
  put_signed(out, e.time);
  for (const auto* team : {&e.left, &e.right})
    for (int v : *team) put_signed(out, kStaminaTop - v);
  return out;
}

std::string encode(const KickEvent& e) {
  std::string out(1, static_cast<char>(kTagKick));
  put_varint(out, e.seq);
  put_signed(out, e.time);
  // side (2 bits: 0 neutral, 1 left, 2 right) | foot (1 bit) | unum (4 bits)
  const unsigned side = e.side == Side::Left ? 1u : e.side == Side::Right ? 2u : 0u;
  out.push_back(static_cast<char>(side | (e.foot == Foot::Left ? 4u : 0u) | (static_cast<unsigned>(e.unum) << 3)));
  // The contact is within a frame or two of the kick's own frame (seq * 50 ms).
  put_signed(out, static_cast<std::int64_t>(e.contact_time_ms) - static_cast<std::int64_t>(e.seq) * kFrameIntervalMs);
  return out;
}

}  // namespace

std::string compact_control(std::string_view json_text) {
  // Only the two frequent messages are worth a parse; the others are left
  // alone without one.
  if (json_text.find(R"("type":"stamina")") == std::string_view::npos &&
      json_text.find(R"("type":"kick")") == std::string_view::npos)
    return {};
  ControlMessage m;
  std::string error;
  if (!control_from_json(json_text, m, error) || to_json(m) != json_text) return {};
  std::string out;
  if (const auto* s = std::get_if<StaminaUpdate>(&m)) out = encode(*s);
  else if (const auto* k = std::get_if<KickEvent>(&m)) {
    if (k->contact_time_ms > static_cast<std::uint64_t>(std::numeric_limits<std::int64_t>::max() / 2)) return {};
    out = encode(*k);
  } else return {};
  // The form must give back exactly this text (what a reader will produce).
  std::string back;
  return expand_control(out, back) && back == json_text ? out : std::string();
}

bool expand_control(std::string_view bytes, std::string& json_text) {
  if (bytes.empty()) return false;
  Reader r{bytes.substr(1)};
  const auto tag = static_cast<unsigned char>(bytes[0]);
  ControlMessage m;
  if (tag == kTagStamina) {
    StaminaUpdate e;
    const std::uint64_t seq = r.varint();
    if (seq > std::numeric_limits<std::uint32_t>::max()) r.ok = false;
    e.seq = static_cast<std::uint32_t>(seq);
    e.time = static_cast<int>(r.in_range(std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
    for (auto* team : {&e.left, &e.right})
      for (int& v : *team) v = static_cast<int>(kStaminaTop - r.in_range(kStaminaTop - 1000000, kStaminaTop + 1));
    m = e;
  } else if (tag == kTagKick) {
    KickEvent e;
    const std::uint64_t seq = r.varint();
    if (seq > std::numeric_limits<std::uint32_t>::max()) r.ok = false;
    e.seq = static_cast<std::uint32_t>(seq);
    e.time = static_cast<int>(r.in_range(std::numeric_limits<int>::min(), std::numeric_limits<int>::max()));
    if (r.in.empty()) return false;
    const auto bits = static_cast<unsigned char>(r.in.front());
    r.in.remove_prefix(1);
    if ((bits & 3u) == 3u || (bits >> 3) > kPlayersPerSide) return false;
    e.side = (bits & 3u) == 1u ? Side::Left : (bits & 3u) == 2u ? Side::Right : Side::Neutral;
    e.foot = (bits & 4u) ? Foot::Left : Foot::Right;
    e.unum = static_cast<std::uint8_t>(bits >> 3);
    const std::int64_t base = static_cast<std::int64_t>(e.seq) * kFrameIntervalMs;
    const std::int64_t contact = base + r.in_range(-base, std::numeric_limits<std::int64_t>::max() / 4);
    e.contact_time_ms = static_cast<std::uint64_t>(contact);
    m = e;
  } else {
    return false;
  }
  if (!r.ok || !r.in.empty()) return false;
  json_text = to_json(m);
  return true;
}

}  // namespace mc::proto::rec
