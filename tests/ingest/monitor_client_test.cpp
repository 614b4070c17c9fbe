// The live UDP monitor client against the feeder over loopback (127.0.0.1,
// ephemeral ports, bounded waits): what the client sees equals the log;
// feed lost / back on a restart; bad and oversized datagrams are counted.
#include "server/ingest/monitor_client.hpp"

#include <gtest/gtest.h>

#include <thread>

#include "server/ingest/state_source.hpp"
#include "server/tools/feeder/feeder.hpp"
#include "tests/ingest/state_compare.hpp"

namespace mc::ingest {
namespace {

using namespace std::chrono_literals;
const std::string kGen = std::string(MATCHCAST_TEST_RCG_DIR) + "/generated/";
const std::string kV6 = kGen + "gen19-v6-20261122025254-Alpha_0-vs-Beta_0.rcg.gz";

// A feeder serving `log` on an ephemeral port from a background thread.
class FeederThread {
 public:
  FeederThread(const std::string& log, double speed, bool loop = false, std::uint16_t port = 0) {
    feeder::FeederConfig cfg;
    cfg.log_path = log;
    cfg.port = port;
    cfg.speed = speed;
    cfg.loop = loop;
    feeder_ = std::make_unique<feeder::Feeder>(cfg);
    std::string err;
    ok_ = feeder_->open(err);
    EXPECT_TRUE(ok_) << err;
    if (ok_) thread_ = std::thread([this] {
      std::string e;
      feeder_->run(e);
    });
  }
  ~FeederThread() { stop(); }
  void stop() {
    feeder_->stop();
    if (thread_.joinable()) thread_.join();
  }
  std::uint16_t port() const { return feeder_->port(); }
  bool ok() const { return ok_; }

 private:
  std::unique_ptr<feeder::Feeder> feeder_;
  std::thread thread_;
  bool ok_ = false;
};

std::vector<WorldState> log_states(const std::string& path) {
  std::string err;
  auto src = open_log(path, err);
  std::vector<WorldState> v;
  WorldState s;
  while (src && src->next(s)) v.push_back(s);
  return v;
}

// Reads states until `n` arrived or `limit` passed.
std::vector<WorldState> receive(MonitorClient& c, std::size_t n, std::chrono::milliseconds limit) {
  std::vector<WorldState> v;
  const auto end = std::chrono::steady_clock::now() + limit;
  WorldState s;
  while (v.size() < n && std::chrono::steady_clock::now() < end)
    if (c.next_for(s, 100ms) == StateSource::Wait::State) v.push_back(s);
  return v;
}

// The first kCompared shows at 10 ms each: fast, yet with slack for a
// loaded test machine (UDP drops what a stalled reader cannot take).
constexpr std::size_t kCompared = 300;
constexpr double kSpeed = 10.0;

void expect_loopback_equals_log(int version, testing::Tolerance tol) {
  auto ref = log_states(kV6);
  ASSERT_EQ(ref.size(), 599u);
  ref.resize(kCompared);
  FeederThread f(kV6, kSpeed);
  ASSERT_TRUE(f.ok());
  MonitorClientConfig cfg;
  cfg.port = f.port();
  cfg.version = version;
  MonitorClient client(cfg);
  const auto got = receive(client, ref.size(), 20s);
  ASSERT_EQ(got.size(), ref.size()) << "stats: skipped " << client.stats().skipped;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    ASSERT_EQ(testing::first_difference(ref[i], got[i], tol), "") << "show " << i;
    EXPECT_EQ(got[i].index, i);
    EXPECT_EQ(got[i].stoppage, ref[i].stoppage);
  }
  EXPECT_EQ(client.params().player_types.size(), 18u);
  EXPECT_NEAR(client.params().server.number("half_time", 0), 30, 1e-9);
  EXPECT_NE(client.server_port(), f.port());  // per-monitor port
  EXPECT_EQ(client.stats().skipped, 0u);
}

TEST(MonitorClient, FeederLoopbackV5EqualsLog) { expect_loopback_equals_log(5, testing::Tolerance{}); }

TEST(MonitorClient, FeederLoopbackJsonEqualsLog) {
  testing::Tolerance t;
  t.counters = false;  // JSON monitor shows have none
  expect_loopback_equals_log(-1, t);
}

TEST(MonitorClient, FeederLoopbackBinaryV2WithinQuantisation) {
  testing::Tolerance t;
  t.pos = 1e-4;
  t.angle = 1e-3;
  t.stamina = 1e-4;
  t.state_mask = 0xffff;
  t.capacity = t.counters = t.details = false;
  expect_loopback_equals_log(2, t);
}

TEST(MonitorClient, FeederLoopbackV4EqualsLogWithoutFocusPoint) {
  // v4 has no (fp) and 11 counters: compare what v4 carries.
  auto ref = log_states(kV6);
  ref.resize(kCompared);
  FeederThread f(kV6, kSpeed);
  ASSERT_TRUE(f.ok());
  MonitorClientConfig cfg;
  cfg.port = f.port();
  cfg.version = 4;
  MonitorClient client(cfg);
  const auto got = receive(client, ref.size(), 20s);
  ASSERT_EQ(got.size(), ref.size());
  testing::Tolerance t;
  t.counters = false;
  for (std::size_t i = 0; i < ref.size(); ++i) {
    ASSERT_EQ(testing::first_difference(ref[i], got[i], t), "") << "show " << i;
    ASSERT_FALSE(got[i].players[0].focus_point.has_value());
    ASSERT_EQ(got[i].players[0].counters.count, 11);
  }
}

TEST(MonitorClient, FeedLostAndBackAcrossARestart) {
  const std::string log = kGen + "gen19-v5-20261122025405-Alpha_0-vs-Beta_0.rcg.gz";
  auto f = std::make_unique<FeederThread>(log, 20.0, /*loop=*/true);
  ASSERT_TRUE(f->ok());
  const std::uint16_t port = f->port();
  MonitorClientConfig cfg;
  cfg.port = port;
  cfg.lost_after = 300ms;
  cfg.backoff_initial = 50ms;
  cfg.backoff_max = 200ms;
  MonitorClient client(cfg);
  ASSERT_EQ(receive(client, 5, 5s).size(), 5u);
  f.reset();  // server gone
  WorldState s;
  bool lost = false, back = false;
  const auto end = std::chrono::steady_clock::now() + 10s;
  bool restarted = false;
  while (!back && std::chrono::steady_clock::now() < end) {
    client.next_for(s, 50ms);
    SourceEvent ev;
    while (client.poll_event(ev)) {
      if (ev.kind == SourceEvent::Kind::FeedLost) lost = true;
      if (ev.kind == SourceEvent::Kind::FeedBack && lost) back = true;
    }
    if (lost && !restarted) {
      f = std::make_unique<FeederThread>(log, 20.0, true, port);  // same port, new server
      ASSERT_TRUE(f->ok());
      restarted = true;
    }
  }
  EXPECT_TRUE(lost);
  EXPECT_TRUE(back);
  EXPECT_EQ(receive(client, 3, 5s).size(), 3u);  // states flow again
}

TEST(MonitorClient, BadAndOversizedDatagramsAreCountedAndSkipped) {
  // A fake server: answer the dispinit from a second socket with junk, an
  // oversized datagram, then one good show.
  UdpSocket init, per_monitor;
  ASSERT_TRUE(init.open(UdpEndpoint{0x7f000001, 0}));
  ASSERT_TRUE(per_monitor.open(UdpEndpoint{0x7f000001, 0}));
  MonitorClientConfig cfg;
  cfg.port = init.local_port();
  MonitorClient client(cfg);
  WorldState s;
  std::thread server([&] {
    std::vector<char> buf(65536);
    std::size_t n = 0;
    UdpEndpoint from;
    if (init.receive(buf.data(), buf.size(), n, from, 5000ms) != UdpSocket::Recv::Data) return;
    per_monitor.send_to(from, std::string_view("(show 1 ((b) 0 0 0\0", 19));
    per_monitor.send_to(from, std::string(20000, '('));
    per_monitor.send_to(from, std::string_view("\x01\x02\x03", 3));
    per_monitor.send_to(from, "(show 7 (pm 3) (tm A B 1 2) ((b) 1 2 0 0))");
  });
  // The first call also sends the dispinit.
  bool got = false;
  const auto end = std::chrono::steady_clock::now() + 5s;
  while (!got && std::chrono::steady_clock::now() < end) got = client.next_for(s, 100ms) == StateSource::Wait::State;
  server.join();
  ASSERT_TRUE(got);
  EXPECT_EQ(s.time, 7);
  EXPECT_EQ(s.play_mode, PlayMode::PlayOn);
  EXPECT_EQ(s.right.score, 2);
  EXPECT_EQ(client.stats().skipped, 3u);
  ASSERT_EQ(client.stats().errors.size(), 3u);
  EXPECT_NE(client.stats().errors[0].find("datagram 0"), std::string::npos) << client.stats().errors[0];
  EXPECT_NE(client.stats().errors[1].find("oversized"), std::string::npos) << client.stats().errors[1];
}

TEST(MonitorClient, StopUnblocksNext) {
  MonitorClientConfig cfg;
  cfg.port = 9;  // nobody answers
  MonitorClient client(cfg);
  std::thread t([&] {
    std::this_thread::sleep_for(100ms);
    client.stop();
  });
  WorldState s;
  EXPECT_FALSE(client.next(s));
  t.join();
}

}  // namespace
}  // namespace mc::ingest
