// The feeder's serializer: shows, params and messages written in each
// monitor version parse back to the same values.
#include "server/ingest/monitor_serializer.hpp"

#include <gtest/gtest.h>

#include "server/ingest/monitor_decoder.hpp"
#include "server/ingest/state_source.hpp"
#include "tests/ingest/state_compare.hpp"
#include "tests/ingest/test_data.hpp"

namespace mc::ingest {
namespace {

std::vector<WorldState> first_states(const std::string& path, std::size_t n, GameParams* params = nullptr) {
  std::string err;
  auto src = open_log(path, err);
  std::vector<WorldState> v;
  WorldState s;
  while (src && v.size() < n && src->next(s)) v.push_back(s);
  if (src && params) *params = src->params();
  return v;
}

TEST(MonitorSerializer, ShowsRoundTripInEveryVersion) {
  GameParams params;
  const auto states = first_states(testing::rcg("full/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz"), 400, &params);
  ASSERT_EQ(states.size(), 400u);
  for (int version : {3, 4, 5, -1}) {
    MonitorDecoder d;
    for (const std::string& p : serialize_params(params, version)) {
      WorldState s;
      MessageRecord m;
      std::string err;
      ASSERT_EQ(d.decode(p, s, m, err), MonitorDecoder::Kind::Params) << err << "\n" << p.substr(0, 200);
    }
    EXPECT_EQ(d.context().params.player_types.size(), params.player_types.size());
    EXPECT_DOUBLE_EQ(d.context().params.type(5).kickable_margin, params.type(5).kickable_margin);
    EXPECT_EQ(d.context().params.server.text("log_date_format"), params.server.text("log_date_format"));
    testing::Tolerance t;
    t.counters = version == 5;
    t.capacity = version != 3;
    for (const WorldState& ref : states) {
      const std::string dg = serialize_show(ref, version);
      ASSERT_LE(dg.size(), kMaxDatagram);
      WorldState got;
      MessageRecord m;
      std::string err;
      ASSERT_EQ(d.decode(dg, got, m, err), MonitorDecoder::Kind::Show) << err;
      ASSERT_EQ(testing::first_difference(ref, got, t), "") << "version " << version;
      EXPECT_EQ(got.players[0].focus_point.has_value(), version == 5 || version == -1);
    }
  }
}

TEST(MonitorSerializer, BinaryShowsRoundTripWithinQuantisation) {
  GameParams params;
  const auto states = first_states(testing::rcg("full/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz"), 200, &params);
  for (int version : {1, 2}) {
    MonitorDecoder d;
    for (const std::string& p : serialize_params(params, version)) {
      WorldState s;
      MessageRecord m;
      std::string err;
      ASSERT_EQ(d.decode(p, s, m, err), MonitorDecoder::Kind::Params) << err;
    }
    if (version == 2) {
      EXPECT_EQ(d.context().params.player_types.size(), params.player_types.size());
      EXPECT_NEAR(d.context().params.type(5).kickable_margin, params.type(5).kickable_margin, 1e-4);
      EXPECT_NEAR(d.context().params.goal_width(), 14.02, 1e-4);
      EXPECT_EQ(d.context().params.server.number("half_time", 0), 300);
    }
    testing::Tolerance t;
    t.pos = version == 1 ? 1.0 / 32 + 1e-9 : 1e-4;  // rounded to 1/16 m or 1/65536 m
    t.angle = version == 1 ? 0.5 + 1e-9 : 1e-3;
    t.stamina = 1e-4;
    t.state_mask = 0xffff;
    t.capacity = t.counters = t.details = false;
    t.velocities = version == 2;
    for (const WorldState& ref : states) {
      const std::string dg = serialize_show(ref, version);
      EXPECT_TRUE(serializer_is_binary(version));
      WorldState got;
      MessageRecord m;
      std::string err;
      ASSERT_EQ(d.decode(dg, got, m, err), MonitorDecoder::Kind::Show) << err;
      if (version == 1) {  // v1 carries no type; compare the rest
        for (std::size_t i = 0; i < got.players.size(); ++i) got.players[i].type = ref.players[i].type;
      }
      ASSERT_EQ(testing::first_difference(ref, got, t), "") << "version " << version;
    }
  }
}

TEST(MonitorSerializer, MessagesKeepQuotes) {
  MessageRecord m{12, 1, R"((team_graphic_l (0 0 "8 8 1 1" "a c #ff0000")))"};
  for (int version : {5, -1, 2, 1}) {
    MonitorDecoder d;
    WorldState s;
    MessageRecord got;
    std::string err;
    ASSERT_EQ(d.decode(serialize_msg(m, version), s, got, err), MonitorDecoder::Kind::Message) << err;
    EXPECT_EQ(got.text, m.text);
    if (!serializer_is_binary(version)) {
      EXPECT_EQ(got.time, 12);  // binary msgs carry no time
    }
  }
}

TEST(MonitorSerializer, StateZeroIsBareAndOthersHex) {
  WorldState s;
  s.players[0].state = 0;
  s.players[1].state = 0x80100;
  const std::string t = serialize_show(s, 5);
  EXPECT_NE(t.find("((l 1) 0 0 "), std::string::npos) << t.substr(0, 200);
  EXPECT_NE(t.find("((l 2) 0 0x80100 "), std::string::npos);
  EXPECT_TRUE(serializer_supports(5));
  EXPECT_TRUE(serializer_supports(2));
  EXPECT_FALSE(serializer_supports(6));
  EXPECT_FALSE(serializer_supports(0));
}

}  // namespace
}  // namespace mc::ingest
