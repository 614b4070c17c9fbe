// Binary struct decoders: big-endian fields, radians, short spans refused.
#include "server/ingest/binary_records.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <numbers>

namespace mc::ingest::binary {
namespace {

void put16(std::string& b, std::size_t at, int v) {
  b[at] = static_cast<char>((v >> 8) & 0xff);
  b[at + 1] = static_cast<char>(v & 0xff);
}
void put32(std::string& b, std::size_t at, std::int64_t v) {
  for (int i = 0; i < 4; ++i) b[at + i] = static_cast<char>((v >> (24 - 8 * i)) & 0xff);
}

TEST(BinaryRecords, BigEndian) {
  EXPECT_EQ(be16("\xff\xfe"), -2);
  EXPECT_EQ(be32("\x00\x0e\x05\x1e"), 918814);  // goal_width 14.02 * 65536
}

TEST(BinaryRecords, ShortShowInfo2) {
  std::string b(kShortShowInfo2Size, '\0');
  put32(b, 0, 65536 * 3);                // ball x = 3
  const std::size_t p = 16 + 64 * 12;     // right 2
  put16(b, p, 0x9);                       // state
  put16(b, p + 2, 7);                     // type
  put32(b, p + 4, -65536 * 10);           // x
  put32(b, p + 20, static_cast<std::int64_t>(std::numbers::pi / 2 * 65536));  // body
  put16(b, p + 32, 1);                    // high quality
  put16(b, p + 48, 5);                    // kick count
  put16(b, 1424, 321);                    // time
  WorldState s;
  ASSERT_TRUE(decode_short_showinfo2(b, s));
  EXPECT_EQ(s.time, 321);
  EXPECT_DOUBLE_EQ(s.ball.x, 3);
  const PlayerState& r2 = s.players[player_index(Side::Right, 2)];
  EXPECT_EQ(r2.side, Side::Right);
  EXPECT_EQ(r2.unum, 2);
  EXPECT_EQ(r2.state, 9u);
  EXPECT_EQ(r2.type, 7);
  EXPECT_DOUBLE_EQ(r2.x, -10);
  EXPECT_NEAR(r2.body, 90, 1e-3);
  EXPECT_EQ(r2.view_quality, 'h');
  EXPECT_EQ(r2.counters.kick, 5u);
  EXPECT_EQ(r2.counters.count, 8);
  EXPECT_FALSE(decode_short_showinfo2(std::string_view(b).substr(0, 100), s));
}

TEST(BinaryRecords, ShowInfoV1AndTeams) {
  std::string b(kShowInfoSize, '\0');
  b[0] = 3;  // play_on
  std::memcpy(b.data() + 2, "Alpha", 5);
  put16(b, 18, 2);
  std::memcpy(b.data() + 20, "null", 4);
  put16(b, 38 + 8, 16 * 5);  // ball x = 5
  put16(b, 38 + 12, 1);      // left 1 enabled
  put16(b, 38 + 12 + 6, -90);
  put16(b, 314, 42);
  WorldState s;
  ASSERT_TRUE(decode_showinfo_v1(b, s));
  EXPECT_EQ(s.play_mode, PlayMode::PlayOn);
  EXPECT_EQ(s.left.name, "Alpha");
  EXPECT_EQ(s.left.score, 2);
  EXPECT_EQ(s.right.name, "");
  EXPECT_DOUBLE_EQ(s.ball.x, 5);
  EXPECT_EQ(s.players[0].state, 1u);
  EXPECT_DOUBLE_EQ(s.players[0].body, -90);
  EXPECT_EQ(s.time, 42);
  EXPECT_FALSE(decode_showinfo_v1(std::string_view(b).substr(0, 315), s));
}

TEST(BinaryRecords, NamesWithoutNulAreBounded) {
  std::string b(kTeamPairSize, 'X');
  TeamInfo l, r;
  ASSERT_TRUE(decode_teams(b, l, r));
  EXPECT_EQ(l.name.size(), 16u);
}

TEST(BinaryRecords, ChangePlayerType) {
  std::array<std::int16_t, kMaxPlayers> types{};
  EXPECT_TRUE(apply_change_player_type("(change_player_type r 11 10)", types));
  EXPECT_EQ(types[player_index(Side::Right, 11)], 10);
  EXPECT_FALSE(apply_change_player_type("(change_player_type l 12 1)", types));
  EXPECT_FALSE(apply_change_player_type("(change_player_type l 3 goalie)", types));
  EXPECT_FALSE(apply_change_player_type("(referee kick_off_l)", types));
}

}  // namespace
}  // namespace mc::ingest::binary
