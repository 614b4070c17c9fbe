// The one interface every ingest path (any .rcg log, the live UDP monitor
// feed, a replayed monitor capture) produces: a stream of 2D world states in
// order, plus the parameters the server announced and the side events
// (messages, feed lost/back) that happened between states.
#pragma once

#include <chrono>
#include <concepts>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

#include "proto/game_params.hpp"
#include "proto/world_state.hpp"
#include "server/ingest/text_records.hpp"

namespace mc::ingest {

struct IngestStats {
  std::uint64_t shows = 0;    // states returned by next()
  std::uint64_t skipped = 0;  // malformed lines / records / datagrams skipped
  // The first kMaxErrors errors, each naming its position ("line at offset
  // 1234: bad ball at byte 40", "datagram 17: ...").
  std::vector<std::string> errors;
  std::uint64_t bytes = 0;    // decoded input bytes consumed so far
  static constexpr std::size_t kMaxErrors = 100;
};

// Counts a skipped record and keeps its message if fewer than kMaxErrors are kept.
void record_skip(IngestStats& stats, std::string message);
// The same, making the message only when it is kept: in a log of many bad
// records each one past the first kMaxErrors costs a count, not a message
// built and then dropped.
template <std::invocable MakeMessage>
void record_skip(IngestStats& stats, MakeMessage&& make_message) {
  if (stats.errors.size() < IngestStats::kMaxErrors) record_skip(stats, std::string(make_message()));
  else ++stats.skipped;
}

// Something that happened in the stream between two states.
struct SourceEvent {
  enum class Kind {
    Message,   // a (msg ..) record: team graphic, (result ..), (change_player_type ..)
    FeedLost,  // live feed: no datagram for the timeout, or the server went away
    FeedBack,  // live feed: the server answers again (params may have changed)
    ServerReply,  // live feed: (ok ..), (error ..), (warning ..) in message.text
  };
  Kind kind = Kind::Message;
  // The index the next state returned by next() will have: the event came
  // after state next_index-1 and before state next_index.
  std::uint64_t next_index = 0;
  MessageRecord message;  // Kind::Message and Kind::ServerReply
  std::string detail;     // FeedLost / FeedBack: human-readable reason
};

class StateSource {
 public:
  virtual ~StateSource() = default;
  // The next world state in stream order; false at the end of the input.
  // Never throws on bad input (bad records are counted in stats() and
  // skipped); a bad record never half-writes `out`, so after false `out`
  // still holds the last state returned. A live source blocks until a state
  // arrives or it is stopped.
  virtual bool next(WorldState& out) = 0;
  // Parameters announced so far; valid once the first state has been
  // returned (defaults if the input carried none, e.g. log v1/v2).
  virtual const GameParams& params() const = 0;
  virtual const IngestStats& stats() const = 0;

  // --- extensions (all have defaults, so a plain next() loop keeps working)

  // Pops the oldest pending event; false when there is none. Call after each
  // next() (and after next_for() returns Idle) to see events in order. At
  // most kMaxPendingEvents are kept; older ones are dropped and counted as skips.
  virtual bool poll_event(SourceEvent& out) {
    (void)out;
    return false;
  }
  static constexpr std::size_t kMaxPendingEvents = 4096;

  enum class Wait { State, Idle, End };
  // Like next(), but a live source gives up after `timeout` and returns Idle
  // (so the caller can drain FeedLost / FeedBack events and keep serving its
  // clients during an outage). Logs never return Idle.
  virtual Wait next_for(WorldState& out, std::chrono::milliseconds timeout) {
    (void)timeout;
    return next(out) ? Wait::State : Wait::End;
  }

  // Thread-safe: makes a blocked next() of a live source return false soon
  // (within ~50 ms). No effect on logs.
  virtual void stop() {}
};

// Opens any .rcg (format sniffed from the first bytes, gzip or plain):
// v1/v2/v3 binary, ULG4/5/6 text, 17.x/18.x/19.x JSON. nullptr + error text
// when the file cannot be opened or is not a game log.
std::unique_ptr<StateSource> open_log(const std::string& path, std::string& error);
// The same over bytes in memory (kept alive by the caller); for tests/fuzzing.
std::unique_ptr<StateSource> open_log_memory(std::string_view bytes, std::string& error);

// A log path, or a live rcssserver as "udp://HOST:PORT" ("udp://" alone =
// 127.0.0.1:6000; "udp://HOST:PORT/V" picks monitor version V: 5 by
// default, 4, 3 or -1 for JSON). Live sources never fail to open: they keep
// trying to connect (see monitor_client.hpp). nullptr + error for a bad
// spec or an unreadable log.
std::unique_ptr<StateSource> open_source(const std::string& spec, std::string& error);
bool is_live_spec(const std::string& spec);

}  // namespace mc::ingest
