// Parser for rcssserver's text show record, shared by the log reader (ULG4/5/6
// `(show ...)` lines) and the live monitor client (v3/v4/v5 show datagrams).
// Grammar: server/ingest/rcss-protocol.md section 3.1.
#pragma once

#include <string>
#include <string_view>

#include "proto/world_state.hpp"

namespace mc::ingest {

// What a monitor show carried beyond the log form.
struct ShowExtras {
  bool has_play_mode = false;  // `(pm N)` was present (monitor v3+)
  bool has_team = false;       // `(tm ...)` was present (monitor v3+)
};

// Parses `(show TIME [(pm N)] [(tm L R LS RS [LPS LPM RPS RPM])] BALL PLAYER...)`.
// Fills out.time, out.ball and all 22 out.players (slots missing from the
// record are set to an absent, parked player); out.play_mode and out.left /
// out.right only when the record carries (pm)/(tm) (see `extras`). Does not
// touch out.index or out.stoppage. Returns false and sets `error` (naming
// the byte position inside `text`) when the record is malformed or cut off;
// `out` is then unspecified.
bool parse_text_show(std::string_view text, WorldState& out, ShowExtras& extras,
                     std::string& error);

// The player slots of an absent player: state 0, parked at
// (-(unum*3*side), -37) as rcssserver's Player::disable() does.
void reset_players(WorldState& out);
void reset_player(WorldState& out, int slot);

}  // namespace mc::ingest
