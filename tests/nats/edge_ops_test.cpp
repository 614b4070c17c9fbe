// Issue 18, "operations at the edge", with real processes on loopback:
// nats-server, an origin publishing game "g", and an edge given another
// game only (--edge-games other), which waits 1.5 s for a game asked for.
// - /ws?channel=g: the edge subscribes on demand, and the spectator gets
//   the hello, a keyframe and the live frames;
// - /ws?channel=nosuch: closed with code 4404 and a reason, after the wait;
// - /metrics: NATS messages and bytes in, reconnects, snapshot fetches, the
//   lag behind the origin, games carried, on-demand outcomes.
// Skipped only when nats-server is not installed.
#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <memory>
#include <string>
#include <thread>

#include "tests/nats/child_process.hpp"
#include "tests/nats/nats_processes.hpp"
#include "tests/nats/spectator.hpp"

namespace fs = std::filesystem;
using namespace std::chrono_literals;
using namespace mc::nats::testing;

namespace {

constexpr auto kOnDemandWait = 1500ms;

class NatsEdgeOps : public ::testing::Test {
 protected:
  void SetUp() override {
    nats_bin_ = find_nats_server();
    if (nats_bin_.empty()) GTEST_SKIP() << "nats-server is not installed (Debian package nats-server)";
    dir_ = fs::temp_directory_path() / ("mc-nats-edge-ops-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
    nats_port_ = free_port();
    ASSERT_TRUE(start_nats());
    const std::string url = "nats://127.0.0.1:" + std::to_string(nats_port_);
    ASSERT_TRUE(origin_.start(matchcast_argv(url, "", {"--role", "origin", "--rcg", "g=" + test_game_log()}),
                              (dir_ / "origin.log").string()));
    ASSERT_NE(wait_for_port(origin_, 30s), 0);
    ASSERT_TRUE(edge_.start(matchcast_argv(url, "", {"--role", "edge", "--edge-games", "other", "--edge-on-demand-ms",
                                                     std::to_string(kOnDemandWait.count())}),
                            (dir_ / "edge.log").string()));
    edge_port_ = wait_for_port(edge_, 30s);
    ASSERT_NE(edge_port_, 0);
  }
  void TearDown() override {
    edge_.stop();
    origin_.stop();
    nats_.stop();
    if (HasFailure()) std::printf("logs kept in %s\n", dir_.c_str());
    else if (!dir_.empty()) fs::remove_all(dir_);
  }
  bool start_nats() {
    if (!nats_.start({nats_bin_, "-a", "127.0.0.1", "-p", std::to_string(nats_port_), "-js", "-sd",
                      (dir_ / "js").string()},
                     (dir_ / "nats-server.log").string()))
      return false;
    return eventually([&] { return port_open(nats_port_); }, 10s);
  }
  std::string metrics() { return http_get(edge_port_, "/metrics"); }

  std::string nats_bin_;
  fs::path dir_;
  std::uint16_t nats_port_ = 0, edge_port_ = 0;
  ChildProcess nats_, origin_, edge_;
};

TEST_F(NatsEdgeOps, AGameTheEdgeDoesNotCarryIsSubscribedWhenASpectatorAsksForIt) {
  // Wait until the origin's snapshot is in the stream: the edge reads it at once.
  Spectator s(edge_port_, "/ws?channel=g");
  ASSERT_TRUE(eventually([&] { return s.frame_count() >= 20; }, 15s)) << describe(s);
  ASSERT_FALSE(s.texts().empty());
  EXPECT_NE(s.texts().front().data.find("\"type\":\"hello\""), std::string::npos) << "the hello first";
  const auto f = s.frames();
  EXPECT_TRUE(f.front().key) << "then a keyframe";
  EXPECT_TRUE(in_sequence_after_sync(f));
  EXPECT_EQ(s.bad(), 0);
  EXPECT_FALSE(s.closed());
  // Past the wait, the game stays: it is carried now.
  std::this_thread::sleep_for(kOnDemandWait + 500ms);
  EXPECT_FALSE(s.closed());
  const std::string m = metrics();
  EXPECT_EQ(metric(m, "matchcast_edge_on_demand_total{result=\"requested\"}"), 1) << m;
  EXPECT_EQ(metric(m, "matchcast_edge_on_demand_total{result=\"found\"}"), 1);
  EXPECT_EQ(metric(m, "matchcast_edge_on_demand_total{result=\"unknown\"}"), 0);
  EXPECT_EQ(metric(m, "matchcast_edge_games{state=\"ready\"}"), 1);    // g
  EXPECT_EQ(metric(m, "matchcast_edge_games{state=\"waiting\"}"), 1);  // other, never published
  // A second spectator joins the carried game: no new request.
  Spectator s2(edge_port_, "/ws?channel=g");
  EXPECT_TRUE(eventually([&] { return s2.frame_count() >= 5; }, 5s));
  EXPECT_EQ(metric(metrics(), "matchcast_edge_on_demand_total{result=\"requested\"}"), 1);
}

TEST_F(NatsEdgeOps, AnUnknownGameIsClosedWithAReasonAfterABoundedWait) {
  const auto asked = Clock::now();
  Spectator s(edge_port_, "/ws?channel=nosuch");
  ASSERT_TRUE(eventually([&] { return s.closed(); }, 10s)) << "still open 10 s after asking";
  const auto waited = std::chrono::duration_cast<std::chrono::milliseconds>(s.closed_at() - asked);
  std::printf("unknown game closed after %lld ms: %u \"%s\"\n", static_cast<long long>(waited.count()),
              s.close_code(), s.close_reason().c_str());
  EXPECT_GE(waited, kOnDemandWait - 100ms);
  EXPECT_LE(waited, kOnDemandWait + 1500ms);
  EXPECT_EQ(s.close_code(), 4404);
  EXPECT_NE(s.close_reason().find("no game 'nosuch'"), std::string::npos) << s.close_reason();
  EXPECT_EQ(s.frame_count(), 0u);
  // Forgotten: not in /channels, counted on /metrics.
  EXPECT_EQ(http_get(edge_port_, "/channels").find("\"nosuch\""), std::string::npos);
  const std::string m = metrics();
  EXPECT_EQ(metric(m, "matchcast_edge_on_demand_total{result=\"unknown\"}"), 1) << m;
  // A name that cannot be a game is refused at once, as before (404).
  EXPECT_THROW(Spectator(edge_port_, "/ws?channel=a.b"), std::exception);
}

TEST_F(NatsEdgeOps, MetricsShowTheEdgesOwnCounters) {
  Spectator s(edge_port_, "/ws?channel=g");
  ASSERT_TRUE(eventually([&] { return s.frame_count() >= 40; }, 15s)) << describe(s);
  std::string m = metrics();
  EXPECT_EQ(metric(m, "matchcast_edge_nats_connected"), 1) << m;
  EXPECT_GT(metric(m, "matchcast_edge_nats_messages_in_total"), 40);
  EXPECT_GT(metric(m, "matchcast_edge_nats_bytes_in_total"), 40 * 100);
  EXPECT_EQ(metric(m, "matchcast_edge_nats_reconnects_total"), 0);
  EXPECT_GE(metric(m, "matchcast_edge_snapshot_fetches_total{result=\"found\"}"), 1);
  EXPECT_EQ(metric(m, "matchcast_edge_snapshot_fetches_total{result=\"failed\"}"), 0);
  EXPECT_GT(metric(m, "matchcast_edge_applied_total{channel=\"g\"}"), 40);
  EXPECT_EQ(metric(m, "matchcast_edge_rejected_total{channel=\"g\"}"), 0);
  // The lag behind the origin: same clock on loopback, so a few ms.
  const double frames = metric(m, "matchcast_edge_origin_lag_ms_count");
  EXPECT_GT(frames, 30);
  const double mean = metric(m, "matchcast_edge_origin_lag_ms_sum") / frames;
  const double last = metric(m, "matchcast_edge_origin_lag_last_ms{channel=\"g\"}");
  std::printf("lag behind the origin on loopback: mean %.1f ms, latest %.0f ms, %.0f frames\n", mean, last, frames);
  EXPECT_GE(last, 0);
  EXPECT_LT(mean, 200);
  EXPECT_LT(last, 1000);
  EXPECT_EQ(metric(m, "matchcast_edge_origin_lag_ms_bucket{le=\"+Inf\"}"), frames);
  // A NATS restart: one reconnect, and the link up again.
  nats_.stop(SIGTERM);
  EXPECT_TRUE(eventually([&] { return metric(metrics(), "matchcast_edge_nats_connected") == 0; }, 10s));
  ASSERT_TRUE(start_nats());
  EXPECT_TRUE(eventually(
      [&] {
        m = metrics();
        return metric(m, "matchcast_edge_nats_connected") == 1 && metric(m, "matchcast_edge_nats_reconnects_total") >= 1;
      },
      15s))
      << m;
}

}  // namespace
