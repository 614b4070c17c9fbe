// The feeds a server runs, one per channel, and the control actions an
// operator may take on them (POST /control/feed/stop?channel=NAME, ...).
#pragma once

#include <map>
#include <memory>
#include <mutex>
#include <string>

#include "server/app/log_feed.hpp"
#include "server/relay/channel_registry.hpp"
#include "server/relay/control_handler.hpp"

namespace mc::app {

class FeedControl : public relay::ControlHandler {
 public:
  explicit FeedControl(std::shared_ptr<relay::ChannelRegistry> channels)
      : channels_(std::move(channels)) {}
  ~FeedControl() override { stop_all(); }

  // Opens `channel` and starts broadcasting `config` on it. False + error
  // when the log cannot be read.
  bool add(const std::string& channel, const FeedConfig& config, std::string& error);
  void stop_all();

  // Actions: "feed/stop", "feed/start" (restarts a stopped feed).
  bool control(const std::string& action, const std::string& channel,
               std::string& message) override;

 private:
  struct Entry {
    FeedConfig config;
    std::unique_ptr<LogFeed> feed;
  };
  std::shared_ptr<relay::ChannelRegistry> channels_;
  std::mutex mutex_;
  std::map<std::string, Entry> feeds_;
};

}  // namespace mc::app
