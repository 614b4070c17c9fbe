#include "server/ingest/monitor_serializer.hpp"

#include <nlohmann/json.hpp>

#include "proto/float_chars.hpp"
#include "server/ingest/binary_writer.hpp"

#include <charconv>
#include <cstdio>

namespace mc::ingest {
namespace {

using nlohmann::json;

void put(std::string& o, double v) {
  char buf[32];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  o.append(buf, r.ptr);
}
void put_int(std::string& o, long long v) {
  char buf[24];
  auto r = std::to_chars(buf, buf + sizeof buf, v);
  o.append(buf, r.ptr);
}
void put_state(std::string& o, std::uint32_t s) {
  // std::showbase style: "0" for zero, "0x.." otherwise (rcss-protocol.md 3.1).
  if (s == 0) {
    o += '0';
    return;
  }
  char buf[16];
  auto r = std::to_chars(buf, buf + sizeof buf, s, 16);
  o += "0x";
  o.append(buf, r.ptr);
}
const char* side_name(Side s) { return s == Side::Right ? "r" : "l"; }
std::string team_name(const std::string& n) { return n.empty() ? "null" : n; }

bool is_number(const std::string& v) {
  double d = 0;
  auto r = from_chars_double(v.data(), v.data() + v.size(), d);
  return !v.empty() && r.ec == std::errc() && r.ptr == v.data() + v.size();
}

void counters_of(const CommandCounters& c, std::uint32_t (&out)[12]) {
  const std::uint32_t v[12] = {c.kick, c.dash, c.turn, c.catch_, c.move, c.turn_neck, c.change_view,
                               c.say, c.tackle, c.pointto, c.attentionto, c.change_focus};
  for (int i = 0; i < 12; ++i) out[i] = v[i];
}

std::string show_text(const WorldState& s, int version) {
  std::string o;
  o.reserve(4096);
  o += "(show ";
  put_int(o, s.time);
  o += " (pm ";
  put_int(o, static_cast<int>(s.play_mode));
  o += ") (tm ";
  o += team_name(s.left.name) + ' ' + team_name(s.right.name) + ' ';
  put_int(o, s.left.score);
  o += ' ';
  put_int(o, s.right.score);
  if (s.left.pen_score || s.left.pen_miss || s.right.pen_score || s.right.pen_miss) {
    for (int v : {s.left.pen_score, s.left.pen_miss, s.right.pen_score, s.right.pen_miss}) {
      o += ' ';
      put_int(o, v);
    }
  }
  o += ") ((b) ";
  for (double v : {s.ball.x, s.ball.y, s.ball.vx, s.ball.vy}) {
    put(o, v);
    o += ' ';
  }
  o.back() = ')';
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerState& p = s.players[static_cast<std::size_t>(i)];
    // Side and number from the slot: the order rcssserver uses.
    o += " ((";
    o += i < kPlayersPerSide ? 'l' : 'r';
    o += ' ';
    put_int(o, i % kPlayersPerSide + 1);
    o += ") ";
    put_int(o, p.type);
    o += ' ';
    put_state(o, p.state);
    for (double v : {p.x, p.y, p.vx, p.vy, p.body, p.neck}) {
      o += ' ';
      put(o, v);
    }
    if (p.point) {
      o += ' ';
      put(o, (*p.point)[0]);
      o += ' ';
      put(o, (*p.point)[1]);
    }
    o += " (v ";
    o += p.view_quality;
    o += ' ';
    put(o, p.view_width);
    o += ')';
    if (version >= 5 && p.focus_point) {
      o += " (fp ";
      put(o, (*p.focus_point)[0]);
      o += ' ';
      put(o, (*p.focus_point)[1]);
      o += ')';
    }
    o += " (s ";
    put(o, p.stamina);
    o += ' ';
    put(o, p.effort);
    o += ' ';
    put(o, p.recovery);
    if (version >= 4 && p.capacity) {
      o += ' ';
      put(o, *p.capacity);
    }
    o += ')';
    if (p.attention) {
      o += " (f ";
      o += side_name(p.attention->first);
      o += ' ';
      put_int(o, p.attention->second);
      o += ')';
    }
    o += " (c";
    std::uint32_t c[12];
    counters_of(p.counters, c);
    const int n = std::min<int>(p.counters.count, version >= 5 ? 12 : 11);
    for (int i = 0; i < n; ++i) {
      o += ' ';
      put_int(o, c[i]);
    }
    o += "))";
  }
  o += ')';
  return o;
}

json team_json(const TeamInfo& t) {
  json j{{"name", team_name(t.name)}, {"score", t.score}};
  if (t.pen_score || t.pen_miss) {
    j["pen_score"] = t.pen_score;
    j["pen_miss"] = t.pen_miss;
  }
  return j;
}

std::string show_json(const WorldState& s) {
  json players = json::array();
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerState& p = s.players[static_cast<std::size_t>(i)];
    json j{{"side", i < kPlayersPerSide ? "l" : "r"}, {"unum", i % kPlayersPerSide + 1}, {"type", p.type}, {"state", p.state},
           {"x", p.x}, {"y", p.y}, {"vx", p.vx}, {"vy", p.vy}, {"body", p.body}, {"neck", p.neck}};
    if (p.point) {
      j["px"] = (*p.point)[0];
      j["py"] = (*p.point)[1];
    }
    j["vq"] = std::string(1, p.view_quality);
    j["vw"] = p.view_width;
    if (p.focus_point) {
      j["fdist"] = (*p.focus_point)[0];
      j["fdir"] = (*p.focus_point)[1];
    }
    j["stamina"] = p.stamina;
    j["effort"] = p.effort;
    j["recovery"] = p.recovery;
    if (p.capacity) j["capacity"] = *p.capacity;
    if (p.attention) {
      j["fside"] = side_name(p.attention->first);
      j["fnum"] = p.attention->second;
    }
    // rcssserver's JSON monitor shows carry no counters (DispSenderMonitorJSON
    // has them commented out), and with them a show would pass 8192 bytes.
    players.push_back(std::move(j));
  }
  json show{{"time", s.time},
            {"mode", std::string(play_mode_name(s.play_mode))},
            {"team", {{"l", team_json(s.left)}, {"r", team_json(s.right)}}},
            {"ball", {{"x", s.ball.x}, {"y", s.ball.y}, {"vx", s.ball.vx}, {"vy", s.ball.vy}}},
            {"players", std::move(players)}};
  if (s.stoppage > 0) show["stime"] = s.stoppage;
  return json{{"show", std::move(show)}}.dump();
}

std::string params_text(const char* head, const ParamTable& t) {
  std::string o = std::string("(") + head + ' ';
  for (const auto& [k, v] : t.all()) {
    o += '(' + k + ' ';
    o += is_number(v) ? v : '"' + v + '"';
    o += ')';
  }
  o += ')';
  return o;
}

json params_json(const ParamTable& t) {
  json j = json::object();
  for (const auto& [k, v] : t.all()) {
    double d = 0;
    if (is_number(v) && from_chars_double(v.data(), v.data() + v.size(), d).ec == std::errc()) j[k] = d;
    else j[k] = v;
  }
  return j;
}

std::vector<std::pair<const char*, double>> type_fields(const PlayerType& t) {
  return {{"player_speed_max", t.player_speed_max}, {"stamina_inc_max", t.stamina_inc_max},
          {"player_decay", t.player_decay}, {"inertia_moment", t.inertia_moment},
          {"dash_power_rate", t.dash_power_rate}, {"player_size", t.player_size},
          {"kickable_margin", t.kickable_margin}, {"kick_rand", t.kick_rand},
          {"extra_stamina", t.extra_stamina}, {"effort_max", t.effort_max},
          {"effort_min", t.effort_min}, {"kick_power_rate", t.kick_power_rate},
          {"foul_detect_probability", t.foul_detect_probability},
          {"catchable_area_l_stretch", t.catchable_area_l_stretch}};
}

}  // namespace

bool serializer_supports(int version) { return version >= -1 && version <= 5 && version != 0; }
bool serializer_is_binary(int version) { return version == 1 || version == 2; }

std::string serialize_show(const WorldState& s, int version) {
  if (serializer_is_binary(version)) return binary::encode_show(s, version);
  return version < 0 ? show_json(s) : show_text(s, version);
}

std::vector<std::string> serialize_params(const GameParams& p, int version) {
  if (serializer_is_binary(version)) return binary::encode_params(p, version);
  std::vector<std::string> out;
  if (version < 0) {
    out.push_back(json{{"server_param", params_json(p.server)}}.dump());
    out.push_back(json{{"player_param", params_json(p.player)}}.dump());
    for (const PlayerType& t : p.player_types) {
      json j{{"id", t.id}};
      for (const auto& [k, v] : type_fields(t)) j[k] = v;
      out.push_back(json{{"player_type", std::move(j)}}.dump());
    }
    return out;
  }
  out.push_back(params_text("server_param", p.server));
  out.push_back(params_text("player_param", p.player));
  for (const PlayerType& t : p.player_types) {
    std::string o = "(player_type (id ";
    put_int(o, t.id);
    o += ')';
    for (const auto& [k, v] : type_fields(t)) {
      o += '(';
      o += k;
      o += ' ';
      put(o, v);
      o += ')';
    }
    o += ')';
    out.push_back(std::move(o));
  }
  return out;
}

std::string serialize_msg(const MessageRecord& m, int version) {
  if (serializer_is_binary(version)) return binary::encode_msg(m, version);
  if (version < 0)
    return json{{"msg", {{"time", m.time}, {"board", m.board}, {"message", m.text}}}}.dump();
  std::string o = "(msg ";
  put_int(o, m.time);
  o += ' ';
  put_int(o, m.board);
  o += " \"" + m.text + "\")";
  return o;
}

}  // namespace mc::ingest
