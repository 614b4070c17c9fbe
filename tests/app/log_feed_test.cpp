// The whole pipeline in-process: a real log through ingest, anim and the
// codec into a channel; a subscriber decodes what a spectator would get.
#include "server/app/log_feed.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <mutex>
#include <optional>
#include <thread>

#include "anim/human_skeleton.hpp"
#include "proto/control_messages.hpp"
#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"
#include "server/relay/relay_server.hpp"
#include "tests/relay/channel_collector.hpp"
#include "tests/relay/ws_test_client.hpp"

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
    if (i > 0) {  // every 10th state's first frame: exactly 20 frames apart
      EXPECT_EQ(stamina[i].seq - stamina[i - 1].seq, 20u);
    }
    for (const auto* team : {&stamina[i].left, &stamina[i].right})
      for (int v : *team) {
        EXPECT_GE(v, 0);
        EXPECT_LE(v, stamina_max);
        varies = varies || v != stamina[0].left[0];
      }
  }
  EXPECT_TRUE(varies);
}

// Proto SPEC section 5.3 on the real game, through a real relay on
// loopback: teams and score before the first frame, a score message right
// after each goal event, stamina exactly every 20 frames (stoppages
// included), and a spectator who joins after a goal gets the current teams
// and score right after the hello.
TEST(LogFeed, MetadataFollowsTheSpecAndReachesALateJoiner) {
  auto channels = std::make_shared<relay::ChannelRegistry>();
  auto channel = channels->open("live");
  relay::RelayConfig relay_config;
  relay_config.port = 0;
  relay_config.threads = 1;
  relay::RelayServer server(relay_config, channels);
  std::string error;
  ASSERT_TRUE(server.start(error)) << error;

  // Joined before the feed starts: it sees every message, the hello first.
  auto collector = std::make_shared<Collector>();
  EXPECT_TRUE(channel->join(collector).empty());
  FeedConfig config;
  config.log_path = kLog;
  config.speed = 1000;  // as fast as the pipeline goes
  config.loop = false;
  LogFeed feed(config, channel);
  ASSERT_TRUE(feed.start(error)) << error;

  // The last score message seen so far, and how many messages were read.
  std::size_t scanned = 0;
  std::optional<proto::ScoreUpdate> score;
  const auto wait_for_score = [&](int left, int right) {
    for (int i = 0; i < 3000; ++i) {
      const auto messages = collector->snapshot();
      for (; scanned < messages.size(); ++scanned) {
        proto::ControlMessage c;
        if (messages[scanned].binary() || !proto::control_from_json(*messages[scanned].bytes, c, error)) continue;
        if (const auto* s = std::get_if<proto::ScoreUpdate>(&c)) score = *s;
      }
      if (score && score->left == left && score->right == right) return true;
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    return false;
  };
  // HELIOS_B scores at cycle 720, HELIOS_A at 857.
  ASSERT_TRUE(wait_for_score(0, 1)) << "no 0-1 score message within 30 s";
  {
    relay::testing::WsTestClient late(server.port());
    const auto hello = late.read();
    ASSERT_FALSE(hello.binary);
    EXPECT_EQ(proto::control_type(hello.data, error), "hello");
    proto::ControlMessage teams, current;
    const auto first = late.read();
    ASSERT_FALSE(first.binary);
    ASSERT_TRUE(proto::control_from_json(first.data, teams, error)) << error;
    ASSERT_TRUE(std::holds_alternative<proto::TeamsUpdate>(teams)) << first.data;
    EXPECT_EQ(std::get<proto::TeamsUpdate>(teams).left.name, "HELIOS_A");
    EXPECT_EQ(std::get<proto::TeamsUpdate>(teams).right.name, "HELIOS_B");
    const auto second = late.read();
    ASSERT_FALSE(second.binary);
    ASSERT_TRUE(proto::control_from_json(second.data, current, error)) << error;
    ASSERT_TRUE(std::holds_alternative<proto::ScoreUpdate>(current)) << second.data;
    // The score of the game when it joined: 0-1 (1-1 only if the feed got that far meanwhile).
    EXPECT_EQ(std::get<proto::ScoreUpdate>(current).right, 1);
    EXPECT_LE(std::get<proto::ScoreUpdate>(current).left, 1);
    EXPECT_TRUE(late.read().binary) << "the keyframe follows the metadata";
  }
  ASSERT_TRUE(wait_for_score(1, 1)) << "no 1-1 score message within 30 s";
  feed.stop();
  server.stop();

  // The whole stream as the first spectator got it.
  const auto messages = collector->snapshot();
  ASSERT_FALSE(messages.empty());
  ASSERT_EQ(proto::control_type(*messages[0].bytes, error), "hello");
  auto decoder = std::make_unique<proto::FrameDecoder>(anim::human_skeleton());
  std::vector<proto::ControlMessage> pending;  // control messages since the last frame
  std::vector<std::uint32_t> stamina_seqs;
  int goals = 0, scores = 0, frames = 0, stoppage_frames = 0;
  std::optional<proto::GoalEvent> goal;  // a goal event not yet followed by its score message
  PoseFrame f;
  for (std::size_t i = 1; i < messages.size(); ++i) {
    const auto& m = messages[i];
    if (!m.binary()) {
      proto::ControlMessage c;
      ASSERT_TRUE(proto::control_from_json(*m.bytes, c, error)) << error << ": " << *m.bytes;
      if (goal) {  // the message right after a goal is its score
        const auto* s = std::get_if<proto::ScoreUpdate>(&c);
        ASSERT_NE(s, nullptr) << "after a goal came " << *m.bytes;
        EXPECT_EQ(s->seq, goal->seq);
        EXPECT_EQ(s->left, goal->score_left);
        EXPECT_EQ(s->right, goal->score_right);
        goal.reset();
      }
      if (const auto* g = std::get_if<proto::GoalEvent>(&c)) goal = *g, ++goals;
      pending.push_back(c);
      continue;
    }
    ASSERT_FALSE(goal) << "a goal event without its score message before the frame";
    ASSERT_TRUE(decoder->decode(*m.bytes, f, error)) << error;
    if (frames == 0) {
      // The first frame comes after teams, score and stamina, in that order.
      ASSERT_GE(pending.size(), 3u);
      EXPECT_TRUE(std::holds_alternative<proto::TeamsUpdate>(pending[0]));
      EXPECT_TRUE(std::holds_alternative<proto::ScoreUpdate>(pending[1]));
      EXPECT_TRUE(std::holds_alternative<proto::StaminaUpdate>(pending[2]));
    }
    for (const auto& c : pending) {
      const std::uint32_t seq = std::visit([](const auto& x) { return x.seq; }, c);
      if (const auto* s = std::get_if<proto::ScoreUpdate>(&c)) {
        ++scores;
        EXPECT_EQ(s->seq, f.seq);
        EXPECT_EQ(s->left, f.score_left) << "frame " << f.seq;
        EXPECT_EQ(s->right, f.score_right) << "frame " << f.seq;
      }
      if (std::holds_alternative<proto::StaminaUpdate>(c)) {
        EXPECT_EQ(seq, f.seq);
        EXPECT_EQ(f.substep, 0);
        stamina_seqs.push_back(seq);
      }
    }
    pending.clear();
    ++frames;
    if (f.stoppage > 0) ++stoppage_frames;
  }
  EXPECT_EQ(goals, 2);
  EXPECT_EQ(scores, 3);  // 0-0 at the start, 0-1, 1-1
  EXPECT_GT(stoppage_frames, 100) << "the run must cover stoppages (kick-off, goals)";
  // Stamina with the first frame, then exactly every 20 frames.
  ASSERT_GE(stamina_seqs.size(), 80u);
  EXPECT_EQ(stamina_seqs[0], 0u);
  for (std::size_t i = 1; i < stamina_seqs.size(); ++i)
    ASSERT_EQ(stamina_seqs[i] - stamina_seqs[i - 1], 20u) << "stamina " << i;
  EXPECT_GE(frames, static_cast<int>(20 * (stamina_seqs.size() - 1)));
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
