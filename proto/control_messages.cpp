#include "proto/control_messages.hpp"

#include "proto/json_number.hpp"
#include "proto/json_text.hpp"

#include <algorithm>
#include <charconv>

#include "proto/pose_frame.hpp"

#include <cmath>
#include <stdexcept>

namespace mc::proto {
namespace {

using nlohmann::json;

const char* side_name(Side s) { return s == Side::Left ? "left" : s == Side::Right ? "right" : "neutral"; }
Side side_from(const json& j) {
  const std::string s = j.get<std::string>();
  if (s == "left") return Side::Left;
  if (s == "right") return Side::Right;
  if (s == "neutral") return Side::Neutral;
  throw std::runtime_error("side must be \"left\", \"right\" or \"neutral\"");
}
std::uint8_t unum_from(const json& j) {
  const int u = json_integer<int>(j);
  if (u < 0 || u > kPlayersPerSide) throw std::runtime_error("unum out of range");
  return static_cast<std::uint8_t>(u);
}
json team_json(const TeamHello& t) { return {{"name", t.name}, {"color", t.color}, {"color2", t.color2}}; }
TeamHello team_from(const json& j) {
  TeamHello t;
  t.name = j.at("name").get<std::string>();
  t.color = j.value("color", t.color);
  t.color2 = j.value("color2", t.color2);
  return t;
}

// Run-length code of a reach map's cells: "l37c2r14n5" (a letter, then its count).
std::string rle_encode(const std::string& cells) {
  std::string out;
  for (std::size_t i = 0; i < cells.size();) {
    std::size_t j = i;
    while (j < cells.size() && cells[j] == cells[i]) ++j;
    out += cells[i];
    out += std::to_string(j - i);
    i = j;
  }
  return out;
}
std::string rle_decode(const std::string& rle, std::size_t expected) {
  std::string out;
  for (std::size_t i = 0; i < rle.size();) {
    const char c = rle[i++];
    if (c != 'n' && c != 'l' && c != 'r' && c != 'c') throw std::runtime_error("reach_map cells: bad owner letter");
    std::size_t n = 0, digits = 0;
    while (i < rle.size() && rle[i] >= '0' && rle[i] <= '9' && digits < 7) {
      n = n * 10 + static_cast<std::size_t>(rle[i++] - '0');
      ++digits;
    }
    if (digits == 0 || n == 0 || n > expected - out.size()) throw std::runtime_error("reach_map cells: bad run length");
    out.append(n, c);
  }
  if (out.size() != expected) throw std::runtime_error("reach_map cells do not cover the grid");
  return out;
}

// Eleven stamina values (-1: no player), each in [-1, 1e6].
std::array<int, 11> stamina_from(const json& j) {
  if (!j.is_array() || j.size() != 11) throw std::runtime_error("stamina must be an array of 11 numbers");
  std::array<int, 11> out{};
  for (std::size_t i = 0; i < 11; ++i) {
    const int v = json_integer<int>(j.at(i));
    if (v < -1 || v > 1000000) throw std::runtime_error("stamina out of range");
    out[i] = v;
  }
  return out;
}

struct ToJson {
  json operator()(const StaminaUpdate& e) const {
    return {{"type", "stamina"}, {"seq", e.seq}, {"time", e.time}, {"left", e.left}, {"right", e.right}};
  }
  json operator()(const ReachMapUpdate& e) const {
    json j = {{"type", "reach_map"}, {"seq", e.seq}, {"time", e.time},
              {"grid", {{"w", e.width}, {"h", e.height}, {"cell", e.cell}, {"x0", e.x0}, {"y0", e.y0}}},
              {"cells", rle_encode(e.cells)}};
    if (e.ball_side != Side::Neutral) j["ball"] = {{"side", side_name(e.ball_side)}, {"unum", e.ball_unum}, {"t", e.ball_time}};
    return j;
  }
  json operator()(const KickEvent& e) const {
    return {{"type", "kick"}, {"seq", e.seq}, {"time", e.time}, {"side", side_name(e.side)}, {"unum", e.unum},
            {"foot", e.foot == Foot::Left ? "left" : "right"}, {"contact_time_ms", e.contact_time_ms}};
  }
  json operator()(const GoalEvent& e) const {
    return {{"type", "goal"}, {"seq", e.seq}, {"time", e.time}, {"side", side_name(e.side)},
            {"score", {e.score_left, e.score_right}}};
  }
  json operator()(const PlayModeEvent& e) const {
    return {{"type", "play_mode"}, {"seq", e.seq}, {"time", e.time}, {"mode", std::string(play_mode_name(e.mode))},
            {"mode_id", static_cast<int>(e.mode)}};
  }
  json operator()(const CardEvent& e) const {
    return {{"type", "card"}, {"seq", e.seq}, {"time", e.time}, {"side", side_name(e.side)}, {"unum", e.unum},
            {"card", e.card == CardColor::Red ? "red" : "yellow"}};
  }
  json operator()(const ScoreUpdate& e) const {
    return {{"type", "score"}, {"seq", e.seq}, {"time", e.time}, {"left", e.left}, {"right", e.right},
            {"pen_left", e.pen_left}, {"pen_right", e.pen_right}};
  }
  json operator()(const TeamsUpdate& e) const {
    return {{"type", "teams"}, {"seq", e.seq}, {"left", team_json(e.left)}, {"right", team_json(e.right)}};
  }
  json operator()(const DirectorCue& e) const { return director_cue_to_json(e); }
  json operator()(const FeedStatus& e) const {
    return {{"type", "feed"}, {"status", e.lost ? "lost" : "back"}, {"seq", e.seq},
            {"server_time_ms", e.server_time_ms}, {"detail", e.detail}};
  }
};

ControlMessage parse(const json& j, const std::string& type) {
  if (type == "kick") {
    KickEvent e;
    e.seq = json_integer<std::uint32_t>(j.at("seq"));
    e.time = json_integer<int>(j.at("time"));
    e.side = side_from(j.at("side"));
    e.unum = unum_from(j.at("unum"));
    const std::string foot = j.at("foot").get<std::string>();
    if (foot != "left" && foot != "right") throw std::runtime_error("foot must be \"left\" or \"right\"");
    e.foot = foot == "left" ? Foot::Left : Foot::Right;
    e.contact_time_ms = json_integer<std::uint64_t>(j.at("contact_time_ms"));
    return e;
  }
  if (type == "goal") {
    GoalEvent e;
    e.seq = json_integer<std::uint32_t>(j.at("seq"));
    e.time = json_integer<int>(j.at("time"));
    e.side = side_from(j.at("side"));
    const json& s = j.at("score");
    if (!s.is_array() || s.size() != 2) throw std::runtime_error("score must be [left, right]");
    e.score_left = json_integer<int>(s.at(0));
    e.score_right = json_integer<int>(s.at(1));
    return e;
  }
  if (type == "play_mode") {
    PlayModeEvent e;
    e.seq = json_integer<std::uint32_t>(j.at("seq"));
    e.time = json_integer<int>(j.at("time"));
    const auto mode = play_mode_from_name(j.at("mode").get<std::string>());
    if (!mode) throw std::runtime_error("unknown play mode name");
    e.mode = *mode;
    return e;
  }
  if (type == "card") {
    CardEvent e;
    e.seq = json_integer<std::uint32_t>(j.at("seq"));
    e.time = json_integer<int>(j.at("time"));
    e.side = side_from(j.at("side"));
    e.unum = unum_from(j.at("unum"));
    const std::string card = j.at("card").get<std::string>();
    if (card != "yellow" && card != "red") throw std::runtime_error("card must be \"yellow\" or \"red\"");
    e.card = card == "red" ? CardColor::Red : CardColor::Yellow;
    return e;
  }
  if (type == "score") {
    ScoreUpdate e;
    e.seq = json_integer<std::uint32_t>(j.at("seq"));
    e.time = json_integer<int>(j.at("time"));
    e.left = json_integer<int>(j.at("left"));
    e.right = json_integer<int>(j.at("right"));
    e.pen_left = j.value("pen_left", 0);
    e.pen_right = j.value("pen_right", 0);
    return e;
  }
  if (type == "teams") {
    TeamsUpdate e;
    e.seq = json_integer<std::uint32_t>(j.at("seq"));
    e.left = team_from(j.at("left"));
    e.right = team_from(j.at("right"));
    return e;
  }
  if (type == "feed") {
    FeedStatus e;
    const std::string status = j.at("status").get<std::string>();
    if (status != "lost" && status != "back") throw std::runtime_error("status must be \"lost\" or \"back\"");
    e.lost = status == "lost";
    e.seq = json_integer<std::uint32_t>(j.at("seq"));
    e.server_time_ms = json_integer<std::uint64_t>(j.at("server_time_ms"));
    e.detail = j.value("detail", "");
    return e;
  }
  if (type == "reach_map") {
    ReachMapUpdate e;
    e.seq = json_integer<std::uint32_t>(j.at("seq"));
    e.time = json_integer<int>(j.at("time"));
    const json& g = j.at("grid");
    e.width = json_integer<int>(g.at("w"));
    e.height = json_integer<int>(g.at("h"));
    e.cell = g.at("cell").get<double>();
    e.x0 = g.at("x0").get<double>();
    e.y0 = g.at("y0").get<double>();
    if (e.width < 1 || e.height < 1 || e.width > 512 || e.height > 512) throw std::runtime_error("grid size out of range");
    if (!(e.cell > 0 && e.cell < 1000) || !(std::fabs(e.x0) < 1e4) || !(std::fabs(e.y0) < 1e4))
      throw std::runtime_error("grid geometry out of range");
    e.cells = rle_decode(j.at("cells").get<std::string>(), static_cast<std::size_t>(e.width) * static_cast<std::size_t>(e.height));
    if (const auto b = j.find("ball"); b != j.end()) {
      e.ball_side = side_from(b->at("side"));
      e.ball_unum = unum_from(b->at("unum"));
      e.ball_time = b->at("t").get<double>();
    }
    return e;
  }
  if (type == "stamina") {
    StaminaUpdate e;
    e.seq = json_integer<std::uint32_t>(j.at("seq"));
    e.time = json_integer<int>(j.at("time"));
    e.left = stamina_from(j.at("left"));
    e.right = stamina_from(j.at("right"));
    return e;
  }
  if (type == "director") return director_cue_from_json(j);
  throw std::invalid_argument("unknown control message type \"" + type + "\"");
}

}  // namespace

StaminaUpdate stamina_update(const WorldState& state) {
  StaminaUpdate u;
  u.time = state.time;
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerState& p = state.players[static_cast<std::size_t>(i)];
    const int v = p.state != 0 ? static_cast<int>(std::lround(std::clamp(p.stamina, 0.0, 1e6))) : -1;
    (i < kPlayersPerSide ? u.left : u.right)[static_cast<std::size_t>(i % kPlayersPerSide)] = v;
  }
  return u;
}

json control_to_json_value(const ControlMessage& message) { return std::visit(ToJson{}, message); }
namespace {

void append_int(std::string& out, long long v) {
  char buf[24];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, v).ptr);
}

// The stamina message is most of a recording's control messages (one for
// each team every few cycles): it is written straight, byte for byte what
// the tree's dump() writes (keys in the tree's sorted order), without the
// tree's ~30 allocations.
std::string stamina_json(const StaminaUpdate& e) {
  std::string out;
  out.reserve(160);
  const auto team = [&out](const char* key, const std::array<int, 11>& v) {
    out += key;
    for (std::size_t i = 0; i < v.size(); ++i) {
      out += i == 0 ? '[' : ',';
      append_int(out, v[i]);
    }
    out += ']';
  };
  team("{\"left\":", e.left);
  team(",\"right\":", e.right);
  out += ",\"seq\":";
  append_int(out, e.seq);
  out += ",\"time\":";
  append_int(out, e.time);
  out += ",\"type\":\"stamina\"}";
  return out;
}

}  // namespace

std::string to_json(const ControlMessage& message) {
  if (const auto* stamina = std::get_if<StaminaUpdate>(&message)) return stamina_json(*stamina);
  return control_to_json_value(message).dump();
}

std::string control_type(std::string_view text, std::string& error) {
  const json j = parse_json_text(text);
  if (j.is_discarded() || !j.is_object()) {
    error = "control message is not a JSON object";
    return "";
  }
  const auto it = j.find("type");
  if (it == j.end() || !it->is_string()) {
    error = "control message has no \"type\"";
    return "";
  }
  return it->get<std::string>();
}

bool control_from_json(std::string_view text, ControlMessage& out, std::string& error) {
  const json j = parse_json_text(text);
  if (j.is_discarded() || !j.is_object()) {
    error = "control message is not a JSON object";
    return false;
  }
  const auto it = j.find("type");
  if (it == j.end() || !it->is_string()) {
    error = "control message has no \"type\"";
    return false;
  }
  const std::string type = it->get<std::string>();
  try {
    out = parse(j, type);
  } catch (const std::invalid_argument& e) {
    error = e.what();
    return false;
  } catch (const std::exception& e) {
    error = "bad \"" + type + "\" message: " + e.what();
    return false;
  }
  return true;
}

void shift_frames(ControlMessage& message, std::int64_t frames) {
  std::visit(
      [frames](auto& m) {
        m.seq = static_cast<std::uint32_t>(static_cast<std::int64_t>(m.seq) + frames);
        if constexpr (requires { m.contact_time_ms; })
          m.contact_time_ms = static_cast<std::uint64_t>(static_cast<std::int64_t>(m.contact_time_ms) +
                                                        frames * kFrameIntervalMs);
      },
      message);
}

}  // namespace mc::proto
