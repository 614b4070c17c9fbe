// The NATS envelope and subject names: round trips, and every malformed
// input refused with a reason (an edge reads whatever is on the subject).
#include "server/nats/envelope.hpp"

#include <gtest/gtest.h>

#include "server/nats/subjects.hpp"

namespace mc::nats {
namespace {

TEST(NatsEnvelope, RoundTripKeepsKindNumberAndBytes) {
  const std::string payload("\x4d\x01\x00\x01 frame bytes \xff", 18);
  for (Kind k : {Kind::Hello, Kind::Keyframe, Kind::Delta, Kind::Control}) {
    const std::string w = wrap(k, 0x0102030405060708ull, payload);
    ASSERT_EQ(w.size(), kEnvelopeHeaderSize + payload.size());
    Envelope e;
    std::string error;
    ASSERT_TRUE(unwrap(w, e, error)) << error;
    EXPECT_EQ(e.kind, k);
    EXPECT_EQ(e.number, 0x0102030405060708ull);
    EXPECT_EQ(e.payload, payload);
  }
  // Little-endian number right after the kind byte, as README.md documents.
  const std::string w = wrap(Kind::Delta, 1, "");
  EXPECT_EQ(w, std::string("D\x01\0\0\0\0\0\0\0", 9));
}

TEST(NatsEnvelope, RefusesShortUnknownAndOversizedInput) {
  Envelope e;
  std::string error;
  EXPECT_FALSE(unwrap("", e, error));
  EXPECT_NE(error.find("shorter"), std::string::npos);
  EXPECT_FALSE(unwrap(std::string("K\1\0\0\0\0\0\0", 8), e, error));
  error.clear();
  EXPECT_FALSE(unwrap(std::string("X\1\0\0\0\0\0\0\0payload", 16), e, error));
  EXPECT_NE(error.find("unknown envelope kind"), std::string::npos);
  EXPECT_FALSE(unwrap(wrap(Kind::Delta, 1, std::string(kMaxPayload + 1, 'x')), e, error));
  EXPECT_NE(error.find("too large"), std::string::npos);
  EXPECT_TRUE(unwrap(wrap(Kind::Delta, 1, std::string(kMaxPayload, 'x')), e, error));
}

TEST(NatsEnvelope, SnapshotRoundTripWithAndWithoutKeyframe) {
  Envelope e;
  Snapshot s;
  std::string error;
  const std::string both = wrap_snapshot(42, "{\"type\":\"hello\"}", "KEYFRAME");
  ASSERT_TRUE(unwrap(both, e, error));
  ASSERT_TRUE(unwrap_snapshot(e, s, error)) << error;
  EXPECT_EQ(e.number, 42u);
  EXPECT_EQ(s.hello, "{\"type\":\"hello\"}");
  EXPECT_EQ(s.keyframe, "KEYFRAME");
  const std::string hello_only = wrap_snapshot(7, "{}", "");
  ASSERT_TRUE(unwrap(hello_only, e, error));
  ASSERT_TRUE(unwrap_snapshot(e, s, error));
  EXPECT_EQ(s.hello, "{}");
  EXPECT_TRUE(s.keyframe.empty());
}

TEST(NatsEnvelope, SnapshotRefusesBadLengths) {
  Envelope e;
  Snapshot s;
  std::string error;
  // Hello length past the end, zero hello, too short, and the wrong kind.
  for (const std::string& payload : {std::string("\xff\0\0\0{}", 6), std::string("\0\0\0\0key", 7),
                                     std::string("\1\0", 2)}) {
    ASSERT_TRUE(unwrap(wrap(Kind::Snapshot, 1, payload), e, error));
    EXPECT_FALSE(unwrap_snapshot(e, s, error)) << payload.size();
  }
  ASSERT_TRUE(unwrap(wrap(Kind::Keyframe, 1, "xxxx"), e, error));
  EXPECT_FALSE(unwrap_snapshot(e, s, error));
}

TEST(NatsSubjects, NamesAndParsing) {
  EXPECT_EQ(live_subject("matchcast", "final"), "matchcast.final.live");
  EXPECT_EQ(key_subject("mc.eu", "g1"), "mc.eu.g1.key");
  EXPECT_EQ(live_wildcard("matchcast"), "matchcast.*.live");
  EXPECT_EQ(key_wildcard("matchcast"), "matchcast.*.key");
  EXPECT_EQ(stream_name("matchcast"), "MATCHCAST_KEY");
  EXPECT_EQ(stream_name("mc.eu"), "MC_EU_KEY");
  EXPECT_EQ(game_of_live_subject("matchcast", "matchcast.final-2.live"), "final-2");
  EXPECT_EQ(game_of_live_subject("matchcast", "matchcast.final.key"), "");
  EXPECT_EQ(game_of_live_subject("matchcast", "other.final.live"), "");
  EXPECT_EQ(game_of_live_subject("matchcast", "matchcast.a.b.live"), "");
  EXPECT_EQ(game_of_live_subject("matchcast", "matchcast..live"), "");
  EXPECT_EQ(game_of_live_subject("matchcast", "matchcastX.g.live"), "");
}

TEST(NatsSubjects, ValidNames) {
  EXPECT_TRUE(valid_game("live"));
  EXPECT_TRUE(valid_game("Final_2026-a"));
  for (const char* bad : {"", "a.b", "*", ">", "a b", "a\n"}) EXPECT_FALSE(valid_game(bad)) << bad;
  EXPECT_FALSE(valid_game(std::string(65, 'a')));
  EXPECT_TRUE(valid_prefix("matchcast"));
  EXPECT_TRUE(valid_prefix("mc.eu-1"));
  for (const char* bad : {"", ".", "a.", ".a", "a..b", "a.*", "a.>"}) EXPECT_FALSE(valid_prefix(bad)) << bad;
}

}  // namespace
}  // namespace mc::nats
