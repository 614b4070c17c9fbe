#include "server/ingest/json_records.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>

#include "server/ingest/text_show.hpp"

namespace mc::ingest {
namespace {

using nlohmann::json;

bool num(const json& o, const char* key, double& v) {
  auto it = o.find(key);
  if (it == o.end() || !it->is_number()) return false;
  v = it->get<double>();
  return std::isfinite(v);
}

template <typename Int>
bool integer(const json& o, const char* key, Int& v, double lo, double hi) {
  double d = 0;
  if (!num(o, key, d) || d < lo || d > hi || d != std::floor(d)) return false;
  v = static_cast<Int>(d);
  return true;
}

bool str(const json& o, const char* key, std::string& v) {
  auto it = o.find(key);
  if (it == o.end() || !it->is_string()) return false;
  v = it->get<std::string>();
  return true;
}

bool side_of(const json& o, const char* key, Side& s) {
  std::string v;
  if (!str(o, key, v)) return false;
  if (v == "l") s = Side::Left;
  else if (v == "r") s = Side::Right;
  else return false;
  return true;
}

void params_from(const json& body, ParamTable& table) {
  for (auto it = body.begin(); it != body.end(); ++it) {
    const json& v = it.value();
    std::string text;
    if (v.is_string()) text = v.get<std::string>();
    else if (v.is_boolean()) text = v.get<bool>() ? "1" : "0";
    else if (v.is_number()) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.10g", v.get<double>());
      text = buf;
    } else continue;
    table.set(it.key(), std::move(text));
  }
}

bool team_from(const json& body, TeamInfo& left, TeamInfo& right) {
  auto side = [](const json& b, const char* key, TeamInfo& t) {
    auto it = b.find(key);
    if (it == b.end() || !it->is_object()) return false;
    std::string name;
    if (!str(*it, "name", name)) name.clear();
    t.name = name == "null" ? std::string() : name;
    t.score = t.pen_score = t.pen_miss = 0;
    if (!integer(*it, "score", t.score, 0, 1e6)) return false;
    integer(*it, "pen_score", t.pen_score, 0, 1e6);
    integer(*it, "pen_miss", t.pen_miss, 0, 1e6);
    return true;
  };
  TeamInfo l, r;
  if (!side(body, "l", l) || !side(body, "r", r)) return false;
  left = std::move(l);
  right = std::move(r);
  return true;
}

bool player_from(const json& o, WorldState& out) {
  Side side{};
  int unum = 0;
  if (!side_of(o, "side", side) || !integer(o, "unum", unum, 1, kPlayersPerSide)) return false;
  PlayerState& p = out.players[static_cast<std::size_t>(player_index(side, unum))];
  p = PlayerState{};
  p.side = side;
  p.unum = static_cast<std::uint8_t>(unum);
  if (!integer(o, "type", p.type, -1, 1000) || !integer(o, "state", p.state, 0, 4294967295.0) ||
      !num(o, "x", p.x) || !num(o, "y", p.y))
    return false;
  num(o, "vx", p.vx);
  num(o, "vy", p.vy);
  num(o, "body", p.body);
  num(o, "neck", p.neck);
  std::array<double, 2> pair{};
  if (num(o, "px", pair[0]) && num(o, "py", pair[1])) p.point = pair;
  if (num(o, "fdist", pair[0]) && num(o, "fdir", pair[1])) p.focus_point = pair;
  std::string vq;
  if (str(o, "vq", vq) && vq.size() == 1) p.view_quality = vq[0];
  num(o, "vw", p.view_width);
  num(o, "stamina", p.stamina);
  num(o, "effort", p.effort);
  num(o, "recovery", p.recovery);
  double cap = 0;
  if (num(o, "capacity", cap)) p.capacity = cap;
  Side fs{};
  std::uint8_t fn = 0;
  if (side_of(o, "fside", fs) && integer(o, "fnum", fn, 1, kPlayersPerSide)) p.attention = std::make_pair(fs, fn);
  // Counters, in text order; present in logs, absent from monitor shows.
  static constexpr const char* kCounters[] = {"kick", "dash", "turn", "catch", "move", "turn_neck",
                                              "change_view", "say", "tackle", "pointto",
                                              "attentionto", "change_focus"};
  std::uint32_t* fields[] = {&p.counters.kick, &p.counters.dash, &p.counters.turn,
                             &p.counters.catch_, &p.counters.move, &p.counters.turn_neck,
                             &p.counters.change_view, &p.counters.say, &p.counters.tackle,
                             &p.counters.pointto, &p.counters.attentionto, &p.counters.change_focus};
  std::uint8_t n = 0;
  for (std::size_t i = 0; i < std::size(kCounters); ++i) {
    if (!integer(o, kCounters[i], *fields[i], 0, 4294967295.0)) break;
    n = static_cast<std::uint8_t>(i + 1);
  }
  p.counters.count = n;
  return true;
}

bool show_from(const json& body, GameContext& ctx, WorldState& out) {
  if (!integer(body, "time", out.time, -1, 1 << 30)) return false;
  auto ball = body.find("ball");
  if (ball == body.end() || !ball->is_object()) return false;
  out.ball = BallState{};
  if (!num(*ball, "x", out.ball.x) || !num(*ball, "y", out.ball.y)) return false;
  num(*ball, "vx", out.ball.vx);
  num(*ball, "vy", out.ball.vy);
  reset_players(out);
  auto players = body.find("players");
  if (players == body.end() || !players->is_array()) return false;
  for (const json& p : *players)
    if (!p.is_object() || !player_from(p, out)) return false;
  std::string mode;
  if (str(body, "mode", mode)) {
    if (auto pm = play_mode_from_name(mode)) ctx.play_mode = *pm;
  }
  auto team = body.find("team");
  if (team != body.end() && team->is_object()) team_from(*team, ctx.left, ctx.right);
  out.play_mode = ctx.play_mode;
  out.left = ctx.left;
  out.right = ctx.right;
  return true;
}

}  // namespace

bool decode_json_record(std::string_view text, GameContext& ctx, WorldState& out,
                        MessageRecord& msg, RecordKind& kind, std::string& error) {
  kind = RecordKind::Other;
  const json doc = json::parse(text.begin(), text.end(), nullptr, /*allow_exceptions=*/false);
  if (doc.is_discarded() || !doc.is_object()) {
    error = "invalid JSON";
    return false;
  }
  // 19.x: {"kind": body}; 17.x/18.x: {"type": "kind", ...body}.
  std::string name;
  const json* body = nullptr;
  auto type = doc.find("type");
  if (type != doc.end() && type->is_string()) {
    name = type->get<std::string>();
    body = &doc;
  } else if (doc.size() == 1 && doc.begin().value().is_object()) {
    name = doc.begin().key();
    body = &doc.begin().value();
  } else {
    return true;  // {"version":..}, {"timestamp":..}
  }
  bool ok = true;
  if (name == "show") {
    kind = RecordKind::Show;
    ok = show_from(*body, ctx, out);
  } else if (name == "playmode") {
    kind = RecordKind::PlayMode;
    std::string mode;
    ok = str(*body, "mode", mode);
    auto pm = ok ? play_mode_from_name(mode) : std::nullopt;
    ok = pm.has_value();
    if (ok) ctx.play_mode = *pm;
  } else if (name == "team") {
    kind = RecordKind::Team;
    ok = team_from(*body, ctx.left, ctx.right);
  } else if (name == "msg") {
    kind = RecordKind::Msg;
    msg = MessageRecord{};
    integer(*body, "time", msg.time, -1, 1 << 30);
    integer(*body, "board", msg.board, -1e6, 1e6);
    ok = str(*body, "message", msg.text);
  } else if (name == "server_param") {
    kind = RecordKind::ServerParam;
    params_from(*body, ctx.params.server);
  } else if (name == "player_param") {
    kind = RecordKind::PlayerParam;
    params_from(*body, ctx.params.player);
  } else if (name == "player_type") {
    kind = RecordKind::PlayerType;
    ParamTable t;
    params_from(*body, t);
    ok = store_player_type(ctx.params, player_type_from_table(t));
  }
  if (!ok) error = "bad " + name + " record";
  return ok;
}

}  // namespace mc::ingest
