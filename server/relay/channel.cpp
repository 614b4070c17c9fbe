#include "server/relay/channel.hpp"

#include <algorithm>

namespace mc::relay {

void Channel::set_hello(std::string json) {
  Message m = Message::control(std::move(json));
  {
    std::lock_guard lock(mutex_);
    hello_ = m;
    // Frames coded against the old hello's skeleton are meaningless under the
    // new one: joiners wait for the next keyframe.
    gop_.clear();
  }
  broadcast(m);
}

void Channel::publish_frame(std::string bytes, bool keyframe) {
  Message m = Message::frame(std::move(bytes), keyframe);
  {
    std::lock_guard lock(mutex_);
    if (keyframe) gop_.clear();
    // Deltas with no keyframe before them cannot be decoded by a joiner.
    if (keyframe || !gop_.empty()) gop_.push_back(m);
  }
  ++frames_published_;
  broadcast(m);
}

void Channel::publish_control(std::string json) { broadcast(Message::control(std::move(json))); }

std::vector<Message> Channel::join(const std::shared_ptr<Subscriber>& s) {
  std::lock_guard lock(mutex_);
  std::vector<Message> first;
  first.reserve(gop_.size() + 1);
  if (hello_.bytes) first.push_back(hello_);
  first.insert(first.end(), gop_.begin(), gop_.end());
  subscribers_.push_back(s);
  return first;
}

void Channel::leave(const Subscriber* s) {
  std::lock_guard lock(mutex_);
  std::erase_if(subscribers_, [s](const std::weak_ptr<Subscriber>& w) {
    auto p = w.lock();
    return !p || p.get() == s;
  });
}

std::size_t Channel::subscribers() const {
  std::lock_guard lock(mutex_);
  return subscribers_.size();
}

const char* feed_state_name(FeedState s) {
  switch (s) {
    case FeedState::Starting: return "starting";
    case FeedState::Live: return "live";
    case FeedState::Lost: return "lost";
    case FeedState::Ended: return "ended";
  }
  return "unknown";
}

void Channel::shutdown_subscribers() {
  std::vector<std::shared_ptr<Subscriber>> targets;
  {
    std::lock_guard lock(mutex_);
    for (auto& w : subscribers_)
      if (auto p = w.lock()) targets.push_back(std::move(p));
  }
  for (auto& t : targets) t->shutdown();
}

void Channel::broadcast(const Message& m) {
  // Copy the live subscribers under the lock, deliver outside it, so a slow
  // deliver never blocks joins or the next publish's bookkeeping.
  std::vector<std::shared_ptr<Subscriber>> targets;
  {
    std::lock_guard lock(mutex_);
    targets.reserve(subscribers_.size());
    for (auto& w : subscribers_)
      if (auto p = w.lock()) targets.push_back(std::move(p));
  }
  for (auto& t : targets) t->deliver(m);
}

}  // namespace mc::relay
