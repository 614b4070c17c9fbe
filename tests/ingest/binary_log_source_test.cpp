// Binary logs v1/v2/v3: params from v3, cuts at every kind of boundary,
// and an unknown record tag stops the reader with a named offset.
#include "server/ingest/state_source.hpp"

#include <gtest/gtest.h>

#include <cstring>

#include "tests/ingest/test_data.hpp"

namespace mc::ingest {
namespace {

const std::string kV1 = testing::rcg("generated/gen19-v1-20261122025913-Alpha_0-vs-Beta_0.rcg.gz");
const std::string kV2 = testing::rcg("generated/gen19-v2-20261122025747-Alpha_1-vs-Beta_2.rcg.gz");
const std::string kV3 = testing::rcg("generated/gen19-v3-20261122025631-Alpha_0-vs-Beta_1.rcg.gz");

std::uint64_t count(std::string_view bytes, IngestStats* stats = nullptr) {
  std::string err;
  auto src = open_log_memory(bytes, err);
  if (!src) return 0;
  WorldState s;
  while (src->next(s)) {
  }
  if (stats) *stats = src->stats();
  return src->stats().shows;
}

TEST(BinaryLogSource, V3CarriesParamsAndTypes) {
  std::string err;
  auto src = open_log(kV3, err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  ASSERT_TRUE(src->next(s));
  EXPECT_NEAR(src->params().goal_width(), 14.02, 1e-4);
  EXPECT_EQ(src->params().server.number("half_time", 0), 30);
  EXPECT_EQ(src->params().simulator_step_ms(), 100);
  ASSERT_EQ(src->params().player_types.size(), 18u);
  EXPECT_NEAR(src->params().type(0).player_speed_max, 1.05, 1e-4);
  EXPECT_NEAR(src->params().type(0).kickable_margin, 0.7, 1e-4);
  EXPECT_EQ(s.time, 1);
  EXPECT_EQ(s.left.name, "Alpha");
}

TEST(BinaryLogSource, V1TypesComeFromChangePlayerTypeMessages) {
  // A v1 log: one MSG record announcing a type, then one show.
  std::string v1(2052, '\0');
  v1[1] = 2;  // MSG_MODE
  v1[3] = 1;  // board
  const std::string text = "(change_player_type r 4 7)";
  std::memcpy(v1.data() + 4, text.data(), text.size());
  std::string show(2052, '\0');
  show[1] = 1;  // SHOW_MODE
  v1 += show;
  std::string err;
  auto src = open_log_memory(v1, err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  ASSERT_TRUE(src->next(s));
  EXPECT_EQ(s.players[player_index(Side::Right, 4)].type, 7);
  EXPECT_EQ(s.players[player_index(Side::Right, 5)].type, 0);
}

TEST(BinaryLogSource, TruncationYieldsEveryCompleteShow) {
  for (const std::string& path : {kV1, kV2, kV3}) {
    const std::string all = testing::decoded(path);
    const std::uint64_t full = count(all);
    ASSERT_GT(full, 100u);
    // Cuts inside records (never on a record boundary: +1 off any multiple).
    for (std::size_t cut : {all.size() / 3 + 1, all.size() / 2 + 1, all.size() - 1}) {
      IngestStats st;
      const std::uint64_t n = count(std::string_view(all).substr(0, cut), &st);
      // The last byte belongs to the closing (result) message / team record.
      if (cut < all.size() - 1) EXPECT_LT(n, full) << path << " cut " << cut;
      else EXPECT_EQ(n, full) << path;
      EXPECT_GT(n, 0u);
      EXPECT_GE(st.skipped, 1u) << path << " cut " << cut;
      ASSERT_FALSE(st.errors.empty());
      EXPECT_NE(st.errors[0].find("offset"), std::string::npos) << st.errors[0];
    }
  }
}

TEST(BinaryLogSource, UnknownRecordTagStops) {
  std::string v3 = testing::decoded(kV3);
  v3.resize(4 + 2 + 396);   // header + the PARAM record
  v3 += std::string("\x00\x63", 2) + std::string(100, '\0');  // tag 99
  IngestStats st;
  EXPECT_EQ(count(v3, &st), 0u);
  ASSERT_EQ(st.errors.size(), 1u);
  EXPECT_NE(st.errors[0].find("offset 402"), std::string::npos) << st.errors[0];
}

TEST(BinaryLogSource, BadMessageLengthStops) {
  std::string v2("ULG\x02", 4);
  v2 += std::string("\x00\x02\x00\x01\xff\xff", 6);  // MSG, board 1, len -1
  IngestStats st;
  EXPECT_EQ(count(v2, &st), 0u);
  EXPECT_EQ(st.skipped, 1u);
}

}  // namespace
}  // namespace mc::ingest
