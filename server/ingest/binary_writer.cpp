#include "server/ingest/binary_writer.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

#include "server/ingest/binary_records.hpp"

namespace mc::ingest::binary {
namespace {

constexpr double kDegToRad = std::numbers::pi / 180.0;

std::int64_t clamp_round(double v, double lo, double hi) {
  if (!std::isfinite(v)) return 0;
  return static_cast<std::int64_t>(std::llround(std::clamp(v, lo, hi)));
}
void put16(std::string& b, std::size_t at, double v) {
  const auto x = static_cast<std::uint16_t>(static_cast<std::int16_t>(clamp_round(v, -32768, 32767)));
  b[at] = static_cast<char>(x >> 8);
  b[at + 1] = static_cast<char>(x & 0xff);
}
void put32(std::string& b, std::size_t at, double v) {
  const auto x = static_cast<std::uint32_t>(static_cast<std::int32_t>(clamp_round(v, -2147483648.0, 2147483647.0)));
  for (int i = 0; i < 4; ++i) b[at + static_cast<std::size_t>(i)] = static_cast<char>((x >> (24 - 8 * i)) & 0xff);
}
void fixed(std::string& b, std::size_t at, double v) { put32(b, at, v * 65536.0); }

// team_t: char name[16] (NUL-padded, "null" for no team); Int16 score.
void team(std::string& b, std::size_t at, const TeamInfo& t) {
  const std::string name = t.name.empty() ? "null" : t.name;
  std::memcpy(b.data() + at, name.data(), std::min<std::size_t>(name.size(), 15));
  put16(b, at + 16, t.score);
}

// dispinfo_t (v1) or dispinfo_t2 (v2) with `mode`; returns the union offset.
std::string record(int version, Mode mode, std::size_t& body) {
  std::string b(version == 1 ? kDispInfoSize : kDispInfo2Size, '\0');
  put16(b, 0, mode);
  body = version == 1 ? 2 : 4;
  return b;
}

// player_t (64 bytes), see binary_records.cpp.
void player(std::string& b, std::size_t at, const PlayerState& p) {
  put16(b, at, static_cast<double>(p.state & 0xffffu));
  put16(b, at + 2, p.type);
  fixed(b, at + 4, p.x);
  fixed(b, at + 8, p.y);
  fixed(b, at + 12, p.vx);
  fixed(b, at + 16, p.vy);
  fixed(b, at + 20, p.body * kDegToRad);
  fixed(b, at + 24, p.neck * kDegToRad);
  fixed(b, at + 28, p.view_width * kDegToRad);
  put16(b, at + 32, p.view_quality == 'h' ? 1 : 0);
  fixed(b, at + 36, p.stamina);
  fixed(b, at + 40, p.effort);
  fixed(b, at + 44, p.recovery);
  const CommandCounters& c = p.counters;
  const std::uint32_t counts[8] = {c.kick, c.dash, c.turn, c.say, c.turn_neck, c.catch_, c.move, c.change_view};
  for (std::size_t i = 0; i < 8; ++i) put16(b, at + 48 + 2 * i, static_cast<double>(counts[i] & 0x7fff));
}

}  // namespace

std::string encode_show(const WorldState& s, int version) {
  std::size_t o = 0;
  std::string b = record(version, kShow, o);
  b[o] = static_cast<char>(s.play_mode);
  team(b, o + 2, s.left);
  team(b, o + 20, s.right);
  if (version == 1) {
    // showinfo_t: pos_t[23] at 38 (pos[0] = ball), Int16 time at 314.
    const std::size_t pos = o + 38;
    put16(b, pos + 8, s.ball.x * 16);
    put16(b, pos + 10, s.ball.y * 16);
    for (int i = 0; i < kMaxPlayers; ++i) {
      const PlayerState& p = s.players[static_cast<std::size_t>(i)];
      const std::size_t q = pos + 12 * static_cast<std::size_t>(i + 1);
      put16(b, q, static_cast<double>(p.state & 0xffffu));
      put16(b, q + 2, i < kPlayersPerSide ? 1 : -1);
      put16(b, q + 4, i % kPlayersPerSide + 1);
      put16(b, q + 6, p.body);
      put16(b, q + 8, p.x * 16);
      put16(b, q + 10, p.y * 16);
    }
    put16(b, o + 314, s.time);
    return b;
  }
  // showinfo_t2: ball_t at 40, player_t[22] at 56, Int16 time at 1464.
  fixed(b, o + 40, s.ball.x);
  fixed(b, o + 44, s.ball.y);
  fixed(b, o + 48, s.ball.vx);
  fixed(b, o + 52, s.ball.vy);
  for (int i = 0; i < kMaxPlayers; ++i) player(b, o + 56 + 64 * static_cast<std::size_t>(i), s.players[static_cast<std::size_t>(i)]);
  put16(b, o + 1464, s.time);
  return b;
}

std::string encode_msg(const MessageRecord& m, int version) {
  std::size_t o = 0;
  std::string b = record(version, kMsg, o);
  put16(b, o, m.board);
  std::memcpy(b.data() + o + 2, m.text.data(), std::min<std::size_t>(m.text.size(), 2047));
  return b;
}

std::vector<std::string> encode_params(const GameParams& p, int version) {
  std::vector<std::string> out;
  if (version != 2) return out;  // v1 monitors get no init block
  std::size_t o = 0;
  std::string param = record(version, kParam, o);
  std::string tmp(kServerParamsSize, '\0');
  encode_server_params(p.server, tmp);
  std::memcpy(param.data() + o, tmp.data(), tmp.size());
  out.push_back(std::move(param));
  out.push_back(record(version, kPlayerParam, o));
  for (const PlayerType& t : p.player_types) {
    std::string pt = record(version, kPlayerType, o);
    put16(pt, o, t.id);
    const double fields[] = {t.player_speed_max, t.stamina_inc_max, t.player_decay, t.inertia_moment,
                             t.dash_power_rate,  t.player_size,     t.kickable_margin, t.kick_rand,
                             t.extra_stamina,    t.effort_max,      t.effort_min, t.kick_power_rate,
                             t.foul_detect_probability, t.catchable_area_l_stretch};
    for (std::size_t i = 0; i < std::size(fields); ++i) fixed(pt, o + 4 + 4 * i, fields[i]);
    out.push_back(std::move(pt));
  }
  return out;
}

}  // namespace mc::ingest::binary
