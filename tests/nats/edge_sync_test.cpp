// EdgeSync without a NATS server: envelopes in, channel publishes out. The
// order, the snapshot / live merge, gaps, hostile input and feed lost/back.
#include "server/nats/edge_sync.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <memory>
#include <mutex>
#include <vector>

#include "anim/human_skeleton.hpp"
#include "proto/frame_header.hpp"
#include "proto/hello.hpp"

namespace mc::nats {
namespace {

std::string make_hello(const std::string& match) {
  proto::Hello h;
  h.skeleton = anim::human_skeleton();
  h.match_id = match;
  return proto::to_json(h);
}

std::string frame(std::uint32_t seq, bool key) {
  proto::FrameHeader h;
  h.seq = seq;
  h.keyframe = key;
  std::string out;
  proto::write_header(h, out);
  out += "body-" + std::to_string(seq);
  return out;
}

// A spectator: what the channel sends it, in order.
struct Collector : relay::Subscriber {
  std::mutex mutex;
  std::vector<relay::Message> got;
  void deliver(const relay::Message& m) override {
    std::lock_guard lock(mutex);
    got.push_back(m);
  }
  // "H", "K<seq>", "D<seq>", "C" per message.
  std::vector<std::string> summary() {
    std::lock_guard lock(mutex);
    std::vector<std::string> out;
    for (const auto& m : got) {
      if (!m.binary()) {
        out.push_back(m.bytes->find("\"hello\"") != std::string::npos ? "H" : "C");
        continue;
      }
      proto::FrameHeader h;
      std::string error;
      EXPECT_TRUE(proto::peek_header(*m.bytes, h, error));
      out.push_back((h.keyframe ? "K" : "D") + std::to_string(h.seq));
    }
    return out;
  }
};

class NatsEdgeSync : public ::testing::Test {
 protected:
  void SetUp() override {
    channel_ = std::make_shared<relay::Channel>("g");
    spectator_ = std::make_shared<Collector>();
    EXPECT_TRUE(channel_->join(spectator_).empty());
    sync_ = std::make_unique<EdgeSync>(channel_);
    hello_ = make_hello("m1");
  }
  // Envelope n carries frame seq 100 + n; keyframes where `key`.
  std::string live(std::uint64_t n, bool key) {
    return wrap(key ? Kind::Keyframe : Kind::Delta, n, frame(static_cast<std::uint32_t>(100 + n), key));
  }
  std::shared_ptr<relay::Channel> channel_;
  std::shared_ptr<Collector> spectator_;
  std::unique_ptr<EdgeSync> sync_;
  std::string hello_;
};

using Seq = std::vector<std::string>;

TEST_F(NatsEdgeSync, PassesTheOriginsMessagesInOrderWithTheSameBytes) {
  sync_->on_snapshot(nullptr);  // nothing stored yet: go live
  sync_->on_live(wrap(Kind::Hello, 1, hello_));
  sync_->on_live(live(2, true));
  sync_->on_live(live(3, false));
  sync_->on_live(wrap(Kind::Control, 4, R"({"type":"goal","seq":103,"time":10,"side":"l","unum":9})"));
  sync_->on_live(live(5, false));
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K102", "D103", "C", "D105"}));
  EXPECT_EQ(*spectator_->got[1].bytes, frame(102, true));
  EXPECT_EQ(channel_->feed_state(), relay::FeedState::Live);
  // A late joiner on the edge gets the hello and the keyframe group.
  auto late = std::make_shared<Collector>();
  const auto first = channel_->join(late);
  ASSERT_EQ(first.size(), 4u);
  EXPECT_EQ(*first[0].bytes, hello_);
  EXPECT_EQ(sync_->stats().applied, 5u);
}

TEST_F(NatsEdgeSync, MeasuresHowFarLiveFramesAreBehindTheOrigin) {
  using namespace std::chrono;
  const auto now = static_cast<std::uint64_t>(duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count());
  auto stamped = [](std::uint32_t seq, bool key, std::uint64_t at) {
    proto::FrameHeader h;
    h.seq = seq;
    h.keyframe = key;
    h.server_time_ms = at;
    std::string out;
    proto::write_header(h, out);
    return out + "body";
  };
  // A snapshot's keyframe is old by design: not counted.
  const std::string snap = wrap_snapshot(1, hello_, stamped(101, true, now - 5000));
  sync_->on_snapshot(&snap);
  sync_->on_live(wrap(Kind::Delta, 2, stamped(102, false, now - 150)));
  sync_->on_live(wrap(Kind::Delta, 3, stamped(103, false, now + 60000)));  // the edge's clock is behind: 0 ms
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K101", "D102", "D103"}));
  const LagHistogram lag = sync_->stats().lag;
  EXPECT_EQ(lag.count, 2u);
  EXPECT_EQ(lag.counts[0], 1u);  // <= 1 ms: the one from the future
  EXPECT_EQ(lag.counts[7], 1u);  // (100, 200] ms
  EXPECT_EQ(LagHistogram::kBucketsMs[7], 200u);
  EXPECT_GE(lag.sum_ms, 150u);
  EXPECT_LT(lag.sum_ms, 200u);
  EXPECT_EQ(lag.last_ms, 0u);
}

TEST_F(NatsEdgeSync, AGapHoldsDeltasBackUntilTheNextKeyframe) {
  sync_->on_snapshot(nullptr);
  sync_->on_live(wrap(Kind::Hello, 1, hello_));
  sync_->on_live(live(2, true));
  sync_->on_live(live(3, false));
  sync_->on_live(live(5, false));  // 4 was lost
  sync_->on_live(live(6, false));
  sync_->on_live(live(7, true));
  sync_->on_live(live(8, false));
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K102", "D103", "K107", "D108"}));
  EXPECT_EQ(sync_->stats().gaps, 1u);
  EXPECT_EQ(sync_->stats().held_back, 2u);
}

TEST_F(NatsEdgeSync, NothingBeforeAHello) {
  sync_->on_snapshot(nullptr);
  sync_->on_live(live(2, true));
  sync_->on_live(live(3, false));
  sync_->on_live(wrap(Kind::Control, 4, R"({"type":"play_mode","seq":3,"time":1,"mode":"play_on","mode_id":3})"));
  sync_->on_link_lost("test: link lost");
  EXPECT_TRUE(spectator_->summary().empty());
  EXPECT_EQ(channel_->feed_state(), relay::FeedState::Lost);
  EXPECT_FALSE(sync_->has_hello());
  EXPECT_EQ(sync_->stats().held_back, 3u);
  // The hello, then a keyframe: the stream starts.
  sync_->on_link_back("test: link back");
  sync_->on_live(wrap(Kind::Hello, 5, hello_));
  sync_->on_live(live(6, false));
  sync_->on_live(live(7, true));
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K107"}));
}

TEST_F(NatsEdgeSync, TheFirstHelloComesFromAnOlderSnapshotWhenLiveRanAhead) {
  // The stream had nothing at the first read; live messages went on
  // without a hello; the snapshot read again is older than them.
  sync_->on_snapshot(nullptr);
  for (std::uint64_t n = 20; n <= 24; ++n) sync_->on_live(live(n, false));
  sync_->begin_resync();
  sync_->on_live(live(25, false));
  const std::string snap = wrap_snapshot(19, hello_, frame(119, true));
  sync_->on_snapshot(&snap);
  EXPECT_TRUE(sync_->has_hello());
  sync_->on_live(live(26, false));  // its base (25) is not with the spectators
  sync_->on_live(live(27, true));
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K119", "K127"}));
}

TEST_F(NatsEdgeSync, SnapshotThenBufferedLiveMessagesEachOnce) {
  // Joining a running game: live 5..10 arrive while the snapshot is read.
  sync_->begin_resync();
  for (std::uint64_t n = 5; n <= 10; ++n) sync_->on_live(live(n, n == 9));
  EXPECT_TRUE(spectator_->summary().empty());
  const std::string snap = wrap_snapshot(7, hello_, frame(107, true));
  sync_->on_snapshot(&snap);
  // The hello and keyframe 7 at once, then 8..10; 5..7 were already covered.
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K107", "D108", "K109", "D110"}));
  EXPECT_EQ(sync_->stats().duplicates, 3u);
  EXPECT_EQ(sync_->stats().resyncs, 1u);
  EXPECT_FALSE(sync_->resync_pending());
  sync_->on_live(live(11, false));
  EXPECT_EQ(spectator_->summary().back(), "D111");
}

TEST_F(NatsEdgeSync, ResyncAfterReconnectSkipsToTheNewerSnapshot) {
  sync_->on_snapshot(nullptr);
  sync_->on_live(wrap(Kind::Hello, 1, hello_));
  sync_->on_live(live(2, true));
  sync_->on_link_lost("test: link lost");
  sync_->on_link_back("test: link back");
  sync_->begin_resync();
  sync_->on_live(live(31, false));
  sync_->on_live(live(32, false));
  const std::string snap = wrap_snapshot(30, hello_, frame(130, true));
  sync_->on_snapshot(&snap);
  // The same hello is not sent again; the spectators jump to keyframe 30.
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K102", "C", "C", "K130", "D131", "D132"}));
  EXPECT_NE(spectator_->got[2].bytes->find("\"status\":\"lost\""), std::string::npos);
  EXPECT_NE(spectator_->got[3].bytes->find("\"status\":\"back\""), std::string::npos);
  EXPECT_EQ(channel_->feed_state(), relay::FeedState::Live);
}

TEST_F(NatsEdgeSync, AnOlderSnapshotIsIgnoredAndTheLiveGapWaitsForAKeyframe) {
  sync_->on_snapshot(nullptr);
  sync_->on_live(wrap(Kind::Hello, 1, hello_));
  sync_->on_live(live(2, true));
  sync_->on_live(live(3, false));
  sync_->begin_resync();
  sync_->on_live(live(6, false));  // 4, 5 lost during the reconnect
  sync_->on_live(live(7, true));
  const std::string snap = wrap_snapshot(2, hello_, frame(102, true));
  sync_->on_snapshot(&snap);
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K102", "D103", "K107"}));
  EXPECT_EQ(sync_->stats().resyncs, 0u);
}

TEST_F(NatsEdgeSync, AReconnectThatLostNothingResumesWithoutWaitingForTheSnapshot) {
  sync_->on_snapshot(nullptr);
  sync_->on_live(wrap(Kind::Hello, 1, hello_));
  sync_->on_live(live(2, true));
  sync_->on_live(live(3, false));
  EXPECT_TRUE(sync_->in_sync());
  sync_->begin_resync();  // reconnected
  EXPECT_FALSE(sync_->in_sync());
  sync_->on_live(live(4, false));  // the very next one: nothing was lost
  EXPECT_FALSE(sync_->resync_pending());
  EXPECT_TRUE(sync_->in_sync());
  sync_->on_live(live(5, false));
  // The snapshot read that was under way comes back late: ignored.
  const std::string snap = wrap_snapshot(2, hello_, frame(102, true));
  sync_->on_snapshot(&snap);
  sync_->on_live(live(6, false));
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K102", "D103", "D104", "D105", "D106"}));
  EXPECT_EQ(sync_->stats().resyncs, 0u);
  EXPECT_EQ(sync_->stats().gaps, 0u);
}

TEST_F(NatsEdgeSync, HostileInputIsCountedAndSkipped) {
  sync_->on_snapshot(nullptr);
  sync_->on_live(wrap(Kind::Hello, 1, hello_));
  sync_->on_live(live(2, true));
  const std::vector<std::string> hostile = {
      "",                                                    // empty
      "garbage",                                             // shorter than a header
      std::string("Z\3\0\0\0\0\0\0\0xx", 11),                // unknown kind
      wrap(Kind::Delta, 3, "not a frame"),                   // bad frame header
      wrap(Kind::Keyframe, 4, frame(104, false)),            // kind and header disagree
      wrap(Kind::Control, 5, "{not json"),                   // control that is not JSON
      wrap(Kind::Hello, 6, R"({"type":"hello"})"),           // hello without its fields
      wrap_snapshot(7, hello_, frame(107, true)),            // snapshot on the live subject
  };
  for (const auto& h : hostile) sync_->on_live(h);
  EXPECT_EQ(sync_->stats().rejected, hostile.size());
  const std::string bad_snapshot = wrap(Kind::Snapshot, 9, std::string("\xff\xff\0\0", 4));
  sync_->begin_resync();
  sync_->on_snapshot(&bad_snapshot);
  EXPECT_EQ(sync_->stats().rejected, hostile.size() + 1);
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K102"}));
  // The stream goes on at the next keyframe.
  sync_->on_live(live(10, true));
  sync_->on_live(live(11, false));
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K102", "K110", "D111"}));
}

TEST_F(NatsEdgeSync, AnOriginSilentTooLongIsAFeedLostThenBack) {
  sync_->on_snapshot(nullptr);
  sync_->on_live(wrap(Kind::Hello, 1, hello_));
  sync_->on_live(live(2, true));
  const auto now = EdgeSync::Clock::now();
  sync_->check_silence(now, std::chrono::milliseconds(60000));
  EXPECT_EQ(channel_->feed_state(), relay::FeedState::Live);
  sync_->check_silence(now + std::chrono::seconds(5), std::chrono::milliseconds(3000));
  EXPECT_EQ(channel_->feed_state(), relay::FeedState::Lost);
  sync_->check_silence(now + std::chrono::seconds(9), std::chrono::milliseconds(3000));  // said once
  sync_->on_live(live(3, false));
  EXPECT_EQ(channel_->feed_state(), relay::FeedState::Live);
  const auto s = spectator_->summary();
  EXPECT_EQ(s, (Seq{"H", "K102", "C", "C", "D103"}));
  EXPECT_NE(spectator_->got[2].bytes->find("\"type\":\"feed\""), std::string::npos);
  EXPECT_NE(spectator_->got[2].bytes->find("\"seq\":102"), std::string::npos);
}

TEST_F(NatsEdgeSync, ANewHelloReplacesTheOldAndWaitsForItsKeyframe) {
  sync_->on_snapshot(nullptr);
  sync_->on_live(wrap(Kind::Hello, 1, hello_));
  sync_->on_live(live(2, true));
  const std::string other = make_hello("m2");
  sync_->on_live(wrap(Kind::Hello, 3, other));
  sync_->on_live(live(4, false));  // coded against the old skeleton state
  sync_->on_live(live(5, true));
  EXPECT_EQ(spectator_->summary(), (Seq{"H", "K102", "H", "K105"}));
  EXPECT_EQ(*spectator_->got[2].bytes, other);
}

}  // namespace
}  // namespace mc::nats
