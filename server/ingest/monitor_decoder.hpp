// Decodes one datagram of rcssserver's monitor feed, whatever the protocol
// version: text v3/v4/v5 (`(show ..)`, `(msg ..)`, `(server_param ..)`, ...),
// JSON (-1), binary v1 (2052-byte dispinfo_t) or v2 (2056-byte dispinfo_t2).
// The form is recognised per datagram (first byte / size), which also copes
// with the server's shared-cache bug that mixes v3 and v5 text shows
// (rcss-protocol.md section 13, item 11).
#pragma once

#include <array>
#include <string>
#include <string_view>

#include "server/ingest/json_records.hpp"

namespace mc::ingest {

// rcssserver never sends more than MaxMesg = 8192 bytes; anything larger is
// not from a server and is refused unread.
inline constexpr std::size_t kMaxDatagram = 8192;

class MonitorDecoder {
 public:
  enum class Kind {
    Show,     // `out` holds the show (time, play mode, teams, ball, players)
    Message,  // `msg` holds a (msg ..)
    Params,   // server_param / player_param / player_type: context().params updated
    Reply,    // (ok ..), (error ..), (warning ..): `msg.text` holds it
    Ignored,  // a well-formed datagram of no interest (draw, blank, ...)
    Error,    // malformed or oversized: `error` says why
  };
  // Decodes `datagram` (a trailing NUL is allowed). Never throws; never
  // reads outside the span.
  Kind decode(std::string_view datagram, WorldState& out, MessageRecord& msg, std::string& error);

  // Play mode, teams and parameters as last announced.
  const GameContext& context() const { return ctx_; }

 private:
  Kind decode_text(std::string_view d, WorldState& out, MessageRecord& msg, std::string& error);
  Kind decode_binary(std::string_view d, WorldState& out, MessageRecord& msg, std::string& error);

  GameContext ctx_;
  std::array<std::int16_t, kMaxPlayers> v1_types_{};  // from (change_player_type ..)
};

}  // namespace mc::ingest
