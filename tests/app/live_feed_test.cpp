// Live mode without rcssserver: the feeder plays a real log as a monitor
// port, the server's feed reads it over UDP on loopback, and spectators see
// the game, then a "feed lost" when the feeder stops.
#include <gtest/gtest.h>

#include <chrono>
#include <mutex>
#include <thread>

#include "proto/control_messages.hpp"
#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"
#include "server/app/log_feed.hpp"
#include "server/tools/feeder/feeder.hpp"
#include "tests/relay/channel_collector.hpp"

namespace mc::app {
namespace {

using Collector = relay::testing::ChannelCollector;

TEST(LiveFeed, BroadcastsAMonitorFeedAndTellsSpectatorsWhenItIsLost) {
  feeder::FeederConfig fc;
  fc.log_path = std::string(MATCHCAST_SOURCE_DIR) + "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";
  fc.port = 0;
  fc.speed = 4;
  feeder::Feeder server(fc);
  std::string error;
  ASSERT_TRUE(server.open(error)) << error;
  std::thread serving([&] {
    std::string e;
    server.run(e);
  });

  auto channel = std::make_shared<relay::Channel>("live");
  FeedConfig config;
  config.log_path = "udp://127.0.0.1:" + std::to_string(server.port());
  LogFeed feed(config, channel);
  const bool started = feed.start(error);
  if (!started) {
    server.stop();
    serving.join();
    FAIL() << error;
  }
  auto collector = std::make_shared<Collector>();
  auto first = channel->join(collector);
  proto::Hello hello;
  ASSERT_TRUE(proto::hello_from_json(*first.at(0).bytes, hello, error)) << error;
  EXPECT_EQ(hello.left.name, "HELIOS_A");
  EXPECT_EQ(hello.right.name, "HELIOS_B");
  // The game by its teams, not by the rcssserver's address.
  EXPECT_EQ(hello.match_id, "HELIOS_A-vs-HELIOS_B");

  // Two seconds of the live game, then the feeder goes away.
  std::this_thread::sleep_for(std::chrono::seconds(2));
  server.stop();
  serving.join();
  bool lost = false;
  for (int i = 0; i < 120 && !lost; ++i) {
    std::this_thread::sleep_for(std::chrono::milliseconds(100));
    for (const auto& m : collector->snapshot()) {
      proto::ControlMessage c;
      if (!m.binary() && proto::control_from_json(*m.bytes, c, error))
        if (auto* f = std::get_if<proto::FeedStatus>(&c)) {
          lost = lost || f->lost;
          EXPECT_EQ(f->detail.find("127.0.0.1"), std::string::npos) << f->detail;
        }
    }
  }
  feed.stop();
  EXPECT_TRUE(lost) << "no feed-lost message within 12 s of the feeder stopping";
  EXPECT_EQ(channel->feed_state(), relay::FeedState::Ended);

  auto decoder = std::make_unique<proto::FrameDecoder>(hello.skeleton);
  int frames = 0;
  std::vector<relay::Message> all(first.begin() + 1, first.end());
  for (auto& m : collector->snapshot()) all.push_back(m);
  PoseFrame f;
  for (const auto& m : all) {
    if (!m.binary()) continue;
    ASSERT_TRUE(decoder->decode(*m.bytes, f, error)) << error;
    ++frames;
  }
  // 2 s at 4x = ~80 states = ~160 frames; allow for a loaded machine.
  EXPECT_GE(frames, 40);
}

}  // namespace
}  // namespace mc::app
