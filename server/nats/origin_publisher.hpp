// The origin side: taps one local channel like a spectator does and puts
// each of its messages on NATS once, in an envelope (envelope.hpp), on
// <prefix>.<game>.live. Each hello and each keyframe also replaces the
// game's snapshot on <prefix>.<game>.key, which the JetStream stream keeps
// for edges that join or come back. The hello is also repeated on the live
// subject every 10 keyframes, for edges without the stream.
//
// While the NATS link is down, messages are dropped and counted, not
// buffered: spectators want the present, and the numbers tell the edges
// they must wait for the next keyframe.
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <mutex>
#include <string>

#include "server/nats/nats_link.hpp"
#include "server/relay/channel.hpp"

namespace mc::nats {

class OriginPublisher : public relay::Subscriber, public std::enable_shared_from_this<OriginPublisher> {
 public:
  // Joins `channel` and publishes from then on; its current hello and
  // keyframe group go out first. `link` must outlive the publisher.
  static std::shared_ptr<OriginPublisher> start(NatsLink& link, const std::string& prefix,
                                                std::shared_ptr<relay::Channel> channel);
  ~OriginPublisher() override;

  void deliver(const relay::Message& m) override;
  // Publishes the snapshot again (the keyframe stream was recreated after
  // the NATS servers restarted with no store).
  void republish_snapshot();
  void stop();

  std::uint64_t published() const { return published_.load(); }
  std::uint64_t dropped() const { return dropped_.load(); }

 private:
  OriginPublisher(NatsLink& link, const std::string& prefix, std::shared_ptr<relay::Channel> channel);
  void send(const relay::Message& m);
  void put(const std::string& subject, const std::string& bytes);

  NatsLink& link_;
  std::shared_ptr<relay::Channel> channel_;
  const std::string live_subject_;
  const std::string key_subject_;
  std::mutex mutex_;
  bool stopped_ = false;
  std::uint64_t number_ = 0;
  std::string hello_;
  static constexpr int kHelloEveryKeyframes = 10;
  int keyframes_since_hello_ = 0;
  std::string snapshot_;  // the last snapshot sent
  std::atomic<std::uint64_t> published_{0}, dropped_{0};
};

}  // namespace mc::nats
