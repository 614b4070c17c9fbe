// The bounded FIFO behind StateSource::poll_event(). A consumer that never
// drains events must not make a long game grow memory without bound.
#pragma once

#include <deque>

#include "server/ingest/state_source.hpp"

namespace mc::ingest {

class EventQueue {
 public:
  // Appends `ev`; when full, drops the oldest event and counts a skip.
  void push(SourceEvent ev, IngestStats& stats) {
    if (q_.size() >= StateSource::kMaxPendingEvents) {
      q_.pop_front();
      record_skip(stats, "event queue full: oldest event dropped");
    }
    q_.push_back(std::move(ev));
  }
  bool pop(SourceEvent& out) {
    if (q_.empty()) return false;
    out = std::move(q_.front());
    q_.pop_front();
    return true;
  }
  bool empty() const { return q_.empty(); }

 private:
  std::deque<SourceEvent> q_;
};

}  // namespace mc::ingest
