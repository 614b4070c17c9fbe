// The origin role: publishes every local feed's channel on NATS
// (OriginPublisher per game) and keeps the keyframe stream in place. After
// each (re)connection it makes sure the stream exists (the NATS servers may
// have restarted without their store) and puts the current snapshots back.
#pragma once

#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "server/nats/nats_config.hpp"
#include "server/nats/nats_link.hpp"
#include "server/nats/origin_publisher.hpp"
#include "server/relay/channel_registry.hpp"

namespace mc::nats {

class Origin {
 public:
  Origin(NatsConfig config, std::shared_ptr<relay::ChannelRegistry> channels);
  ~Origin();

  // Publishes the channels named `games` (which must exist). False + error
  // on a name that cannot be a subject token or bad NATS options; a NATS
  // server that is not up yet is not an error (the client keeps trying).
  bool start(const std::vector<std::string>& games, std::string& error);
  void stop();

  bool connected() const { return link_ && link_->connected(); }
  std::uint64_t published() const;
  std::uint64_t dropped() const;

 private:
  void run();

  NatsConfig config_;
  std::shared_ptr<relay::ChannelRegistry> channels_;
  std::unique_ptr<NatsLink> link_;
  std::vector<std::shared_ptr<OriginPublisher>> publishers_;
  std::thread worker_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  bool need_stream_ = false;
  std::uint64_t failures_ = 0;  // worker thread only
};

}  // namespace mc::nats
