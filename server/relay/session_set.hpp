// Every open WebSocket session of one relay, whatever it follows (a live
// channel, a private replay, a time shift), so that a graceful stop reaches
// them all. Touched on connect and disconnect only, never per frame.
#pragma once

#include <memory>
#include <mutex>
#include <unordered_map>
#include <vector>

namespace mc::relay {

class WebSocketSession;

class SessionSet {
 public:
  void add(const std::shared_ptr<WebSocketSession>& s) {
    std::lock_guard lock(mutex_);
    sessions_[s.get()] = s;
  }
  void remove(const WebSocketSession* s) {
    std::lock_guard lock(mutex_);
    sessions_.erase(s);
  }
  std::vector<std::shared_ptr<WebSocketSession>> snapshot() const {
    std::lock_guard lock(mutex_);
    std::vector<std::shared_ptr<WebSocketSession>> out;
    out.reserve(sessions_.size());
    for (const auto& [_, w] : sessions_)
      if (auto p = w.lock()) out.push_back(std::move(p));
    return out;
  }

 private:
  mutable std::mutex mutex_;
  std::unordered_map<const WebSocketSession*, std::weak_ptr<WebSocketSession>> sessions_;
};

}  // namespace mc::relay
