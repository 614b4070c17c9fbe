#include "server/ingest/binary_records.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iterator>
#include <cstring>
#include <numbers>

#include "server/ingest/sexp_cursor.hpp"
#include "server/ingest/text_show.hpp"

namespace mc::ingest::binary {
namespace {

constexpr double kScale1 = 16.0;     // SHOWINFO_SCALE
constexpr double kScale2 = 65536.0;  // SHOWINFO_SCALE2
constexpr double kRadToDeg = 180.0 / std::numbers::pi;

double fixed(const char* p) { return be32(p) / kScale2; }

std::string fixed_string(const char* p, std::size_t n) {
  std::size_t len = 0;
  while (len < n && p[len] != '\0') ++len;
  return std::string(p, len);
}

void team_at(const char* p, TeamInfo& t) {
  // team_t: char name[16]; Int16 score.
  t.name = fixed_string(p, 16);
  if (t.name == "null") t.name.clear();
  t.score = be16(p + 16);
  if (t.score < 0) t.score = 0;
  t.pen_score = t.pen_miss = 0;
}

PlayMode play_mode_of(char c) {
  const int pm = static_cast<unsigned char>(c);
  return pm < kPlayModeCount ? static_cast<PlayMode>(pm) : PlayMode::Null;
}

// player_t (64 bytes): see the table in rcss-protocol.md section 6.
void player_at(const char* p, PlayerState& s) {
  s.state = static_cast<std::uint16_t>(be16(p));
  s.type = be16(p + 2);
  s.x = fixed(p + 4);
  s.y = fixed(p + 8);
  s.vx = fixed(p + 12);
  s.vy = fixed(p + 16);
  s.body = fixed(p + 20) * kRadToDeg;
  s.neck = fixed(p + 24) * kRadToDeg;
  s.view_width = fixed(p + 28) * kRadToDeg;
  s.view_quality = be16(p + 32) == 1 ? 'h' : 'l';
  s.stamina = fixed(p + 36);
  s.effort = fixed(p + 40);
  s.recovery = fixed(p + 44);
  // Binary order: kick, dash, turn, say, tneck, catch, move, chg_view. These
  // are the first eight counters of the text order, hence count = 8.
  auto u = [&](int off) { return static_cast<std::uint32_t>(static_cast<std::uint16_t>(be16(p + off))); };
  CommandCounters& c = s.counters;
  c.kick = u(48);
  c.dash = u(50);
  c.turn = u(52);
  c.say = u(54);
  c.turn_neck = u(56);
  c.catch_ = u(58);
  c.move = u(60);
  c.change_view = u(62);
  c.count = 8;
}

void ball_and_players2(const char* ball, const char* players, WorldState& out) {
  out.ball.x = fixed(ball);
  out.ball.y = fixed(ball + 4);
  out.ball.vx = fixed(ball + 8);
  out.ball.vy = fixed(ball + 12);
  reset_players(out);
  for (int i = 0; i < kMaxPlayers; ++i) {
    PlayerState& s = out.players[static_cast<std::size_t>(i)];
    player_at(players + 64 * i, s);
  }
}

}  // namespace

std::int16_t be16(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return static_cast<std::int16_t>(static_cast<std::uint16_t>((u[0] << 8) | u[1]));
}

std::int32_t be32(const char* p) {
  const auto* u = reinterpret_cast<const unsigned char*>(p);
  return static_cast<std::int32_t>((std::uint32_t{u[0]} << 24) | (std::uint32_t{u[1]} << 16) |
                                   (std::uint32_t{u[2]} << 8) | std::uint32_t{u[3]});
}

bool decode_showinfo_v1(std::string_view bytes, WorldState& out) {
  if (bytes.size() < kShowInfoSize) return false;
  const char* p = bytes.data();
  out.play_mode = play_mode_of(p[0]);
  team_at(p + 2, out.left);
  team_at(p + 20, out.right);
  // pos_t[23] at 38: enable, side, unum, angle, x, y (Int16 each); [0] = ball.
  const char* pos = p + 38;
  out.ball = BallState{};
  out.ball.x = be16(pos + 8) / kScale1;
  out.ball.y = be16(pos + 10) / kScale1;
  reset_players(out);
  for (int i = 0; i < kMaxPlayers; ++i) {
    const char* q = pos + 12 * (i + 1);
    PlayerState& s = out.players[static_cast<std::size_t>(i)];
    s.state = static_cast<std::uint16_t>(be16(q));
    s.body = be16(q + 6);
    s.x = be16(q + 8) / kScale1;
    s.y = be16(q + 10) / kScale1;
  }
  out.time = be16(p + 314);
  return true;
}

bool decode_showinfo2(std::string_view bytes, WorldState& out) {
  if (bytes.size() < kShowInfo2Size) return false;
  const char* p = bytes.data();
  out.play_mode = play_mode_of(p[0]);
  team_at(p + 2, out.left);
  team_at(p + 20, out.right);
  ball_and_players2(p + 40, p + 56, out);
  out.time = be16(p + 1464);
  return true;
}

bool decode_short_showinfo2(std::string_view bytes, WorldState& out) {
  if (bytes.size() < kShortShowInfo2Size) return false;
  const char* p = bytes.data();
  ball_and_players2(p, p + 16, out);
  out.time = be16(p + 1424);
  return true;
}

bool decode_teams(std::string_view bytes, TeamInfo& left, TeamInfo& right) {
  if (bytes.size() < kTeamPairSize) return false;
  team_at(bytes.data(), left);
  team_at(bytes.data() + 18, right);
  return true;
}

bool decode_player_type(std::string_view bytes, PlayerType& t) {
  if (bytes.size() < kPlayerTypeSize) return false;
  const char* p = bytes.data();
  // Int16 id, pad, then Int32 fields in this order (later servers filled the
  // first spare slots with kick_power_rate, foul_detect_probability and
  // catchable_area_l_stretch).
  t.id = be16(p);
  double* fields[] = {&t.player_speed_max, &t.stamina_inc_max, &t.player_decay,
                      &t.inertia_moment,   &t.dash_power_rate, &t.player_size,
                      &t.kickable_margin,  &t.kick_rand,       &t.extra_stamina,
                      &t.effort_max,       &t.effort_min,      &t.kick_power_rate,
                      &t.foul_detect_probability, &t.catchable_area_l_stretch};
  for (std::size_t i = 0; i < std::size(fields); ++i) *fields[i] = fixed(p + 4 + 4 * i);
  return true;
}

namespace {
// Offsets in server_params_t (Int32 *65536 unless marked Int16).
struct ParamField {
  const char* name;
  int offset;
  bool int16;
};
constexpr ParamField kParamFields[] = {
    {"goal_width", 0, false},        {"inertia_moment", 4, false},
    {"player_size", 8, false},       {"player_decay", 12, false},
    {"player_rand", 16, false},      {"player_weight", 20, false},
    {"player_speed_max", 24, false}, {"player_accel_max", 28, false},
    {"stamina_max", 32, false},      {"stamina_inc_max", 36, false},
    {"kick_rand", 80, false},        {"ball_size", 104, false},
    {"ball_decay", 108, false},      {"ball_rand", 112, false},
    {"ball_weight", 116, false},     {"ball_speed_max", 120, false},
    {"ball_accel_max", 124, false},  {"dash_power_rate", 128, false},
    {"kick_power_rate", 132, false}, {"kickable_margin", 136, false},
    {"control_radius", 140, false},  {"maxpower", 148, false},
    {"minpower", 152, false},        {"maxmoment", 156, false},
    {"minmoment", 160, false},       {"maxneckmoment", 164, false},
    {"minneckmoment", 168, false},   {"maxneckang", 172, false},
    {"minneckang", 176, false},      {"visible_angle", 180, false},
    {"visible_distance", 184, false},{"catchable_area_l", 208, false},
    {"catchable_area_w", 212, false},{"catch_probability", 216, false},
    {"goalie_max_moves", 220, true}, {"ckick_margin", 224, false},
    {"half_time", 254, true},        {"simulator_step", 256, true},
    {"send_step", 258, true},        {"recv_step", 260, true},
    {"sense_body_step", 262, true},  {"catch_ban_cycle", 274, true},
};
}  // namespace

bool decode_server_params(std::string_view bytes, ParamTable& out) {
  if (bytes.size() < kServerParamsSize) return false;
  const char* p = bytes.data();
  for (const ParamField& f : kParamFields) {
    const double v = f.int16 ? be16(p + f.offset) : fixed(p + f.offset);
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.10g", v);
    out.set(f.name, buf);
  }
  return true;
}

bool encode_server_params(const ParamTable& in, std::string& out) {
  if (out.size() < kServerParamsSize) return false;
  for (const ParamField& f : kParamFields) {
    if (!in.has(f.name)) continue;
    double v = in.number(f.name, 0) * (f.int16 ? 1.0 : kScale2);
    if (!std::isfinite(v)) v = 0;
    const double lo = f.int16 ? -32768.0 : -2147483648.0, hi = f.int16 ? 32767.0 : 2147483647.0;
    const auto x = static_cast<std::int64_t>(std::llround(std::clamp(v, lo, hi)));
    auto* d = reinterpret_cast<unsigned char*>(out.data() + f.offset);
    if (f.int16) {
      d[0] = static_cast<unsigned char>((x >> 8) & 0xff);
      d[1] = static_cast<unsigned char>(x & 0xff);
    } else {
      for (int i = 0; i < 4; ++i) d[i] = static_cast<unsigned char>((x >> (24 - 8 * i)) & 0xff);
    }
  }
  return true;
}

bool decode_msginfo(std::string_view bytes, int& board, std::string& text) {
  if (bytes.size() < 2) return false;
  board = be16(bytes.data());
  text = fixed_string(bytes.data() + 2, bytes.size() - 2);
  return true;
}

bool apply_change_player_type(std::string_view text, std::array<std::int16_t, kMaxPlayers>& types) {
  SexpCursor c(text);
  std::string_view side;
  int unum = 0;
  std::int16_t type = 0;
  if (!c.lit('(') || !c.keyword("change_player_type") || !c.symbol(side) ||
      (side != "l" && side != "r") || !c.integer_in(unum, 1, kPlayersPerSide) ||
      !c.integer_in(type, 0, 1000))
    return false;
  types[static_cast<std::size_t>(player_index(side == "l" ? Side::Left : Side::Right, unum))] = type;
  return true;
}

}  // namespace mc::ingest::binary
