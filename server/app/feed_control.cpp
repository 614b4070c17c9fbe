#include "server/app/feed_control.hpp"

#include "server/relay/log.hpp"

namespace mc::app {

bool FeedControl::add(const std::string& channel, const FeedConfig& config, std::string& error) {
  auto feed = std::make_unique<LogFeed>(config, channels_->open(channel));
  if (!feed->start(error)) {
    channels_->remove(channel);
    return false;
  }
  std::lock_guard lock(mutex_);
  feeds_[channel] = Entry{config, std::move(feed)};
  return true;
}

void FeedControl::stop_all() {
  std::lock_guard lock(mutex_);
  for (auto& [name, e] : feeds_)
    if (e.feed) e.feed->stop();
}

bool FeedControl::control(const std::string& action, const std::string& channel,
                          std::string& message) {
  std::lock_guard lock(mutex_);
  auto it = feeds_.find(channel);
  if (it == feeds_.end()) {
    message = "no feed on channel '" + channel + "'";
    return false;
  }
  Entry& e = it->second;
  if (action == "feed/stop") {
    if (e.feed) e.feed->stop();
    e.feed.reset();
    message = "feed on '" + channel + "' stopped";
    return true;
  }
  if (action == "feed/start") {
    if (e.feed) {
      message = "feed on '" + channel + "' is already running";
      return true;
    }
    auto feed = std::make_unique<LogFeed>(e.config, channels_->open(channel));
    std::string error;
    if (!feed->start(error)) {
      // The error names the log's path: the operator finds it in the log.
      relay::log_event("feed_start_failed", channel + ": " + error);
      message = "feed on '" + channel + "' could not start (see the server log)";
      return false;
    }
    e.feed = std::move(feed);
    message = "feed on '" + channel + "' started";
    return true;
  }
  message = "unknown action '" + action + "' (feed/stop, feed/start)";
  return false;
}

}  // namespace mc::app
