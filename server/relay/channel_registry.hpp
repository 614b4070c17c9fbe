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

 private:
  mutable std::mutex mutex_;
  std::map<std::string, std::shared_ptr<Channel>> channels_;
  std::string first_;
};

}  // namespace mc::relay
