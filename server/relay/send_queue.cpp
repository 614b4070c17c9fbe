#include "server/relay/send_queue.hpp"

#include <algorithm>
#include <iterator>

namespace mc::relay {

bool SendQueue::push(Message m) {
  if (skipping_) {
    if (m.droppable()) {
      ++dropped_;
      return false;
    }
    if (m.kind == Message::Kind::Keyframe) skipping_ = false;
  }
  if (m.droppable() && bytes_ + m.size() > max_bytes_) {
    // Behind: a delta chain is useless without every link, so drop the queued
    // ones and this one, and wait for the next keyframe to resync.
    drop_queued_deltas();
    ++dropped_;
    skipping_ = true;
    return false;
  }
  bytes_ += m.size();
  items_.push_back(std::move(m));
  return true;
}

void SendQueue::drop_queued_deltas() {
  // A keyframe still queued is followed by deltas that are now gone, so it is
  // dropped as well: the client resumes at the next keyframe, consistently.
  auto keep = [](const Message& m) { return m.kind == Message::Kind::Control || m.kind == Message::Kind::Session; };
  std::size_t kept_bytes = 0;
  std::size_t out = 0;
  for (auto& m : items_) {
    if (keep(m)) {
      kept_bytes += m.size();
      items_[out++] = std::move(m);
    } else {
      ++dropped_;
    }
  }
  items_.resize(out);
  bytes_ = kept_bytes;
}

void SendQueue::take_all(std::vector<Message>& batch) {
  // Moved, never swapped: `batch` is usually one buffer per I/O thread,
  // and a swap would give its room to this queue.
  batch.insert(batch.end(), std::make_move_iterator(items_.begin()), std::make_move_iterator(items_.end()));
  items_.clear();
  if (items_.capacity() > kKeptRoom) std::vector<Message>().swap(items_);
  bytes_ = 0;
}

}  // namespace mc::relay
