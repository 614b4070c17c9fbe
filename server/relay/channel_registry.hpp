// The channels one relay serves, by name: one per live feed or recording.
// Thread-safe; channels are shared_ptrs so a session keeps its channel alive
// even if the registry drops it.
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

#include "server/relay/channel.hpp"

namespace mc::relay {

// Where channels come from when nothing local opened them: a NATS edge,
// which subscribes to a game when a spectator asks for it. Its calls must
// not block (they run on I/O threads).
class ChannelProvider {
 public:
  virtual ~ChannelProvider() = default;
  // A channel for `name`, opened now, or nullptr when the provider will not
  // carry it (not a game name, at its limit).
  virtual std::shared_ptr<Channel> request(const std::string& name) = 0;
  // Prometheus text appended to /metrics: the provider's own counters.
  virtual std::string metrics() const = 0;
};

class ChannelRegistry {
 public:
  // The channel with this name, created when absent.
  std::shared_ptr<Channel> open(const std::string& name);
  // The channel with this name, or nullptr.
  std::shared_ptr<Channel> find(const std::string& name) const;
  // The first channel opened (what "/ws" with no channel name shows).
  std::shared_ptr<Channel> default_channel() const;
  void remove(const std::string& name);
  std::vector<std::shared_ptr<Channel>> all() const;

  // The channel with this name, or the provider's (which may open it), or
  // nullptr.
  std::shared_ptr<Channel> find_or_request(const std::string& name);
  // Sets or (nullptr) clears the provider. Once cleared, no call to the old
  // one is running or will run, so it may be destroyed.
  void set_provider(ChannelProvider* provider);
  // The provider's /metrics text, or "".
  std::string provider_metrics() const;

 private:
  mutable std::mutex mutex_;
  mutable std::mutex provider_mutex_;  // held during provider calls; never with mutex_
  ChannelProvider* provider_ = nullptr;
  std::map<std::string, std::shared_ptr<Channel>> channels_;
  std::string first_;
};

}  // namespace mc::relay
