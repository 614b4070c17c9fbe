#include "server/nats/origin.hpp"

#include "server/nats/subjects.hpp"
#include "server/relay/log.hpp"

namespace mc::nats {

Origin::Origin(NatsConfig config, std::shared_ptr<relay::ChannelRegistry> channels)
    : config_(std::move(config)), channels_(std::move(channels)) {}

Origin::~Origin() { stop(); }

bool Origin::start(const std::vector<std::string>& games, std::string& error) {
  if (!valid_prefix(config_.subject_prefix)) {
    error = "NATS subject prefix '" + config_.subject_prefix + "' must be tokens of letters, digits, '_', '-' joined by '.'";
    return false;
  }
  for (const auto& g : games) {
    if (!valid_game(g)) {
      error = "channel '" + g + "' cannot be published on NATS: use letters, digits, '_' and '-' only";
      return false;
    }
    if (!channels_->find(g)) {
      error = "no channel '" + g + "' to publish";
      return false;
    }
  }
  NatsLink::Events events;
  events.connected = [this] {
    relay::log_event("nats_connected", "origin");
    std::lock_guard lock(mutex_);
    need_stream_ = true;
    wake_.notify_all();
  };
  events.disconnected = [] { relay::log_event("nats_disconnected", "origin: frames are dropped until it is back"); };
  link_ = NatsLink::open(config_, "matchcast-origin", std::move(events), false, error);
  if (!link_) return false;
  for (const auto& g : games) publishers_.push_back(OriginPublisher::start(*link_, config_.subject_prefix, channels_->find(g)));
  worker_ = std::thread([this] { run(); });
  return true;
}

void Origin::run() {
  std::unique_lock lock(mutex_);
  for (;;) {
    wake_.wait(lock, [this] { return stopping_ || need_stream_; });
    if (stopping_) return;
    lock.unlock();
    std::string error;
    const bool ok = link_->connected() &&
                    link_->ensure_last_per_subject_stream(stream_name(config_.subject_prefix),
                                                          key_wildcard(config_.subject_prefix),
                                                          config_.stream_replicas, error);
    if (ok) {
      for (auto& p : publishers_) p->republish_snapshot();
      relay::log_event("nats_stream_ready", stream_name(config_.subject_prefix));
    } else if (!error.empty() && failures_++ % 30 == 0) {
      relay::log_event("nats_stream_failed", error + " (is JetStream enabled? retrying; " +
                                                 std::to_string(failures_) + " so far)");
    }
    lock.lock();
    if (ok) need_stream_ = false;
    // Not ready (a cluster still electing its leader): try again shortly.
    else wake_.wait_for(lock, config_.reconnect_wait, [this] { return stopping_; });
  }
}

void Origin::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (worker_.joinable()) worker_.join();
  for (auto& p : publishers_) p->stop();
  publishers_.clear();
  link_.reset();
}

std::uint64_t Origin::published() const {
  std::uint64_t n = 0;
  for (const auto& p : publishers_) n += p->published();
  return n;
}

std::uint64_t Origin::dropped() const {
  std::uint64_t n = 0;
  for (const auto& p : publishers_) n += p->dropped();
  return n;
}

}  // namespace mc::nats
