// A spectator for in-process tests: keeps every message a relay::Channel
// delivers to it, in order, safe to read from the test's thread.
#pragma once

#include <cstddef>
#include <mutex>
#include <vector>

#include "server/relay/channel.hpp"

namespace mc::relay::testing {

struct ChannelCollector : Subscriber {
  std::mutex mutex;
  std::vector<Message> messages;
  void deliver(const Message& m) override {
    std::lock_guard lock(mutex);
    messages.push_back(m);
  }
  std::size_t count() {
    std::lock_guard lock(mutex);
    return messages.size();
  }
  std::vector<Message> snapshot() {
    std::lock_guard lock(mutex);
    return messages;
  }
};

}  // namespace mc::relay::testing
