// Decoders for rcssserver's binary structs (monitor v1/v2, logs v1/v2/v3),
// rcss-protocol.md section 6. All integers are big-endian; the structs were
// written with x86-64 natural alignment, so the offsets below include the
// padding. Every decoder checks the span size first and returns false if it
// is too short; it never reads outside `bytes`.
#pragma once

#include <cstddef>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>

#include "proto/game_params.hpp"
#include "proto/world_state.hpp"

namespace mc::ingest::binary {

// DispInfoMode record tags.
enum Mode : std::int16_t {
  kNoInfo = 0, kShow = 1, kMsg = 2, kDraw = 3, kBlank = 4, kPlayMode = 5, kTeam = 6,
  kPlayerType = 7, kParam = 8, kPlayerParam = 9,
};

// Struct sizes in bytes (measured with g++ x86-64, rcss-protocol.md section 6).
inline constexpr std::size_t kShowInfoSize = 316;        // showinfo_t (v1)
inline constexpr std::size_t kMsgInfoSize = 2050;        // msginfo_t
inline constexpr std::size_t kDispInfoSize = 2052;       // dispinfo_t (monitor v1, log v1)
inline constexpr std::size_t kShowInfo2Size = 1468;      // showinfo_t2 (monitor v2)
inline constexpr std::size_t kShortShowInfo2Size = 1428; // short_showinfo_t2 (log v3)
inline constexpr std::size_t kDispInfo2Size = 2056;      // dispinfo_t2 (monitor v2)
inline constexpr std::size_t kTeamPairSize = 36;         // team_t[2]
inline constexpr std::size_t kPlayerTypeSize = 88;       // player_type_t
inline constexpr std::size_t kServerParamsSize = 396;    // server_params_t
inline constexpr std::size_t kPlayerParamsSize = 132;    // player_params_t

std::int16_t be16(const char* p);
std::int32_t be32(const char* p);

// showinfo_t (v1 scale 1/16 m, integer degrees, no velocities): fills time,
// play mode, both teams, ball position and all players.
bool decode_showinfo_v1(std::string_view bytes, WorldState& out);
// showinfo_t2 (monitor v2): play mode, teams, ball, players, time.
bool decode_showinfo2(std::string_view bytes, WorldState& out);
// short_showinfo_t2 (log v3): ball, players and time only.
bool decode_short_showinfo2(std::string_view bytes, WorldState& out);
// team_t[2]: names ("null" -> "") and scores.
bool decode_teams(std::string_view bytes, TeamInfo& left, TeamInfo& right);
// player_type_t.
bool decode_player_type(std::string_view bytes, PlayerType& out);
// server_params_t: the fields a viewer uses, under their text names
// (goal_width, ball_size, player_size, half_time, simulator_step, ...).
bool decode_server_params(std::string_view bytes, ParamTable& out);
// The inverse for the same fields: writes them into `out` (396 bytes,
// other fields zero). False if `out` is too short.
bool encode_server_params(const ParamTable& in, std::string& out);
// msginfo_t (Int16 board + NUL-padded text).
bool decode_msginfo(std::string_view bytes, int& board, std::string& text);

// v1 shows carry no player type; the server announces types in
// `(change_player_type SIDE UNUM TYPE)` messages. Applies one such message to
// `types` (indexed like WorldState::players); false if `text` is not one.
bool apply_change_player_type(std::string_view text, std::array<std::int16_t, kMaxPlayers>& types);

}  // namespace mc::ingest::binary
