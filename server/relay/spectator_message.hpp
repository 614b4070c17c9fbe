// What a spectator may send (text JSON), read once for the session: the
// time shift requests of a live spectator, and the replay controls, which
// go on to the replay (server/replay/replay_player.hpp reads their fields).
//   {"type":"timeshift","action":"seek","time":CYCLE}
//   {"type":"timeshift","action":"live"}
//   {"type":"replay","action":...}
// Anything else is nullopt: spectators are otherwise read-only, and a
// message that is not JSON, not an object or has no string "type" is ignored.
#pragma once

#include <optional>
#include <string>
#include <string_view>

#include <nlohmann/json.hpp>

namespace mc::relay {

struct SpectatorMessage {
  std::string type;    // "timeshift", "replay", or another string (ignored by the caller)
  std::string action;  // "" when absent or not a string
  std::optional<double> time;  // a number "time", when present
};

inline std::optional<SpectatorMessage> read_spectator_message(std::string_view text) {
  const auto j = nlohmann::json::parse(text, nullptr, /*allow_exceptions=*/false);
  if (!j.is_object()) return std::nullopt;
  const auto type = j.find("type");
  if (type == j.end() || !type->is_string()) return std::nullopt;
  SpectatorMessage m;
  m.type = type->get<std::string>();
  const auto action = j.find("action");
  if (action != j.end() && action->is_string()) m.action = action->get<std::string>();
  const auto time = j.find("time");
  if (time != j.end() && time->is_number()) m.time = time->get<double>();
  return m;
}

}  // namespace mc::relay
