// matchcast-feeder's server behaviour: dispinit parsing, refusals from the
// init port, the per-monitor port, (dispbye). Loopback, ephemeral ports.
#include "server/tools/feeder/feeder.hpp"

#include <gtest/gtest.h>

#include <thread>

#include "tests/ingest/test_data.hpp"

namespace mc::feeder {
namespace {

using namespace std::chrono_literals;
using ingest::UdpEndpoint;
using ingest::UdpSocket;

TEST(Feeder, ParseDispinit) {
  int v = 0;
  EXPECT_TRUE(parse_dispinit(std::string_view("(dispinit)\0", 11), v));
  EXPECT_EQ(v, 1);
  EXPECT_TRUE(parse_dispinit("(dispinit version 5)", v));
  EXPECT_EQ(v, 5);
  EXPECT_TRUE(parse_dispinit("(dispinit version -1)\n", v));
  EXPECT_EQ(v, -1);
  EXPECT_TRUE(parse_dispinit("(dispinit version 4.0)", v));
  EXPECT_EQ(v, 4);
  EXPECT_FALSE(parse_dispinit("(dispinit version)", v));
  EXPECT_FALSE(parse_dispinit("(init Team)", v));
  EXPECT_FALSE(parse_dispinit("(dispinit version 1e9)", v));
}

struct Running {
  explicit Running(FeederConfig cfg) : feeder(std::move(cfg)) {
    std::string err;
    ok = feeder.open(err);
    EXPECT_TRUE(ok) << err;
    if (ok) thread = std::thread([this] {
      std::string e;
      feeder.run(e);
    });
  }
  ~Running() {
    feeder.stop();
    if (thread.joinable()) thread.join();
  }
  Feeder feeder;
  std::thread thread;
  bool ok = false;
};

std::string receive(UdpSocket& s, UdpEndpoint& from, std::chrono::milliseconds wait = 2000ms) {
  std::string buf(65536, '\0');
  std::size_t n = 0;
  if (s.receive(buf.data(), buf.size(), n, from, wait) != UdpSocket::Recv::Data) return {};
  buf.resize(std::min(n, buf.size()));
  return buf;
}

FeederConfig config() {
  FeederConfig cfg;
  cfg.log_path = ingest::testing::rcg("generated/gen19-v6-20261122025254-Alpha_0-vs-Beta_0.rcg.gz");
  cfg.port = 0;
  cfg.speed = 20;
  return cfg;
}

TEST(Feeder, HandshakeFromAPerMonitorPortThenShows) {
  Running r(config());
  ASSERT_TRUE(r.ok);
  UdpSocket mon;
  ASSERT_TRUE(mon.open(UdpEndpoint{0x7f000001, 0}));
  const UdpEndpoint init{0x7f000001, r.feeder.port()};
  ASSERT_TRUE(mon.send_to(init, std::string_view("(dispinit version 5)\0", 21)));
  UdpEndpoint from;
  const std::string first = receive(mon, from);
  EXPECT_EQ(first.rfind("(server_param ", 0), 0u) << first.substr(0, 40);
  EXPECT_EQ(first.back(), '\0');
  EXPECT_NE(from.port, init.port);
  const UdpEndpoint per_monitor = from;
  EXPECT_EQ(receive(mon, from).rfind("(player_param ", 0), 0u);
  for (int i = 0; i < 18; ++i) EXPECT_EQ(receive(mon, from).rfind("(player_type ", 0), 0u);
  std::string show;
  for (int i = 0; i < 50 && show.rfind("(show ", 0) != 0; ++i) show = receive(mon, from);
  EXPECT_EQ(show.rfind("(show 1 (pm 4) (tm Alpha Beta 0 0)", 0), 0u) << show.substr(0, 60);
  // Commands on the init port are refused, as rcssserver does.
  ASSERT_TRUE(mon.send_to(init, std::string_view("(dispstart)\0", 12)));
  bool refused = false;
  for (int i = 0; i < 50 && !refused; ++i) refused = receive(mon, from).find("only_init_allowed_on_init_port") != std::string::npos;
  EXPECT_TRUE(refused);
  // (dispbye) on the per-monitor port ends the session.
  ASSERT_TRUE(mon.send_to(per_monitor, std::string_view("(dispbye)\0", 10)));
  for (int i = 0; i < 40 && r.feeder.monitors() != 0; ++i) std::this_thread::sleep_for(25ms);
  EXPECT_EQ(r.feeder.monitors(), 0u);
}

TEST(Feeder, UnsupportedVersionIsRefusedFromTheInitPort) {
  Running r(config());
  ASSERT_TRUE(r.ok);
  UdpSocket mon;
  ASSERT_TRUE(mon.open(UdpEndpoint{0x7f000001, 0}));
  const UdpEndpoint init{0x7f000001, r.feeder.port()};
  ASSERT_TRUE(mon.send_to(init, std::string_view("(dispinit version 6)\0", 21)));
  UdpEndpoint from;
  const std::string reply = receive(mon, from);
  EXPECT_EQ(reply, std::string("(error illegal_client_version)\0", 31));
  EXPECT_EQ(from.port, init.port);
  EXPECT_EQ(r.feeder.monitors(), 0u);
}

TEST(Feeder, BadOptionsAndLogsFailToOpen) {
  FeederConfig cfg = config();
  cfg.speed = 0;
  std::string err;
  EXPECT_FALSE(Feeder(cfg).open(err));
  cfg = config();
  cfg.log_path = "/nonexistent.rcg";
  EXPECT_FALSE(Feeder(cfg).open(err));
  cfg = config();
  cfg.log_path = ingest::testing::rcg("real/20190926071807-HELIOS_base_0-vs-null.rcg");  // no shows
  EXPECT_FALSE(Feeder(cfg).open(err));
}

}  // namespace
}  // namespace mc::feeder
