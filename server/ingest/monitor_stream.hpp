// Turns the datagrams of one monitor session, in arrival order, into the
// state stream: decodes each (MonitorDecoder), stamps index/stoppage, counts
// and names bad datagrams by their number, and queues messages and server
// replies as events. Shared by the live UDP client and the capture replayer,
// so both paths give identical states for identical datagrams.
#pragma once

#include <string_view>

#include "server/ingest/event_queue.hpp"
#include "server/ingest/monitor_decoder.hpp"
#include "server/ingest/show_sequencer.hpp"

namespace mc::ingest {

class MonitorStream {
 public:
  // Feeds the next datagram. True when it was a show, now in `out` with
  // index and stoppage stamped; false otherwise (params, message, reply, or
  // a bad datagram counted in stats() as "datagram N: why").
  bool push(std::string_view datagram, WorldState& out);
  // Counts a datagram refused unread (larger than the receive buffer).
  void refuse_oversized(std::size_t size);
  // Queues a feed event (lost/back) before the next state.
  void push_event(SourceEvent::Kind kind, std::string detail);
  bool poll_event(SourceEvent& out) { return events_.pop(out); }

  const GameParams& params() const { return decoder_.context().params; }
  const IngestStats& stats() const { return stats_; }
  IngestStats& stats() { return stats_; }
  std::uint64_t datagrams() const { return datagrams_; }

 private:
  void queue_message(SourceEvent::Kind kind);

  MonitorDecoder decoder_;
  ShowSequencer seq_;
  EventQueue events_;
  IngestStats stats_;
  std::uint64_t datagrams_ = 0;
  std::string error_;
  MessageRecord msg_;
  WorldState scratch_;
};

}  // namespace mc::ingest
