// Writes world states, parameters and messages in rcssserver's monitor
// formats: text v3/v4/v5, JSON (-1) and binary v1/v2 (binary_writer.hpp). Used by the feeder to play a log as
// if it were a live server. Numbers are printed in their shortest exact form
// (std::to_chars), so a value read from a log makes the round trip unchanged.
// Optional fields the state lacks (capacity, focus point, counters) are left
// out rather than invented: what the client reads back equals the input.
#pragma once

#include <string>
#include <vector>

#include "proto/game_params.hpp"
#include "proto/world_state.hpp"
#include "server/ingest/text_records.hpp"

namespace mc::ingest {

// True for the monitor versions these functions can write: 1..5 and -1.
bool serializer_supports(int version);
// Binary payloads (v1, v2) are fixed-size records sent as they are; text
// and JSON payloads are sent with a terminating NUL.
bool serializer_is_binary(int version);

// One `(show ...)` (text) or `{"show":{...}}` (JSON) datagram payload,
// without the trailing NUL, or a binary SHOW_MODE record. Text v3 drops capacity and the focus point,
// v4 drops the focus point; v5 writes everything present. JSON, like
// rcssserver's JSON monitor, has no command counters.
std::string serialize_show(const WorldState& s, int version);
// The init block: server_param, player_param, then one player_type each.
std::vector<std::string> serialize_params(const GameParams& p, int version);
// `(msg T BOARD "text")` or {"msg":{...}}.
std::string serialize_msg(const MessageRecord& m, int version);

}  // namespace mc::ingest
