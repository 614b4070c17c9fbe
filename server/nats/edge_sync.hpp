// One game on an edge: turns the envelopes that arrive from NATS back into
// the publishes of a local relay Channel, as if a feed ran here. The relay's
// fan-out, late join and keyframe skip then work unchanged.
//
// What it guarantees to the channel's spectators:
// - messages in the origin's order, each once (duplicates from the snapshot /
//   live overlap are dropped by envelope number);
// - no delta whose base is missing: after a lost message (a number gap, a
//   reconnect) deltas are held back until the next keyframe;
// - nothing before a hello (frames, events, feed messages), nothing malformed: an envelope that does not
//   parse, a frame whose header is bad, a control that is not JSON are
//   counted and skipped;
// - "feed lost" / "feed back" messages (proto FeedStatus) when the NATS link
//   drops and returns or the origin falls silent, like a live feed's.
//
// Thread-safe: NATS callbacks, the edge's worker and tests may call any
// member from any thread; calls are serialized so the channel sees one
// producer.
#pragma once

#include <array>
#include <chrono>
#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <string>
#include <string_view>

#include "server/nats/envelope.hpp"
#include "server/relay/channel.hpp"

namespace mc::nats {

// How far behind the origin an edge's frames are: from the frame header's
// server_time_ms (stamped by the origin's feed as it encoded the frame) to
// the frame's publish on the edge's channel; the relay's own
// matchcast_frame_delay_ms then adds the write to each spectator. Across
// machines it needs their clocks in step (NTP); a frame stamped in the
// edge's future counts as 0 ms.
struct LagHistogram {
  static constexpr std::array<std::uint64_t, 12> kBucketsMs = {1, 2, 5, 10, 20, 50, 100, 200, 500, 1000, 2000, 5000};
  std::array<std::uint64_t, kBucketsMs.size() + 1> counts{};  // per bucket, the last one past 5000 ms
  std::uint64_t count = 0;
  std::uint64_t sum_ms = 0;
  std::uint64_t last_ms = 0;  // the latest frame's

  void record(std::uint64_t ms);
  void add(const LagHistogram& other);
};

struct EdgeSyncStats {
  std::uint64_t applied = 0;     // envelopes passed on to the channel
  std::uint64_t duplicates = 0;  // already applied (snapshot / live overlap)
  std::uint64_t gaps = 0;        // times a number was skipped
  std::uint64_t held_back = 0;   // deltas dropped while waiting for a keyframe
  std::uint64_t rejected = 0;    // malformed envelopes or payloads
  std::uint64_t resyncs = 0;     // snapshots applied
  LagHistogram lag;              // live frames only (a snapshot's keyframe is old by design)
};

class EdgeSync {
 public:
  using Clock = std::chrono::steady_clock;

  explicit EdgeSync(std::shared_ptr<relay::Channel> channel);

  // One message from <prefix>.<game>.live. While a resync is pending it is
  // buffered (bounded) and applied after the snapshot.
  void on_live(std::string_view bytes);
  // Starts a resync: live messages are buffered until on_snapshot(), or
  // until one arrives that continues exactly where the spectators are (the
  // reconnect lost nothing), which ends it at once.
  void begin_resync();
  // The game's latest snapshot from the keyframe stream (nullptr: none
  // stored yet), then the buffered live messages after it. Ignored when no
  // resync is pending any more.
  void on_snapshot(const std::string* bytes);

  // The NATS link dropped / came back (the caller then resyncs).
  void on_link_lost(const std::string& detail);
  void on_link_back(const std::string& detail);
  // Says "feed lost" when no live message came for `timeout`.
  void check_silence(Clock::time_point now, std::chrono::milliseconds timeout);

  bool has_hello() const;
  bool resync_pending() const;
  // Up to date: a hello, no resync pending, no keyframe awaited.
  bool in_sync() const;
  EdgeSyncStats stats() const;
  const std::shared_ptr<relay::Channel>& channel() const { return channel_; }

 private:
  // `e` is the next message after what the spectators have, with nothing missing.
  bool continues(const Envelope& e) const;
  void apply(const Envelope& e);
  void apply_hello(std::string_view hello);
  void publish_frame(std::string_view bytes, bool keyframe);
  void announce(bool lost, const std::string& detail);
  void reject(const std::string& why);

  std::shared_ptr<relay::Channel> channel_;
  mutable std::mutex mutex_;
  std::string hello_;              // the hello the channel has
  bool have_last_ = false;
  std::uint64_t last_ = 0;         // number of the last envelope applied
  bool waiting_key_ = true;        // deltas held back until a keyframe
  bool buffering_ = true;          // a resync is pending
  std::deque<std::string> pending_;
  bool lost_ = false;              // spectators were told "feed lost"
  bool silent_ = false;            // ... because the origin fell silent
  Clock::time_point last_live_ = Clock::now();
  std::uint32_t last_frame_seq_ = 0;
  EdgeSyncStats stats_;
};

}  // namespace mc::nats
