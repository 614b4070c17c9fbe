// The whole pipeline in-process: a real log through ingest, anim and the
// codec into a channel; a subscriber decodes what a spectator would get.
#include "server/app/log_feed.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <mutex>
#include <thread>

#include "anim/human_skeleton.hpp"
#include "proto/control_messages.hpp"
#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"
#include "tests/relay/channel_collector.hpp"

namespace mc::app {
namespace {

const std::string kLog = std::string(MATCHCAST_SOURCE_DIR) +
                         "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";

using Collector = relay::testing::ChannelCollector;

TEST(LogFeed, PublishesDecodableContinuousFramesOfTheRealGame) {
  auto channel = std::make_shared<relay::Channel>("test");
  FeedConfig config;
  config.log_path = kLog;
  config.speed = 20;  // 400 frames per second
  LogFeed feed(config, channel);
  std::string error;
  ASSERT_TRUE(feed.start(error)) << error;
  auto collector = std::make_shared<Collector>();
  auto first = channel->join(collector);
  ASSERT_FALSE(first.empty());
  for (int i = 0; i < 300 && collector->count() < 200; ++i)
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  feed.stop();

  proto::Hello hello;
  ASSERT_TRUE(proto::hello_from_json(*first[0].bytes, hello, error)) << error;
  EXPECT_EQ(hello.left.name, "HELIOS_A");
  EXPECT_EQ(hello.right.name, "HELIOS_B");
  EXPECT_EQ(hello.skeleton.joints.size(), anim::human_skeleton().joints.size());

  std::vector<relay::Message> frames(first.begin() + 1, first.end());
  {
    std::lock_guard lock(collector->mutex);
    frames.insert(frames.end(), collector->messages.begin(), collector->messages.end());
  }
  ASSERT_GE(frames.size(), 200u);
  auto decoder_ptr = std::make_unique<proto::FrameDecoder>(hello.skeleton);  // large: not on the stack
  auto& decoder = *decoder_ptr;
  PoseFrame f, start;
  std::uint32_t last_seq = 0;
  bool have = false;
  int kicks = 0;
  std::vector<proto::StaminaUpdate> stamina;
  for (const auto& m : frames) {
    if (!m.binary()) {
      // Events travel between frames and name a frame at or after the last one.
      proto::ControlMessage c;
      ASSERT_TRUE(proto::control_from_json(*m.bytes, c, error)) << error << ": " << *m.bytes;
      if (auto* k = std::get_if<proto::KickEvent>(&c)) {
        ++kicks;
        EXPECT_GE(k->seq, have ? last_seq + 1 : 0u);
        EXPECT_GE(k->unum, 1);
        EXPECT_LE(k->unum, 11);
      }
      if (auto* s = std::get_if<proto::StaminaUpdate>(&c)) stamina.push_back(*s);
      continue;
    }
    ASSERT_TRUE(decoder.decode(*m.bytes, f, error)) << error;
    if (have) {
      ASSERT_EQ(f.seq, last_seq + 1) << "gap in the stream";
    }
    if (!have) start = f;
    last_seq = f.seq;
    have = true;
    EXPECT_GT(f.server_time_ms, 0u);
  }
  // Ten seconds of play: some players must have moved.
  int moved = 0;
  for (int i = 0; i < kMaxPlayers; ++i)
    if (std::hypot(f.players[i].x - start.players[i].x, f.players[i].y - start.players[i].y) > 0.5)
      ++moved;
  EXPECT_GE(moved, 5);
  EXPECT_GE(kicks, 1) << "ten seconds of a real game without a kick event";
  // Stamina once a second (200 frames = 10 s), every player's in
  // [0, stamina_max], and it is not a constant: running players tire.
  ASSERT_GE(stamina.size(), 8u);
  EXPECT_LE(stamina.size(), 12u);
  const double stamina_max = hello.server_params.at("stamina_max");
  bool varies = false;
  for (std::size_t i = 0; i < stamina.size(); ++i) {
    if (i > 0) {  // sent with the first frame at its cycle: a frame or two either way
      EXPECT_NEAR(static_cast<double>(stamina[i].seq - stamina[i - 1].seq), 20.0, 6.0);
    }
    for (const auto* team : {&stamina[i].left, &stamina[i].right})
      for (int v : *team) {
        EXPECT_GE(v, 0);
        EXPECT_LE(v, stamina_max);
        varies = varies || v != stamina[0].left[0];
      }
  }
  EXPECT_TRUE(varies);
  EXPECT_NEAR(static_cast<double>(stamina.back().seq - stamina.front().seq) / static_cast<double>(stamina.size() - 1),
              20.0, 2.0);
}

TEST(LogFeed, RefusesAMissingOrEmptyLogWithAClearError) {
  auto channel = std::make_shared<relay::Channel>("test");
  FeedConfig config;
  config.log_path = "/nonexistent/game.rcg";
  LogFeed feed(config, channel);
  std::string error;
  EXPECT_FALSE(feed.start(error));
  EXPECT_NE(error.find("/nonexistent/game.rcg"), std::string::npos) << error;

  config.log_path = std::string(MATCHCAST_TEST_RCG_DIR) + "/real/20190926071807-HELIOS_base_0-vs-null.rcg";
  LogFeed empty(config, channel);
  EXPECT_FALSE(empty.start(error));
  EXPECT_NE(error.find("no game states"), std::string::npos) << error;
}

}  // namespace
}  // namespace mc::app
