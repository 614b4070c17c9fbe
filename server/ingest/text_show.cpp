#include "server/ingest/text_show.hpp"

#include <memory>

#include "server/ingest/sexp_cursor.hpp"

namespace mc::ingest {
namespace {

bool fail(SexpCursor& c, std::string& error, const char* what) {
  error = std::string(what) + " at byte " + std::to_string(c.position());
  return false;
}

bool parse_side(SexpCursor& c, Side& side) {
  char ch = 0;
  if (!c.single_char(ch)) return false;
  if (ch == 'l') side = Side::Left;
  else if (ch == 'r') side = Side::Right;
  else return false;
  return true;
}

// Player sub-record keys, told apart by length and first letter (hot loop).
enum class Sub { V, Fp, S, F, C, Unknown };
Sub sub_of(std::string_view k) {
  if (k.size() == 1) {
    switch (k[0]) {
      case 'v': return Sub::V;
      case 's': return Sub::S;
      case 'f': return Sub::F;
      case 'c': return Sub::C;
      default: return Sub::Unknown;
    }
  }
  return k.size() == 2 && k[0] == 'f' && k[1] == 'p' ? Sub::Fp : Sub::Unknown;
}

// (tm LNAME RNAME LSCORE RSCORE [LPEN_SCORE LPEN_MISS RPEN_SCORE RPEN_MISS]),
// the "(tm" already consumed.
bool parse_tm(SexpCursor& c, WorldState& out) {
  std::string_view l, r;
  if (!c.symbol(l) || !c.symbol(r)) return false;
  out.left.name = l == "null" ? std::string() : std::string(l);
  out.right.name = r == "null" ? std::string() : std::string(r);
  if (!c.integer_in(out.left.score, 0, 1 << 20) || !c.integer_in(out.right.score, 0, 1 << 20))
    return false;
  out.left.pen_score = out.left.pen_miss = out.right.pen_score = out.right.pen_miss = 0;
  if (c.peek() != ')') {
    if (!c.integer_in(out.left.pen_score, 0, 1 << 20) || !c.integer_in(out.left.pen_miss, 0, 1 << 20) ||
        !c.integer_in(out.right.pen_score, 0, 1 << 20) || !c.integer_in(out.right.pen_miss, 0, 1 << 20))
      return false;
  }
  return c.lit(')');
}

bool parse_counters(SexpCursor& c, CommandCounters& k) {
  std::uint32_t* fields[] = {&k.kick, &k.dash, &k.turn, &k.catch_, &k.move, &k.turn_neck,
                             &k.change_view, &k.say, &k.tackle, &k.pointto, &k.attentionto,
                             &k.change_focus};
  k = CommandCounters{};
  std::uint8_t n = 0;
  while (c.peek() != ')') {
    if (n >= 12) return false;
    if (!c.integer_in(*fields[n], 0, 0xffffffffLL)) return false;
    ++n;
  }
  k.count = n;
  return c.lit(')');
}

// One player, the opening "(" already consumed:
// (SIDE UNUM) TYPE STATE X Y VX VY BODY NECK [PX PY] (v ..) [(fp ..)] (s ..) [(f ..)] (c ..))
bool parse_player(SexpCursor& c, WorldState& out, std::uint32_t& seen, std::string& error) {
  Side side{};
  int unum = 0;
  if (!c.lit('(') || !parse_side(c, side) || !c.integer_in(unum, 1, kPlayersPerSide) || !c.lit(')'))
    return fail(c, error, "bad player id");
  const int slot = player_index(side, unum);
  seen |= 1u << slot;
  PlayerState& p = out.players[static_cast<std::size_t>(slot)];
  // Re-construct rather than assign: PlayerState's assignment is memberwise
  // (std::pair inside an optional), its construction is plain stores.
  std::destroy_at(&p);
  std::construct_at(&p);
  p.side = side;
  p.unum = static_cast<std::uint8_t>(unum);
  if (!c.integer_in(p.type, -1, 1000) || !c.hex(p.state)) return fail(c, error, "bad player type/state");
  if (!c.number(p.x) || !c.number(p.y) || !c.number(p.vx) || !c.number(p.vy) || !c.number(p.body) ||
      !c.number(p.neck))
    return fail(c, error, "bad player position");
  if (c.peek() != '(' && c.peek() != ')') {
    std::array<double, 2> pt{};
    if (!c.number(pt[0]) || !c.number(pt[1])) return fail(c, error, "bad arm point");
    p.point = pt;
  }
  // Sub-records, keyed by their first symbol; order is fixed in practice but
  // nothing depends on it.
  while (c.lit('(')) {
    std::string_view key;
    if (!c.symbol(key)) return fail(c, error, "bad player sub-record");
    bool ok = true;
    const Sub sub = sub_of(key);
    if (sub == Sub::V) {
      char q = 0;
      ok = c.single_char(q) && (q == 'h' || q == 'l') && c.number(p.view_width) && c.lit(')');
      if (ok) p.view_quality = q;
    } else if (sub == Sub::Fp) {
      std::array<double, 2> fp{};
      ok = c.number(fp[0]) && c.number(fp[1]) && c.lit(')');
      p.focus_point = fp;
    } else if (sub == Sub::S) {
      ok = c.number(p.stamina) && c.number(p.effort) && c.number(p.recovery);
      if (ok && c.peek() != ')') {
        double cap = 0;
        ok = c.number(cap);
        p.capacity = cap;
      }
      ok = ok && c.lit(')');
    } else if (sub == Sub::F) {
      Side fs{};
      std::uint8_t fn = 0;
      ok = parse_side(c, fs) && c.integer_in(fn, 1, kPlayersPerSide) && c.lit(')');
      p.attention = std::make_pair(fs, fn);
    } else if (sub == Sub::C) {
      ok = parse_counters(c, p.counters);
    } else {
      ok = false;
    }
    if (!ok) return fail(c, error, "bad player sub-record");
  }
  if (!c.lit(')')) return fail(c, error, "player not closed");
  return true;
}

}  // namespace

void reset_player(WorldState& out, int i) {
  PlayerState& p = out.players[static_cast<std::size_t>(i)];
  p = PlayerState{};
  p.side = i < kPlayersPerSide ? Side::Left : Side::Right;
  p.unum = static_cast<std::uint8_t>(i % kPlayersPerSide + 1);
  const double sign = p.side == Side::Left ? 1.0 : -1.0;
  p.x = -(p.unum * 3.0 * sign);
  p.y = -37.0;
}

void reset_players(WorldState& out) {
  for (int i = 0; i < kMaxPlayers; ++i) reset_player(out, i);
}

bool parse_text_show(std::string_view text, WorldState& out, ShowExtras& extras,
                     std::string& error) {
  SexpCursor c(text);
  extras = ShowExtras{};
  if (!c.lit('(') || !c.keyword("show")) return fail(c, error, "not a show");
  if (!c.integer_in(out.time, -1, 1 << 30)) return fail(c, error, "bad show time");
  bool ball_seen = false;
  std::uint32_t seen = 0;  // player slots present in the record
  // Everything after the time is a parenthesised group: (pm), (tm), ((b) ..),
  // ((l N) ..), ((r N) ..).
  while (c.lit('(')) {
    if (c.peek() == '(') {
      // ((b) ...) or a player.
      const char* save = c.ptr();
      c.lit('(');
      char id = 0;
      if (c.single_char(id) && id == 'b') {
        if (!c.lit(')') || !c.number(out.ball.x) || !c.number(out.ball.y) || !c.number(out.ball.vx) ||
            !c.number(out.ball.vy) || !c.lit(')'))
          return fail(c, error, "bad ball");
        ball_seen = true;
      } else {
        c.seek(save);
        if (!parse_player(c, out, seen, error)) return false;
      }
      continue;
    }
    std::string_view key;
    if (!c.symbol(key)) return fail(c, error, "bad show field");
    if (key == "pm") {
      int pm = 0;
      if (!c.integer_in(pm, 0, kPlayModeCount - 1) || !c.lit(')')) return fail(c, error, "bad (pm)");
      out.play_mode = static_cast<PlayMode>(pm);
      extras.has_play_mode = true;
    } else if (key == "tm") {
      if (!parse_tm(c, out)) return fail(c, error, "bad (tm)");
      extras.has_team = true;
    } else {
      return fail(c, error, "unknown show field");
    }
  }
  if (!c.lit(')')) return fail(c, error, "show not closed");
  if (!ball_seen) return fail(c, error, "show without ball");
  // Slots missing from the record become absent, parked players.
  for (int i = 0; i < kMaxPlayers; ++i)
    if (!(seen & (1u << i))) reset_player(out, i);
  if (!c.at_end()) return fail(c, error, "trailing bytes after show");
  return true;
}

}  // namespace mc::ingest
