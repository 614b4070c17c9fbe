// The reach overlay through the app's feed: the bundled game with a reach
// model sends "reach_map" messages at 2.5 Hz of game time, each before the
// frame of its cycle; without a model it sends none.
#include "server/app/log_feed.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <thread>

#include "proto/control_messages.hpp"
#include "proto/frame_header.hpp"
#include "tests/mocap/synthetic_reach.hpp"
#include "tests/relay/channel_collector.hpp"

namespace mc::app {
namespace {

const std::string kLog = std::string(MATCHCAST_SOURCE_DIR) + "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";

using Collector = relay::testing::ChannelCollector;

// Runs the feed until `frames` frames arrived; returns what a spectator got.
std::vector<relay::Message> run(std::shared_ptr<const anim::mocap::ReachModel> reach, std::size_t frames) {
  auto channel = std::make_shared<relay::Channel>("reach");
  FeedConfig config;
  config.log_path = kLog;
  config.speed = 20;
  config.reach_model = std::move(reach);
  LogFeed feed(config, channel);
  std::string error;
  EXPECT_TRUE(feed.start(error)) << error;
  auto collector = std::make_shared<Collector>();
  auto first = channel->join(collector);
  for (int i = 0; i < 500 && collector->count() < frames; ++i) std::this_thread::sleep_for(std::chrono::milliseconds(10));
  feed.stop();
  std::lock_guard lock(collector->mutex);
  return collector->messages;
}

}  // namespace

TEST(ReachFeed, SendsReachMapsBeforeTheirFrames) {
  const auto messages = run(anim::mocap::test::straight_walker_reach_model(), 300);
  int maps = 0;
  int last_time = -1;
  std::uint32_t last_frame_seq = 0;
  bool any_frame = false;
  for (const auto& m : messages) {
    if (m.binary()) {
      proto::FrameHeader h;
      std::string error;
      if (proto::peek_header(*m.bytes, h, error)) { last_frame_seq = h.seq; any_frame = true; }
      continue;
    }
    proto::ControlMessage c;
    std::string error;
    if (!proto::control_from_json(*m.bytes, c, error)) continue;
    const auto* r = std::get_if<proto::ReachMapUpdate>(&c);
    if (!r) continue;
    ++maps;
    EXPECT_EQ(r->cells.size(), static_cast<std::size_t>(r->width * r->height));
    EXPECT_NE(r->cells.find('l'), std::string::npos);
    EXPECT_NE(r->cells.find('r'), std::string::npos);
    if (any_frame) {
      EXPECT_EQ(r->seq, last_frame_seq + 1);  // names the frame that follows it
    }
    if (last_time >= 0) {
      EXPECT_GE(r->time, last_time);
    }
    last_time = r->time;
  }
  // 300 messages ~ 280 frames ~ 140 states: about 35 maps at one per 4 states.
  EXPECT_GE(maps, 15);
  EXPECT_LE(maps, 80);
}

TEST(ReachFeed, NoModelNoReachMaps) {
  for (const auto& m : run(nullptr, 150)) {
    if (m.binary()) continue;
    std::string error;
    EXPECT_NE(proto::control_type(*m.bytes, error), "reach_map");
  }
}

}  // namespace mc::app
