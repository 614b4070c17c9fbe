// The bounded outbound queue of one spectator, and its skip-ahead policy.
// Pure logic, no sockets, so the policy is tested on its own.
//
// Policy: while the queued bytes stay under the bound, everything queues.
// Past it, every queued delta frame is dropped and deltas keep being dropped
// until the next keyframe, from which the client resyncs. Control messages
// (hello, events, metadata) are never dropped.
#pragma once

#include <cstddef>
#include <vector>

#include "server/relay/message.hpp"

namespace mc::relay {

class SendQueue {
 public:
  explicit SendQueue(std::size_t max_bytes) : max_bytes_(max_bytes) {}

  // Queues `m`, applying the skip policy. Returns false when `m` was dropped.
  bool push(Message m);
  // Moves every queued message to the end of `batch` (the next write),
  // oldest first. The queue keeps at most kKeptRoom slots of room: a
  // join's catch-up (hello, metadata, a keyframe and its deltas: 20 and
  // more messages) would otherwise leave every spectator holding room for
  // all of them, ~1.4 KB, for its whole life.
  void take_all(std::vector<Message>& batch);
  // Room kept between writes: a frame, or a frame and a control message,
  // is what one write usually carries (more just allocates for that write).
  static constexpr std::size_t kKeptRoom = 2;

  bool empty() const { return items_.empty(); }
  std::size_t bytes() const { return bytes_; }
  std::size_t size() const { return items_.size(); }
  // Slots allocated (what an idle spectator's queue costs).
  std::size_t room() const { return items_.capacity(); }
  // Frames dropped so far by the skip policy.
  std::size_t dropped() const { return dropped_; }
  // True between an overflow and the keyframe that ends it.
  bool skipping() const { return skipping_; }

 private:
  void drop_queued_deltas();

  std::size_t max_bytes_;
  // A vector, not a deque: libstdc++'s deque allocates ~600 bytes before
  // its first element, for every spectator; this queue is empty nearly always.
  std::vector<Message> items_;
  std::size_t bytes_ = 0;
  std::size_t dropped_ = 0;
  bool skipping_ = false;
};

}  // namespace mc::relay
