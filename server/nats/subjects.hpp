// NATS names of a Matchcast deployment, all derived from one prefix:
//   <prefix>.<game>.live   every message of a game, core NATS (at most once)
//   <prefix>.<game>.key    the game's latest hello + keyframe, kept by the
//                          JetStream stream <PREFIX>_KEY (one per subject)
// A game name is one subject token: letters, digits, '_' and '-'.
#pragma once

#include <string>
#include <string_view>

namespace mc::nats {

// A game name usable as one subject token (no '.', wildcard or space).
bool valid_game(std::string_view game);
// A prefix of one or more such tokens joined by '.'.
bool valid_prefix(std::string_view prefix);

std::string live_subject(std::string_view prefix, std::string_view game);
std::string key_subject(std::string_view prefix, std::string_view game);
std::string live_wildcard(std::string_view prefix);  // <prefix>.*.live
std::string key_wildcard(std::string_view prefix);   // <prefix>.*.key
// "matchcast" -> "MATCHCAST_KEY", "a.b" -> "A_B_KEY".
std::string stream_name(std::string_view prefix);

// The game of "<prefix>.<game>.live", or "" when `subject` is not one.
std::string game_of_live_subject(std::string_view prefix, std::string_view subject);

}  // namespace mc::nats
