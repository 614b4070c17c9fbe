#include "proto/director_cue.hpp"

#include "proto/json_number.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mc::proto {
namespace {

using nlohmann::json;

constexpr std::array<std::string_view, 6> kShotNames = {"wide", "tracking", "set_piece", "attack", "scorer", "replay"};
constexpr std::array<std::string_view, 3> kAngleNames = {"behind_goal", "low_side", "high"};

const char* side_text(Side s) { return s == Side::Left ? "left" : s == Side::Right ? "right" : "neutral"; }
Side side_of(const json& j) {
  const std::string s = j.get<std::string>();
  if (s == "left") return Side::Left;
  if (s == "right") return Side::Right;
  if (s == "neutral") return Side::Neutral;
  throw std::runtime_error("side must be \"left\", \"right\" or \"neutral\"");
}

// A finite number in [lo, hi].
double number_in(const json& j, const char* key, double lo, double hi) {
  const double v = j.at(key).get<double>();
  if (!std::isfinite(v) || v < lo || v > hi) throw std::runtime_error(std::string(key) + " out of range");
  return v;
}

// Rounded to centimetres / tenths: the text stays short and stable.
double tidy(double v) { return std::round(v * 100.0) / 100.0; }

}  // namespace

std::string_view shot_name(Shot s) { return kShotNames[static_cast<std::size_t>(s)]; }
std::optional<Shot> shot_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kShotNames.size(); ++i)
    if (kShotNames[i] == name) return static_cast<Shot>(i);
  return std::nullopt;
}
std::string_view replay_angle_name(ReplayAngle a) { return kAngleNames[static_cast<std::size_t>(a)]; }
std::optional<ReplayAngle> replay_angle_from_name(std::string_view name) {
  for (std::size_t i = 0; i < kAngleNames.size(); ++i)
    if (kAngleNames[i] == name) return static_cast<ReplayAngle>(i);
  return std::nullopt;
}

json director_cue_to_json(const DirectorCue& c) {
  json j = {{"type", "director"}, {"seq", c.seq}, {"time", c.time}, {"cut", c.cut},
            {"shot", std::string(shot_name(c.shot))}};
  // A replay has none: each of its angles is a fixed rig.
  if (c.shot != Shot::Replay)
    j["framing"] = {{"distance", tidy(c.framing.distance)}, {"height", tidy(c.framing.height)},
                    {"fov", tidy(c.framing.fov)}, {"lead", tidy(c.framing.lead)}};
  if (c.subject_unum != 0) j["subject"] = {{"side", side_text(c.subject_side)}, {"unum", c.subject_unum}};
  if (c.attack != Side::Neutral) j["attack"] = side_text(c.attack);
  if (c.goal != Side::Neutral) j["goal"] = side_text(c.goal);
  if (c.shot == Shot::Replay) {
    json segments = json::array();
    for (const ReplaySegment& s : c.replay)
      segments.push_back({{"from", s.from}, {"to", s.to}, {"angle", std::string(replay_angle_name(s.angle))},
                          {"speed", tidy(s.speed)}});
    j["replay"] = std::move(segments);
  }
  return j;
}

DirectorCue director_cue_from_json(const json& j) {
  DirectorCue c;
  c.seq = json_integer<std::uint32_t>(j.at("seq"));
  c.time = json_integer<int>(j.at("time"));
  c.cut = j.at("cut").get<bool>();
  const auto shot = shot_from_name(j.at("shot").get<std::string>());
  if (!shot) throw std::runtime_error("unknown shot");
  c.shot = *shot;
  if (const auto s = j.find("subject"); s != j.end()) {
    c.subject_side = side_of(s->at("side"));
    const int unum = json_integer<int>(s->at("unum"));
    if (unum < 1 || unum > kPlayersPerSide || c.subject_side == Side::Neutral)
      throw std::runtime_error("subject must be a side and a unum 1..11");
    c.subject_unum = static_cast<std::uint8_t>(unum);
  }
  if (const auto a = j.find("attack"); a != j.end()) c.attack = side_of(*a);
  if (const auto g = j.find("goal"); g != j.end()) c.goal = side_of(*g);
  if (const auto f = j.find("framing"); f != j.end()) {
    c.framing.distance = number_in(*f, "distance", 0, 500);
    c.framing.height = number_in(*f, "height", 0, 500);
    c.framing.fov = number_in(*f, "fov", 1, 170);
    c.framing.lead = number_in(*f, "lead", -100, 100);
  }
  if (c.shot == Shot::Replay) {
    const json& r = j.at("replay");
    if (!r.is_array() || r.empty() || r.size() > kMaxReplaySegments)
      throw std::runtime_error("replay must hold 1 to 4 segments");
    for (const json& s : r) {
      ReplaySegment seg;
      seg.from = json_integer<int>(s.at("from"));
      seg.to = json_integer<int>(s.at("to"));
      if (seg.from >= seg.to || seg.from < -kMaxReplayReachFrames || seg.to > kMaxReplayReachFrames ||
          seg.to - seg.from > kMaxReplaySegmentFrames)
        throw std::runtime_error("replay segment out of range");
      const auto angle = replay_angle_from_name(s.at("angle").get<std::string>());
      if (!angle) throw std::runtime_error("unknown replay angle");
      seg.angle = *angle;
      seg.speed = number_in(s, "speed", 0.1, 4);
      c.replay.push_back(seg);
    }
  }
  return c;
}

}  // namespace mc::proto
