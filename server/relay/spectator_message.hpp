// What a spectator may send (text JSON), read once for the session: the
// time shift requests of a live spectator, and the replay controls, which
// go on, read, to the replay (server/replay/replay_player.hpp).
//   {"type":"timeshift","action":"seek","time":CYCLE}
//   {"type":"timeshift","action":"live"}
//   {"type":"replay","action":"pause"|"play"|"toggle"|"next_goal"|"prev_goal"}
//   {"type":"replay","action":"seek","time":CYCLE}
//   {"type":"replay","action":"speed","speed":FACTOR}
// Anything else is nullopt: spectators are otherwise read-only, and a
// message that is not JSON, not an object or has no string "type" is ignored.
#pragma once

#include <optional>
#include <string>
#include <string_view>

namespace mc::relay {

struct SpectatorMessage {
  std::string type;             // "timeshift", "replay", or another string (ignored by the caller)
  std::string action;           // "" when absent or not a string
  std::optional<double> time;   // a number "time", when present
  std::optional<double> speed;  // a number "speed", when present
};

// The top-level members above; where a key repeats the last one counts, as
// in a parsed object. Nothing else of the message is kept or built: a
// spectator's message is read by a SAX pass, not made into a JSON tree.
std::optional<SpectatorMessage> read_spectator_message(std::string_view text);

}  // namespace mc::relay
