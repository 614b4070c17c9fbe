#include "server/relay/session_set.hpp"

#include "server/relay/websocket_session.hpp"

namespace mc::relay {

std::vector<std::shared_ptr<WebSocketSession>> SessionSet::snapshot() const {
  std::lock_guard lock(mutex_);
  std::vector<std::shared_ptr<WebSocketSession>> out;
  for (const Hook* h = head_.next_; h != &head_; h = h->next_) {
    // A session whose last owner is gone is in its destructor, waiting for
    // the lock to leave: its memory is still there, and lock() gives nullptr.
    if (auto p = h->owner_->weak_from_this().lock()) out.push_back(std::move(p));
  }
  return out;
}

}  // namespace mc::relay
