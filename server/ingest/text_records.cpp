#include "server/ingest/text_records.hpp"

#include "server/ingest/sexp_cursor.hpp"

namespace mc::ingest {
namespace {

bool fail(const SexpCursor& c, std::string& error, const char* what) {
  error = std::string(what) + " at byte " + std::to_string(c.position());
  return false;
}

std::string team_name(std::string_view s) { return s == "null" ? std::string() : std::string(s); }

// Reads `(k v)(k v)...` up to the closing ')' of the record. A value is a
// quoted string (may hold spaces and parentheses) or a bare token.
bool parse_pairs(SexpCursor& c, ParamTable& table, std::string& error) {
  while (c.lit('(')) {
    std::string_view key;
    if (!c.symbol(key)) return fail(c, error, "bad parameter name");
    c.skip_ws();
    std::string value;
    if (c.peek() == '"') {
      const char* s = c.ptr() + 1;
      const char* q = s;
      while (q < c.end() && *q != '"') ++q;
      if (q >= c.end()) return fail(c, error, "unterminated string parameter");
      value.assign(s, static_cast<std::size_t>(q - s));
      c.seek(q + 1);
    } else {
      std::string_view v;
      if (!c.symbol(v)) return fail(c, error, "missing parameter value");
      value.assign(v);
    }
    if (!c.lit(')')) return fail(c, error, "parameter not closed");
    table.set(std::string(key), std::move(value));
  }
  if (!c.lit(')')) return fail(c, error, "record not closed");
  return true;
}

}  // namespace

bool parse_playmode_record(std::string_view text, int& time, PlayMode& mode, std::string& error) {
  SexpCursor c(text);
  std::string_view name;
  if (!c.lit('(') || !c.keyword("playmode") || !c.integer_in(time, -1, 1 << 30) || !c.symbol(name))
    return fail(c, error, "bad playmode record");
  auto pm = play_mode_from_name(name);
  if (!pm) return fail(c, error, "unknown play mode");
  if (!c.lit(')')) return fail(c, error, "playmode record not closed");
  mode = *pm;
  return true;
}

bool parse_team_record(std::string_view text, int& time, TeamInfo& left, TeamInfo& right,
                       std::string& error) {
  SexpCursor c(text);
  std::string_view l, r;
  if (!c.lit('(') || !c.keyword("team") || !c.integer_in(time, -1, 1 << 30) || !c.symbol(l) ||
      !c.symbol(r))
    return fail(c, error, "bad team record");
  TeamInfo a, b;
  a.name = team_name(l);
  b.name = team_name(r);
  if (!c.integer_in(a.score, 0, 1 << 20) || !c.integer_in(b.score, 0, 1 << 20))
    return fail(c, error, "bad team score");
  if (c.peek() != ')') {
    if (!c.integer_in(a.pen_score, 0, 1 << 20) || !c.integer_in(a.pen_miss, 0, 1 << 20) ||
        !c.integer_in(b.pen_score, 0, 1 << 20) || !c.integer_in(b.pen_miss, 0, 1 << 20))
      return fail(c, error, "bad penalty score");
  }
  if (!c.lit(')')) return fail(c, error, "team record not closed");
  left = std::move(a);
  right = std::move(b);
  return true;
}

bool parse_msg_record(std::string_view text, MessageRecord& out, std::string& error) {
  SexpCursor c(text);
  if (!c.lit('(') || !c.keyword("msg") || !c.integer_in(out.time, -1, 1 << 30) ||
      !c.integer_in(out.board, -1000000, 1000000))
    return fail(c, error, "bad msg record");
  if (c.peek() != '"') return fail(c, error, "msg text not quoted");
  const std::size_t open = c.position();
  // The last `")` closes the text (quotes inside are not escaped).
  const std::size_t close = text.rfind("\")");
  if (close == std::string_view::npos || close <= open) return fail(c, error, "msg text not closed");
  out.text.assign(text.substr(open + 1, close - open - 1));
  return true;
}

bool parse_param_record(std::string_view text, std::string_view head, ParamTable& table,
                        std::string& error) {
  SexpCursor c(text);
  if (!c.lit('(') || !c.keyword(head)) return fail(c, error, "bad parameter record");
  return parse_pairs(c, table, error);
}

PlayerType player_type_from_table(const ParamTable& t) {
  PlayerType p;
  const double id = t.number("id", 0);
  p.id = id >= 0 && id <= 255 ? static_cast<int>(id) : -1;  // -1: store_player_type refuses it
  p.player_speed_max = t.number("player_speed_max", p.player_speed_max);
  p.stamina_inc_max = t.number("stamina_inc_max", p.stamina_inc_max);
  p.player_decay = t.number("player_decay", p.player_decay);
  p.inertia_moment = t.number("inertia_moment", p.inertia_moment);
  p.dash_power_rate = t.number("dash_power_rate", p.dash_power_rate);
  p.player_size = t.number("player_size", p.player_size);
  p.kickable_margin = t.number("kickable_margin", p.kickable_margin);
  p.kick_rand = t.number("kick_rand", p.kick_rand);
  p.extra_stamina = t.number("extra_stamina", p.extra_stamina);
  p.effort_max = t.number("effort_max", p.effort_max);
  p.effort_min = t.number("effort_min", p.effort_min);
  p.kick_power_rate = t.number("kick_power_rate", p.kick_power_rate);
  p.foul_detect_probability = t.number("foul_detect_probability", p.foul_detect_probability);
  p.catchable_area_l_stretch = t.number("catchable_area_l_stretch", p.catchable_area_l_stretch);
  return p;
}

bool store_player_type(GameParams& params, const PlayerType& t) {
  if (t.id < 0 || t.id > 255) return false;
  const auto id = static_cast<std::size_t>(t.id);
  if (params.player_types.size() <= id) {
    const std::size_t old = params.player_types.size();
    params.player_types.resize(id + 1);
    for (std::size_t i = old; i < params.player_types.size(); ++i)
      params.player_types[i].id = static_cast<int>(i);
  }
  params.player_types[id] = t;
  return true;
}

bool parse_player_type_record(std::string_view text, GameParams& params, std::string& error) {
  SexpCursor c(text);
  if (!c.lit('(') || !c.keyword("player_type")) return fail(c, error, "bad player_type record");
  ParamTable table;
  if (!parse_pairs(c, table, error)) return false;
  const double id = table.number("id", -1);
  if (!(id >= 0 && id <= 255)) {
    error = "player_type without a valid id";
    return false;
  }
  return store_player_type(params, player_type_from_table(table));
}

}  // namespace mc::ingest
