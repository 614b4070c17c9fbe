// Parsers for the text records other than shows (rcss-protocol.md section 4):
// (playmode ..), (team ..), (msg ..), (server_param ..), (player_param ..),
// (player_type ..). Used by the ULG4/5/6 log reader and the text monitor
// client. Each returns false with `error` naming the byte position inside
// `text` when the record is malformed; outputs are then unspecified.
#pragma once

#include <string>
#include <string_view>

#include "proto/game_params.hpp"
#include "proto/world_state.hpp"

namespace mc::ingest {

// A `(msg TIME BOARD "TEXT")` record: team graphics, `(result ..)`,
// `(change_player_type ..)`, referee and player messages.
struct MessageRecord {
  int time = 0;
  int board = 0;     // 1 = MSG_BOARD, 2 = LOG_BOARD
  std::string text;  // between the first '"' and the last "\")", unescaped
};

// `(playmode TIME NAME)`.
bool parse_playmode_record(std::string_view text, int& time, PlayMode& mode, std::string& error);
// `(team TIME LNAME RNAME LSCORE RSCORE [LPS LPM RPS RPM])`; "null" -> "".
bool parse_team_record(std::string_view text, int& time, TeamInfo& left, TeamInfo& right,
                       std::string& error);
// `(msg TIME BOARD "TEXT")`. The text may hold unescaped quotes (team
// graphics), so it runs to the last `")` of the record.
bool parse_msg_record(std::string_view text, MessageRecord& out, std::string& error);
// `(server_param (k v)..)` or `(player_param (k v)..)` into `table`
// (keys added or overwritten; quotes removed from string values).
bool parse_param_record(std::string_view text, std::string_view head, ParamTable& table,
                        std::string& error);
// `(player_type (id N)(k v)..)`: stores the type at index id in `params`
// (growing player_types with defaults as needed; id limited to 0..255).
bool parse_player_type_record(std::string_view text, GameParams& params, std::string& error);

// Builds a PlayerType from its key/value table (shared with the JSON and
// binary readers). Missing keys keep rcssserver 19's type-0 defaults.
PlayerType player_type_from_table(const ParamTable& table);
// Stores `t` at index t.id, growing the vector as needed. False for ids
// outside 0..255.
bool store_player_type(GameParams& params, const PlayerType& t);

}  // namespace mc::ingest
