// Every open WebSocket session of one relay, whatever it follows (a live
// channel, a private replay, a time shift), so that a graceful stop reaches
// them all. Touched on connect and disconnect only, never per frame.
//
// An intrusive list: each session carries its Hook, so joining the set
// allocates nothing (a hash map cost a node and a bucket per spectator,
// ~56 bytes).
#pragma once

#include <memory>
#include <mutex>
#include <vector>

namespace mc::relay {

class WebSocketSession;

class SessionSet {
 public:
  class Hook {
   public:
    explicit Hook(WebSocketSession* owner) : owner_(owner) {}
    Hook(const Hook&) = delete;
    Hook& operator=(const Hook&) = delete;

   private:
    friend class SessionSet;
    WebSocketSession* owner_;
    Hook* prev_ = nullptr;
    Hook* next_ = nullptr;  // nullptr: not in a set
  };

  SessionSet() { head_.prev_ = head_.next_ = &head_; }
  SessionSet(const SessionSet&) = delete;
  SessionSet& operator=(const SessionSet&) = delete;

  void add(Hook& h) {
    std::lock_guard lock(mutex_);
    if (h.next_) return;
    h.prev_ = head_.prev_;
    h.next_ = &head_;
    head_.prev_->next_ = &h;
    head_.prev_ = &h;
  }
  // From the session's destructor: a snapshot taken meanwhile skips it.
  void remove(Hook& h) {
    std::lock_guard lock(mutex_);
    if (!h.next_) return;
    h.prev_->next_ = h.next_;
    h.next_->prev_ = h.prev_;
    h.prev_ = h.next_ = nullptr;
  }
  // The sessions still alive.
  std::vector<std::shared_ptr<WebSocketSession>> snapshot() const;

 private:
  mutable std::mutex mutex_;
  Hook head_{nullptr};
};

}  // namespace mc::relay
