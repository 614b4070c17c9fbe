#include "server/ingest/json_records.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "proto/json_text.hpp"
#include "server/ingest/text_show.hpp"

namespace mc::ingest {
namespace {

// A record's JSON as a flat tree in one vector, built by nlohmann's SAX
// parser and kept from record to record on each thread. nlohmann's DOM made
// a heap node, and a map entry per key, for every value of every record:
// under ASan that allocation was over half of the JSON log fuzzer's time,
// and a log is thousands of shows. What the decoders below read of a value
// is what they read of the DOM: its type, number, text, and children by key,
// the last one where a key repeats (the DOM keeps the last).
struct Node {
  enum class Type : std::uint8_t { Null, Boolean, Number, String, Object, Array };
  static constexpr std::uint32_t kNone = 0xffffffffu;
  Type type = Type::Null;
  bool boolean = false;
  double number = 0;
  std::string key;   // its key, when in an object
  std::string text;  // Type::String
  std::uint32_t first = kNone, last = kNone, next = kNone;  // children; next sibling
};

class Tree {
 public:
  // False when `text` is not one valid JSON value.
  bool parse(std::string_view text);
  const Node& at(std::uint32_t i) const { return nodes_[i]; }

 private:
  friend class TreeBuilder;
  std::uint32_t add(Node::Type type, const std::string* key);
  std::vector<Node> nodes_;  // the first used_ are this record's; the rest keep their strings' room
  std::uint32_t used_ = 0;
  // The builder's scratch, kept with the tree so that a record costs no
  // allocation once the first records have sized them.
  std::vector<std::uint32_t> open_;  // the containers being filled, innermost last
  std::string key_;                  // the key of the value to come
};

std::uint32_t Tree::add(Node::Type type, const std::string* key) {
  if (used_ == nodes_.size()) nodes_.emplace_back();
  Node& n = nodes_[used_];
  n.type = type;
  n.boolean = false;
  n.number = 0;
  if (key) n.key.assign(*key);
  else n.key.clear();
  n.text.clear();
  n.first = n.last = n.next = Node::kNone;
  return used_++;
}

// nlohmann::json_sax's interface, appending to a Tree.
class TreeBuilder {
 public:
  using json = nlohmann::json;
  explicit TreeBuilder(Tree& t) : t_(t), stack_(t.open_), key_(t.key_) { stack_.clear(); }
  bool null() { return value(Node::Type::Null); }
  bool boolean(bool b) { return value(Node::Type::Boolean, [b](Node& n) { n.boolean = b; }); }
  bool number_integer(json::number_integer_t v) { return number(static_cast<double>(v)); }
  bool number_unsigned(json::number_unsigned_t v) { return number(static_cast<double>(v)); }
  bool number_float(json::number_float_t v, const json::string_t&) { return number(v); }
  bool string(json::string_t& s) { return value(Node::Type::String, [&s](Node& n) { n.text.assign(s); }); }
  bool binary(json::binary_t&) { return value(Node::Type::Null); }  // never from JSON text
  bool start_object(std::size_t) { return open(Node::Type::Object); }
  bool key(json::string_t& k) {
    key_.assign(k);
    return true;
  }
  bool end_object() { return close(); }
  bool start_array(std::size_t) { return open(Node::Type::Array); }
  bool end_array() { return close(); }
  bool parse_error(std::size_t, const std::string&, const nlohmann::detail::exception&) { return false; }

 private:
  template <typename Fill = void (*)(Node&)>
  bool value(Node::Type type, Fill fill = [](Node&) {}) {
    const std::uint32_t i = link(type);
    fill(t_.nodes_[i]);
    return true;
  }
  bool number(double v) { return value(Node::Type::Number, [v](Node& n) { n.number = v; }); }
  bool open(Node::Type type) {
    stack_.push_back(link(type));
    return true;
  }
  bool close() {
    if (!stack_.empty()) stack_.pop_back();
    return true;
  }
  // A new node, made the last child of the open container (if any).
  std::uint32_t link(Node::Type type) {
    const bool in_object = !stack_.empty() && t_.nodes_[stack_.back()].type == Node::Type::Object;
    const std::uint32_t i = t_.add(type, in_object ? &key_ : nullptr);
    if (!stack_.empty()) {
      Node& parent = t_.nodes_[stack_.back()];
      if (parent.last == Node::kNone) parent.first = i;
      else t_.nodes_[parent.last].next = i;
      parent.last = i;
    }
    return i;
  }
  Tree& t_;
  std::vector<std::uint32_t>& stack_;
  std::string& key_;
};

bool Tree::parse(std::string_view text) {
  used_ = 0;
  if (!proto::may_be_json_text(text)) return false;
  TreeBuilder b(*this);
  return nlohmann::json::sax_parse(text.begin(), text.end(), &b) && used_ > 0;
}

// A value of the tree, as the decoders read it.
class Json {
 public:
  Json(const Tree& t, std::uint32_t i) : t_(&t), i_(i) {}
  bool is_object() const { return node().type == Node::Type::Object; }
  bool is_array() const { return node().type == Node::Type::Array; }
  bool is_string() const { return node().type == Node::Type::String; }
  bool is_number() const { return node().type == Node::Type::Number; }
  bool is_boolean() const { return node().type == Node::Type::Boolean; }
  double number() const { return node().number; }
  bool boolean() const { return node().boolean; }
  const std::string& text() const { return node().text; }
  const std::string& key() const { return node().key; }
  // The member `key` of an object (the last of that name), or none.
  std::optional<Json> find(std::string_view key) const {
    std::optional<Json> found;
    for (std::uint32_t c = node().first; c != Node::kNone; c = t_->at(c).next)
      if (t_->at(c).key == key) found = Json(*t_, c);
    return found;
  }
  // Calls f(child) for each array element, or for each object member whose
  // name no later member repeats, in the record's order.
  template <typename F>
  void for_each(F f) const {
    if (!is_object()) {
      for (std::uint32_t c = node().first; c != Node::kNone; c = t_->at(c).next) f(Json(*t_, c));
      return;
    }
    // Sorted by name (equal names in record order), the last of each name is
    // the one kept: O(n log n), where comparing every pair took 14 s for a
    // hostile record of 100,000 keys (a log's records may be 8 MB).
    std::vector<std::uint32_t> members;
    for (std::uint32_t c = node().first; c != Node::kNone; c = t_->at(c).next) members.push_back(c);
    std::stable_sort(members.begin(), members.end(),
                     [this](std::uint32_t a, std::uint32_t b) { return t_->at(a).key < t_->at(b).key; });
    std::vector<std::uint32_t> kept;
    for (std::size_t k = 0; k < members.size(); ++k)
      if (k + 1 == members.size() || t_->at(members[k + 1]).key != t_->at(members[k]).key) kept.push_back(members[k]);
    std::sort(kept.begin(), kept.end());  // nodes are numbered in record order
    for (const std::uint32_t c : kept) f(Json(*t_, c));
  }
  // Calls f(node index, key) for every member of an object, repeats too, in
  // the record's order.
  template <typename F>
  void for_each_member(F f) const {
    for (std::uint32_t c = node().first; c != Node::kNone; c = t_->at(c).next) f(c, t_->at(c).key);
  }
  const Tree& tree() const { return *t_; }
  // The member of an object whose members all have one name (the last of
  // them, as the DOM kept it), or none.
  std::optional<Json> only_member() const {
    const std::uint32_t first = node().first;
    if (first == Node::kNone) return std::nullopt;
    for (std::uint32_t c = t_->at(first).next; c != Node::kNone; c = t_->at(c).next)
      if (t_->at(c).key != t_->at(first).key) return std::nullopt;
    return Json(*t_, node().last);
  }

 private:
  const Node& node() const { return t_->at(i_); }
  const Tree* t_;
  std::uint32_t i_;
};

// An object's members found by name in one pass, for a decoder that reads
// many names of one object. Json::find() walks every member for each name:
// a player's 34 names over its ~30 members were ~1,000 string compares, a
// show's 22 players most of the JSON fuzzer's own decoding time. Each slot
// holds the last member of its name, as find() and the DOM do.
template <std::size_t N>
class KeyedObject {
 public:
  // `names`: every name the decoder asks for, sorted.
  KeyedObject(const Json& o, const std::array<std::string_view, N>& names) : o_(o), names_(names) {
    slot_.fill(Node::kNone);
    o.for_each_member([this](std::uint32_t c, const std::string& key) {
      if (const std::size_t k = index(key); k < N) slot_[k] = c;
    });
  }
  std::optional<Json> find(std::string_view key) const {
    const std::size_t k = index(key);
    if (k == N) return o_.find(key);  // a name left out of the list still reads right
    if (slot_[k] == Node::kNone) return std::nullopt;
    return Json(o_.tree(), slot_[k]);
  }

 private:
  std::size_t index(std::string_view key) const {
    const auto it = std::lower_bound(names_.begin(), names_.end(), key);
    return it != names_.end() && *it == key ? static_cast<std::size_t>(it - names_.begin()) : N;
  }
  Json o_;
  const std::array<std::string_view, N>& names_;
  std::array<std::uint32_t, N> slot_;
};

// The readers below take a Json or a KeyedObject: anything with find().
template <typename Object>
bool num(const Object& o, const char* key, double& v) {
  const auto it = o.find(key);
  if (!it || !it->is_number()) return false;
  v = it->number();
  return std::isfinite(v);
}

template <typename Object, typename Int>
bool integer(const Object& o, const char* key, Int& v, double lo, double hi) {
  double d = 0;
  if (!num(o, key, d) || d < lo || d > hi || d != std::floor(d)) return false;
  v = static_cast<Int>(d);
  return true;
}

template <typename Object>
bool str(const Object& o, const char* key, std::string& v) {
  const auto it = o.find(key);
  if (!it || !it->is_string()) return false;
  v = it->text();
  return true;
}

template <typename Object>
bool side_of(const Object& o, const char* key, Side& s) {
  std::string v;
  if (!str(o, key, v)) return false;
  if (v == "l") s = Side::Left;
  else if (v == "r") s = Side::Right;
  else return false;
  return true;
}

void params_from(const Json& body, ParamTable& table) {
  body.for_each([&table](const Json& v) {
    std::string text;
    if (v.is_string()) text = v.text();
    else if (v.is_boolean()) text = v.boolean() ? "1" : "0";
    else if (v.is_number()) {
      char buf[64];
      std::snprintf(buf, sizeof buf, "%.10g", v.number());
      text = buf;
    } else return;
    table.set(v.key(), std::move(text));
  });
}

bool team_from(const Json& body, TeamInfo& left, TeamInfo& right) {
  auto side = [](const Json& b, const char* key, TeamInfo& t) {
    const auto it = b.find(key);
    if (!it || !it->is_object()) return false;
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

// Every name player_from() reads, sorted.
constexpr std::array<std::string_view, 34> kPlayerNames = {
    "attentionto", "body",     "capacity", "catch", "change_focus", "change_view", "dash",  "effort",
    "fdir",        "fdist",    "fnum",     "fside", "kick",         "move",        "neck",  "pointto",
    "px",          "py",       "recovery", "say",   "side",         "stamina",     "state", "tackle",
    "turn",        "turn_neck", "type",    "unum",  "vq",           "vw",          "vx",    "vy",
    "x",           "y"};
static_assert(std::is_sorted(kPlayerNames.begin(), kPlayerNames.end()));

bool player_from(const Json& json, WorldState& out) {
  const KeyedObject o(json, kPlayerNames);
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

bool show_from(const Json& body, GameContext& ctx, WorldState& out) {
  if (!integer(body, "time", out.time, -1, 1 << 30)) return false;
  const auto ball = body.find("ball");
  if (!ball || !ball->is_object()) return false;
  out.ball = BallState{};
  if (!num(*ball, "x", out.ball.x) || !num(*ball, "y", out.ball.y)) return false;
  num(*ball, "vx", out.ball.vx);
  num(*ball, "vy", out.ball.vy);
  reset_players(out);
  const auto players = body.find("players");
  if (!players || !players->is_array()) return false;
  bool ok = true;
  players->for_each([&](const Json& p) { ok = ok && p.is_object() && player_from(p, out); });
  if (!ok) return false;
  std::string mode;
  if (str(body, "mode", mode)) {
    if (auto pm = play_mode_from_name(mode)) ctx.play_mode = *pm;
  }
  const auto team = body.find("team");
  if (team && team->is_object()) team_from(*team, ctx.left, ctx.right);
  out.play_mode = ctx.play_mode;
  out.left = ctx.left;
  out.right = ctx.right;
  return true;
}

}  // namespace

bool decode_json_record(std::string_view text, GameContext& ctx, WorldState& out,
                        MessageRecord& msg, RecordKind& kind, std::string& error) {
  kind = RecordKind::Other;
  thread_local Tree tree;
  if (!tree.parse(text) || !Json(tree, 0).is_object()) {
    error = "invalid JSON";
    return false;
  }
  const Json doc(tree, 0);
  // 19.x: {"kind": body}; 17.x/18.x: {"type": "kind", ...body}.
  std::string name;
  std::optional<Json> body;
  const auto type = doc.find("type");
  if (type && type->is_string()) {
    name = type->text();
    body = doc;
  } else if (const auto only = doc.only_member(); only && only->is_object()) {
    name = only->key();
    body = only;
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
