// Encoders for the binary monitor protocols (v1 dispinfo_t, v2
// dispinfo_t2), the inverse of binary_records.hpp, so that the feeder can
// serve every monitor version rcssserver serves. Values outside a field's
// range are clamped (a log can hold anything).
#pragma once

#include <string>
#include <vector>

#include "proto/game_params.hpp"
#include "proto/world_state.hpp"
#include "server/ingest/text_records.hpp"

namespace mc::ingest::binary {

// One 2052-byte (v1) or 2056-byte (v2) SHOW_MODE datagram.
std::string encode_show(const WorldState& s, int version);
// One MSG_MODE datagram (text cut to 2047 bytes).
std::string encode_msg(const MessageRecord& m, int version);
// The v2 init block: PARAM_MODE, PPARAM_MODE, one PT_MODE per type. v1: none.
std::vector<std::string> encode_params(const GameParams& p, int version);

}  // namespace mc::ingest::binary
