// Decodes one JSON element of a game log or one JSON monitor datagram
// (rcss-protocol.md section 5). Three flavours are accepted:
//   19.x: {"show":{...}}, {"playmode":{...}}, {"server_param":{...}}, ...
//   17.x/18.x: {"type":"show", ...fields...} (same field names).
// Unknown kinds ({"version":..}, {"timestamp":..}, headers) are reported as
// Other and are not errors.
#pragma once

#include <string>
#include <string_view>

#include "proto/game_params.hpp"
#include "proto/world_state.hpp"
#include "server/ingest/text_records.hpp"

namespace mc::ingest {

// What the stream has said so far, updated by non-show records.
struct GameContext {
  GameParams params;
  PlayMode play_mode = PlayMode::Null;
  TeamInfo left, right;
};

enum class RecordKind { Show, PlayMode, Team, Msg, ServerParam, PlayerParam, PlayerType, Other };

// Parses `text` (one JSON object). Show: fills out.time, ball, players, and
// out.play_mode / teams from the show's "mode"/"team" if present (updating
// `ctx` too), else from ctx. Msg: fills `msg`. Parameter, playmode and team
// records update `ctx`. Returns false with `error` for invalid JSON or a
// record missing required fields; never throws.
bool decode_json_record(std::string_view text, GameContext& ctx, WorldState& out,
                        MessageRecord& msg, RecordKind& kind, std::string& error);

}  // namespace mc::ingest
