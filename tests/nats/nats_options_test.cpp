// The NATS options of matchcast-server (--role, --edge-games, --record-at,
// ...) and which process records what: the parsing and the refusals.
#include "server/app/nats_roles.hpp"

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

namespace mc::app {
namespace {

std::optional<ServerOptions> parse(std::vector<std::string> args, std::string* message = nullptr) {
  args.insert(args.begin(), "matchcast-server");
  std::vector<const char*> argv;
  for (const auto& a : args) argv.push_back(a.c_str());
  std::string m;
  int code = -1;
  auto o = parse_server_options(static_cast<int>(argv.size()), argv.data(), m, code);
  if (message) *message = m;
  return o;
}

TEST(NatsOptions, StandaloneByDefaultAndRecordsItsFeeds) {
  const auto o = parse({});
  ASSERT_TRUE(o);
  EXPECT_EQ(o->nats.role, nats::Role::Standalone);
  EXPECT_FALSE(o->nats.origin());
  EXPECT_FALSE(o->nats.edge());
  EXPECT_EQ(o->feeds.size(), 1u);
  EXPECT_TRUE(records_local_feeds(*o));
  EXPECT_FALSE(records_edge_games(*o));
}

TEST(NatsOptions, AnEdgeHasNoFeedsAndReadsItsGames) {
  const auto o = parse({"--role", "edge", "--nats-url", "nats://a:4222,nats://b:4222", "--edge-games", " final, semi-1 ,",
                        "--nats-subject-prefix", "mc.eu", "--nats-reconnect-wait-ms", "250"});
  ASSERT_TRUE(o);
  EXPECT_TRUE(o->feeds.empty());
  EXPECT_TRUE(o->nats.edge());
  EXPECT_FALSE(o->nats.origin());
  EXPECT_EQ(o->nats.edge_games, (std::vector<std::string>{"final", "semi-1"}));
  EXPECT_EQ(o->nats.url, "nats://a:4222,nats://b:4222");
  EXPECT_EQ(o->nats.subject_prefix, "mc.eu");
  EXPECT_EQ(o->nats.reconnect_wait.count(), 250);
  EXPECT_FALSE(records_local_feeds(*o));
  EXPECT_FALSE(records_edge_games(*o));  // record-at origin: edges never record
}

TEST(NatsOptions, RecordingHappensOnceWhereRecordAtSays) {
  const auto origin = parse({"--role", "origin"});
  ASSERT_TRUE(origin);
  EXPECT_TRUE(records_local_feeds(*origin));
  const auto origin_not = parse({"--role", "origin", "--record-at", "edge"});
  ASSERT_TRUE(origin_not);
  EXPECT_FALSE(records_local_feeds(*origin_not));
  const auto edge = parse({"--role", "edge", "--record-at", "edge"});
  ASSERT_TRUE(edge);
  EXPECT_TRUE(records_edge_games(*edge));
  const auto off = parse({"--role", "edge", "--record-at", "edge", "--record-dir", ""});
  ASSERT_TRUE(off);
  EXPECT_FALSE(records_edge_games(*off));
  const auto both = parse({"--role", "both", "--nats-replicas", "3"});
  ASSERT_TRUE(both);
  EXPECT_TRUE(both->nats.origin());
  EXPECT_TRUE(both->nats.edge());
  EXPECT_EQ(both->feeds.size(), 1u);
  EXPECT_EQ(both->nats.stream_replicas, 3);
}

TEST(NatsOptions, OnDemandWaitAndServerOrder) {
  const auto plain = parse({"--role", "edge"});
  ASSERT_TRUE(plain);
  EXPECT_EQ(plain->nats.on_demand_wait.count(), 5000);
  EXPECT_TRUE(plain->nats.randomize_servers);
  const auto o = parse({"--role", "edge", "--edge-on-demand-ms", "0", "--nats-in-order"});
  ASSERT_TRUE(o);
  EXPECT_EQ(o->nats.on_demand_wait.count(), 0);  // no subscription on demand
  EXPECT_FALSE(o->nats.randomize_servers);
}

TEST(NatsOptions, BadValuesAreRefusedWithAReason) {
  std::string m;
  EXPECT_FALSE(parse({"--role", "relay"}, &m));
  EXPECT_NE(m.find("--role must be"), std::string::npos) << m;
  EXPECT_FALSE(parse({"--role", "edge", "--rcg", "game.rcg"}, &m));
  EXPECT_NE(m.find("an edge has no --rcg"), std::string::npos) << m;
  EXPECT_FALSE(parse({"--record-at", "somewhere"}, &m));
  EXPECT_NE(m.find("--record-at must be"), std::string::npos) << m;
  EXPECT_FALSE(parse({"--nats-replicas", "0"}, &m));
  EXPECT_NE(m.find("--nats-replicas"), std::string::npos) << m;
}

TEST(NatsOptions, AnOriginRefusesAChannelThatIsNotASubjectToken) {
  auto o = parse({"--role", "origin", "--nats-url", "nats://127.0.0.1:1"});
  ASSERT_TRUE(o);
  auto channels = std::make_shared<relay::ChannelRegistry>();
  channels->open("final.2026");
  o->feeds = {ChannelFeed{"final.2026", {}}};
  NatsRoles roles;
  std::string error;
  EXPECT_FALSE(roles.start(*o, channels, nullptr, error));
  EXPECT_NE(error.find("cannot be published on NATS"), std::string::npos) << error;
  roles.stop();
}

}  // namespace
}  // namespace mc::app
