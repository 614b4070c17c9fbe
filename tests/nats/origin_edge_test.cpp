// The scenario with real processes on loopback: nats-server (started
// here, free port, JetStream store in a temp folder), one origin and two
// edges (matchcast-server --role ...), WebSocket spectators on each.
// - both edges deliver the origin's frames: same sequence numbers, same bytes;
// - killing one edge costs the other edge's spectators nothing;
// - restarting nats-server: the edges reconnect by themselves, spectators see
//   "feed lost" / "feed back" and resync at a keyframe;
// - garbage published on the game's subject is skipped by the edges.
// Skipped only when nats-server is not installed.
#include <gtest/gtest.h>
#include <netinet/in.h>
#include <sys/socket.h>

#include <atomic>
#include <boost/asio/ip/tcp.hpp>
#include <chrono>
#include <filesystem>
#include <map>
#include <memory>
#include <mutex>
#include <thread>

#include "proto/frame_header.hpp"
#include "server/nats/nats_link.hpp"
#include "tests/nats/child_process.hpp"
#include "tests/nats/nats_processes.hpp"
#include "tests/nats/spectator.hpp"
#include "tests/relay/ws_test_client.hpp"

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using mc::nats::testing::ChildProcess;
using mc::nats::testing::Frame;
using mc::nats::testing::Spectator;
using mc::nats::testing::consecutive;
using mc::nats::testing::eventually;
using mc::nats::testing::describe;
using mc::nats::testing::find_nats_server;
using mc::nats::testing::free_port;
using mc::nats::testing::in_sequence_after_sync;
using mc::nats::testing::matchcast_argv;
using mc::nats::testing::port_open;
using mc::nats::testing::wait_for_port;
using Clock = std::chrono::steady_clock;

namespace {

class NatsOriginEdge : public ::testing::Test {
 protected:
  void SetUp() override {
    nats_bin_ = find_nats_server();
    if (nats_bin_.empty()) GTEST_SKIP() << "nats-server is not installed (Debian package nats-server)";
    dir_ = fs::temp_directory_path() / ("mc-nats-test-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    nats_port_ = free_port();
    ASSERT_TRUE(start_nats());
    // Recording happens once: here at edge B (--record-at edge on it and
    // on the origin); edge A, with the default, records nothing.
    origin_port_ = start_server(origin_, "origin", {"--role", "origin", "--record-at", "edge"}, "rec-origin");
    ASSERT_NE(origin_port_, 0);
    edge_a_port_ = start_server(edge_a_, "edge-a", {"--role", "edge", "--edge-games", "live"}, "rec-a");
    edge_b_port_ = start_server(edge_b_, "edge-b", {"--role", "edge", "--record-at", "edge"}, "rec-b");  // every game
    ASSERT_NE(edge_a_port_, 0);
    ASSERT_NE(edge_b_port_, 0);
  }
  void TearDown() override {
    edge_a_.stop();
    edge_b_.stop();
    origin_.stop();
    nats_.stop();
    if (HasFailure()) {
      // Leave the logs for a person to read.
      std::printf("logs kept in %s\n", dir_.c_str());
    } else if (!dir_.empty()) {
      fs::remove_all(dir_);
    }
  }

  bool start_nats(bool jetstream = true) {
    std::vector<std::string> argv = {nats_bin_, "-a", "127.0.0.1", "-p", std::to_string(nats_port_)};
    if (jetstream) argv.insert(argv.end(), {"--jetstream", "--store_dir", (dir_ / "js").string()});
    if (!nats_.start(argv, (dir_ / "nats-server.log").string())) return false;
    return eventually([&] { return port_open(nats_port_); }, 10s);
  }

  std::uint16_t start_server(ChildProcess& p, const std::string& name, std::vector<std::string> extra,
                             const std::string& record_dir) {
    const auto argv = matchcast_argv("nats://127.0.0.1:" + std::to_string(nats_port_), (dir_ / record_dir).string(), extra);
    if (!p.start(argv, (dir_ / (name + ".log")).string())) return 0;
    return wait_for_port(p, 30s);
  }

  // A spectator that has received its hello and at least `frames` frames.
  std::unique_ptr<Spectator> watch(std::uint16_t port, std::size_t frames = 10) {
    // An edge carrying every game has its channel once the first message
    // arrived: until then /ws answers 404.
    std::unique_ptr<Spectator> s;
    const auto deadline = Clock::now() + 20s;
    while (!s) {
      try {
        s = std::make_unique<Spectator>(port);
      } catch (const std::exception& e) {
        if (Clock::now() > deadline) throw;
        std::this_thread::sleep_for(100ms);
      }
    }
    EXPECT_TRUE(eventually([&] { return s->frame_count() >= frames; }, 20s)) << "no frames on port " << port;
    return s;
  }

  std::string nats_bin_;
  fs::path dir_;
  std::uint16_t nats_port_ = 0, origin_port_ = 0, edge_a_port_ = 0, edge_b_port_ = 0;
  ChildProcess nats_, origin_, edge_a_, edge_b_;
};

TEST_F(NatsOriginEdge, BothEdgesDeliverTheOriginsFramesByteForByte) {
  auto at_origin = watch(origin_port_);
  auto at_a = watch(edge_a_port_);
  auto at_b = watch(edge_b_port_);
  std::this_thread::sleep_for(3s);
  const auto o = at_origin->frames(), a = at_a->frames(), b = at_b->frames();
  EXPECT_TRUE(in_sequence_after_sync(a));
  EXPECT_TRUE(in_sequence_after_sync(b));
  // The same hello everywhere, first.
  ASSERT_FALSE(at_a->texts().empty());
  ASSERT_FALSE(at_b->texts().empty());
  EXPECT_EQ(at_a->texts().front().data, at_origin->texts().front().data);
  EXPECT_EQ(at_b->texts().front().data, at_origin->texts().front().data);
  EXPECT_NE(at_a->texts().front().data.find("\"type\":\"hello\""), std::string::npos);
  // Every frame both edges and the origin sent in the common window: same bytes.
  std::map<std::uint32_t, const std::string*> by_seq;
  for (const auto& f : o) by_seq[f.seq] = &f.bytes;
  std::size_t compared = 0;
  for (const auto* edge : {&a, &b})
    for (const auto& f : *edge) {
      auto it = by_seq.find(f.seq);
      if (it == by_seq.end()) continue;
      EXPECT_EQ(*it->second, f.bytes) << "seq " << f.seq;
      ++compared;
    }
  EXPECT_GE(compared, 2u * 40u);  // 2 s of frames at 20 Hz on each edge at least
  // The spectators joined mid-stream: each started with a keyframe.
  EXPECT_TRUE(a.front().key);
  EXPECT_TRUE(b.front().key);
  EXPECT_EQ(at_a->bad() + at_b->bad(), 0);
  // One recording, at edge B, growing with the game.
  auto files = [&](const char* sub) {
    std::vector<fs::path> out;
    if (fs::exists(dir_ / sub))
      for (const auto& e : fs::directory_iterator(dir_ / sub)) out.push_back(e.path());
    return out;
  };
  EXPECT_TRUE(files("rec-origin").empty());
  EXPECT_TRUE(files("rec-a").empty());
  ASSERT_EQ(files("rec-b").size(), 1u);
  EXPECT_EQ(files("rec-b").front().extension(), ".mcrec");
  EXPECT_GT(fs::file_size(files("rec-b").front()), 10000u);
}

TEST_F(NatsOriginEdge, KillingOneEdgeCostsTheOtherEdgesSpectatorsNothing) {
  auto at_a = watch(edge_a_port_);
  auto at_b = watch(edge_b_port_);
  std::this_thread::sleep_for(1s);
  const auto killed_at = Clock::now();
  edge_a_.stop(SIGKILL);
  EXPECT_TRUE(eventually([&] { return at_a->closed(); }, 10s));
  std::this_thread::sleep_for(2500ms);
  const auto b = at_b->frames();
  EXPECT_FALSE(at_b->closed());
  // From the last frame before the kill to the end: every frame, in order.
  std::size_t first_after = 0;
  while (first_after < b.size() && b[first_after].at <= killed_at) ++first_after;
  ASSERT_GT(first_after, 0u);
  EXPECT_TRUE(consecutive(b, first_after - 1));
  const std::size_t after = b.size() - first_after;
  EXPECT_GE(after, 30u) << "edge B kept streaming after edge A died";
  // No "feed lost" on B: nothing happened to its feed.
  for (const auto& t : at_b->texts()) EXPECT_EQ(t.data.find("\"type\":\"feed\""), std::string::npos) << t.data;
}

TEST_F(NatsOriginEdge, EdgesReconnectAfterANatsRestartAndResyncAtAKeyframe) {
  auto at_a = watch(edge_a_port_);
  auto at_b = watch(edge_b_port_);
  std::this_thread::sleep_for(1s);
  nats_.stop(SIGTERM);
  std::this_thread::sleep_for(1500ms);
  ASSERT_TRUE(start_nats());
  for (auto* s : {at_a.get(), at_b.get()}) {
    // feed lost, feed back, then a keyframe and frames in sequence again.
    auto resynced = [&] {
      const auto texts = s->texts();
      std::size_t back_at = SIZE_MAX;
      bool lost = false;
      for (const auto& t : texts) {
        if (t.data.find("\"status\":\"lost\"") != std::string::npos) lost = true;
        if (lost && t.data.find("\"status\":\"back\"") != std::string::npos) back_at = t.frames_before;
      }
      if (back_at == SIZE_MAX) return false;
      // The snapshot's keyframe comes at once; the live deltas go on from
      // it, or (when the edge resubscribed after it) from the next keyframe.
      const auto f = s->frames();
      for (std::size_t i = back_at; i < f.size(); ++i)
        if (f[i].key && f.size() - i >= 20 && consecutive(f, i)) return true;
      return false;
    };
    EXPECT_TRUE(eventually(resynced, 30s)) << "no feed lost/back and keyframe resync: " << describe(*s);
    EXPECT_FALSE(s->closed()) << "the spectator stayed connected through the restart";
  }
  // After the resync both edges carry the same frames again.
  std::this_thread::sleep_for(1s);
  std::map<std::uint32_t, std::string> a_by_seq;
  for (auto& f : at_a->frames()) a_by_seq[f.seq] = f.bytes;
  std::size_t same = 0;
  for (auto& f : at_b->frames()) {
    auto it = a_by_seq.find(f.seq);
    if (it != a_by_seq.end()) same += it->second == f.bytes;
  }
  EXPECT_GE(same, 40u);
}

TEST_F(NatsOriginEdge, GarbageOnTheGamesSubjectIsSkipped) {
  auto at_b = watch(edge_b_port_);
  mc::nats::NatsConfig cfg;
  cfg.url = "nats://127.0.0.1:" + std::to_string(nats_port_);
  std::string error;
  auto link = mc::nats::NatsLink::open(cfg, "hostile", {}, true, error);
  ASSERT_TRUE(link) << error;
  ASSERT_TRUE(eventually([&] { return link->connected(); }, 5s));
  const std::size_t before = at_b->frame_count();
  for (const std::string& g : {std::string(), std::string("x"), std::string("K\1\0\0\0\0\0\0\0not a frame"),
                               std::string(4000, '\xff'), std::string("C\xff\xff\xff\xff\xff\xff\xff\xff{", 10)}) {
    EXPECT_TRUE(link->publish("matchcast.live.live", g));
    EXPECT_TRUE(link->publish("matchcast.evil.live", g));
  }
  std::this_thread::sleep_for(2s);
  const auto b = at_b->frames();
  EXPECT_FALSE(at_b->closed());
  EXPECT_GE(b.size(), before + 25);
  // The bogus envelope numbers cost at most a wait for the next keyframe.
  std::size_t gaps = 0;
  for (std::size_t i = std::max<std::size_t>(before, 1); i < b.size(); ++i) gaps += b[i].seq != b[i - 1].seq + 1;
  EXPECT_LE(gaps, 1u);
  EXPECT_EQ(at_b->bad(), 0);
  EXPECT_TRUE(port_open(edge_b_port_));
}

TEST_F(NatsOriginEdge, AnEdgeJoiningWithoutJetStreamGetsTheHelloFromTheLiveSubject) {
  // The NATS server comes back without JetStream: no keyframe stream. An
  // edge started now learns the hello the origin repeats every 10 keyframes.
  nats_.stop(SIGTERM);
  ASSERT_TRUE(start_nats(false));
  ChildProcess edge_c;
  const auto port = start_server(edge_c, "edge-c", {"--role", "edge", "--edge-games", "live"}, "rec-c");
  ASSERT_NE(port, 0);
  auto at_c = watch(port, 20);  // waits up to 20 s: 10 keyframes are 10 s
  const auto f = at_c->frames();
  ASSERT_GE(f.size(), 20u);
  EXPECT_TRUE(f.front().key);
  EXPECT_TRUE(in_sequence_after_sync(f));
  ASSERT_FALSE(at_c->texts().empty());
  EXPECT_NE(at_c->texts().front().data.find("\"type\":\"hello\""), std::string::npos);
  at_c.reset();
  edge_c.stop();
}

}  // namespace
