// JSON logs: the element splitter (braces inside strings, cuts, over-long
// elements), the three flavours, and bad elements counted with offsets.
#include "server/ingest/json_splitter.hpp"
#include "server/ingest/json_records.hpp"

#include <gtest/gtest.h>

#include "server/ingest/state_source.hpp"
#include "tests/ingest/dribble_source.hpp"
#include "tests/ingest/test_data.hpp"

namespace mc::ingest {
namespace {

const char* kShow =
    R"({"show":{"time":5,"ball":{"x":1.5,"y":-0,"vx":0,"vy":0},"players":[{"side":"r","unum":3,"type":2,)"
    R"("state":4097,"x":10,"y":-2,"vx":0,"vy":0,"body":-90,"neck":30,"px":1,"py":2,"vq":"l","vw":60,)"
    R"("stamina":7000.5,"effort":0.9,"recovery":1,"capacity":1000,"fside":"l","fnum":9,"kick":1,"dash":2,)"
    R"("turn":3,"catch":0,"move":1,"turn_neck":0,"change_view":0,"say":0,"tackle":1,"pointto":0,)"
    R"("attentionto":0,"change_focus":0}]}})";

std::vector<WorldState> read(std::string_view bytes, IngestStats* st = nullptr) {
  std::string err;
  auto src = open_log_memory(bytes, err);
  EXPECT_TRUE(src) << err;
  std::vector<WorldState> v;
  WorldState s;
  while (src && src->next(s)) v.push_back(s);
  if (src && st) *st = src->stats();
  return v;
}

TEST(JsonSplitter, BracesInStringsAndCuts) {
  const std::string text = R"x([{"msg":{"message":"(x { } \" {)"}}, {"a":{"b":{}}}, {"cut":)x";
  auto src = open_memory_source(text);
  JsonSplitter sp(*src);
  std::string_view obj;
  std::uint64_t off = 0;
  ASSERT_EQ(sp.next(obj, off), JsonSplitter::Result::Object);
  EXPECT_EQ(obj, R"x({"msg":{"message":"(x { } \" {)"}})x");
  EXPECT_EQ(off, 1u);
  ASSERT_EQ(sp.next(obj, off), JsonSplitter::Result::Object);
  EXPECT_EQ(obj, R"({"a":{"b":{}}})");
  EXPECT_EQ(sp.next(obj, off), JsonSplitter::Result::Truncated);
  EXPECT_EQ(sp.next(obj, off), JsonSplitter::Result::End);
}

// The scan passes over the byte after a backslash in a string, whatever it
// is: also when the backslash is the last byte a read gave, and the quote
// or brace it escapes comes in the next read.
TEST(JsonSplitter, EscapesSplitAcrossReads) {
  const std::vector<std::string> objects = {R"({"m":"a\"{b\\"})", R"({"n":"\\"})", R"({"o":"}\"}{\\\""})",
                                            R"({"p":{"q":"\\}"}})"};
  std::string text = "[";
  for (const auto& o : objects) text += o + ",";
  text += "]";
  for (std::size_t step = 1; step <= 9; ++step) {
    DribbleSource src(text, step);
    JsonSplitter sp(src);
    std::string_view obj;
    std::uint64_t off = 0;
    for (const auto& want : objects) {
      ASSERT_EQ(sp.next(obj, off), JsonSplitter::Result::Object) << "step " << step << ", " << want;
      EXPECT_EQ(obj, want) << "step " << step;
      EXPECT_EQ(text.substr(off, want.size()), want);
    }
    EXPECT_EQ(sp.next(obj, off), JsonSplitter::Result::End) << "step " << step;
  }
}

TEST(JsonSplitter, OverlongElementsAreSkipped) {
  const std::string text = "[{\"a\":\"" + std::string(5000, 'x') + "\"},{\"b\":1}]";
  auto src = open_memory_source(text);
  JsonSplitter sp(*src, 1000);
  std::string_view obj;
  std::uint64_t off = 0;
  EXPECT_EQ(sp.next(obj, off), JsonSplitter::Result::TooLong);
  ASSERT_EQ(sp.next(obj, off), JsonSplitter::Result::Object);
  EXPECT_EQ(obj, "{\"b\":1}");
}

TEST(JsonLogSource, Flavour19Fields) {
  const std::string log = std::string("[\n{\"version\":\"19.0.0\"},\n{\"playmode\":{\"time\":1,\"mode\":\"play_on\"}},\n"
                                      "{\"team\":{\"time\":1,\"l\":{\"name\":\"A\",\"score\":1},\"r\":{\"name\":\"B\",\"score\":2}}},\n") +
                          kShow + "\n]";
  const auto v = read(log);
  ASSERT_EQ(v.size(), 1u);
  const WorldState& s = v[0];
  EXPECT_EQ(s.play_mode, PlayMode::PlayOn);
  EXPECT_EQ(s.right.score, 2);
  const PlayerState& p = s.players[player_index(Side::Right, 3)];
  EXPECT_EQ(p.state, 4097u);
  EXPECT_EQ(p.view_quality, 'l');
  ASSERT_TRUE(p.point && p.capacity && p.attention);
  EXPECT_EQ(p.attention->second, 9);
  EXPECT_EQ(p.counters.count, 12);
  EXPECT_EQ(p.counters.tackle, 1u);
  EXPECT_EQ(s.players[0].state, 0u);  // absent slot
}

TEST(JsonLogSource, Flavours17And18) {
  const std::string show17 =
      R"({"type":"show","time":7,"ball":{"x":0,"y":0},"players":[]})";
  EXPECT_EQ(read("ULG6\n[\n" + show17 + "\n]").size(), 1u);
  EXPECT_EQ(read("JSON\n[\n{\"type\":\"header\"},\n" + show17 + "\n]").size(), 1u);
}

TEST(JsonLogSource, BadElementsAreCountedAndSkipped) {
  IngestStats st;
  const std::string log = std::string("[\n{\"show\":{\"time\":\"x\"}},\n{not json},\n") + kShow + ",\n" + kShow;
  const auto v = read(log.substr(0, log.size() - 10), &st);  // last one cut
  EXPECT_EQ(v.size(), 1u);
  EXPECT_EQ(st.skipped, 3u);
  ASSERT_EQ(st.errors.size(), 3u);
  EXPECT_NE(st.errors[0].find("offset 2"), std::string::npos) << st.errors[0];
}

// Every bad element is counted; the first kMaxErrors keep their message (and
// only those are written), the rest are a count.
TEST(JsonLogSource, ManyBadElementsAreAllCountedAndTheFirstNamed) {
  const std::size_t bad = IngestStats::kMaxErrors + 50;
  std::string log = "[\n";
  std::vector<std::size_t> offsets;
  for (std::size_t k = 0; k < bad; ++k) {
    offsets.push_back(log.size());
    log += "{\"show\":{\"time\":\"x\"}},\n";
  }
  log += std::string(kShow) + "\n]";
  IngestStats st;
  EXPECT_EQ(read(log, &st).size(), 1u);
  EXPECT_EQ(st.skipped, bad);
  ASSERT_EQ(st.errors.size(), IngestStats::kMaxErrors);
  const std::string last_kept = st.errors.back();
  EXPECT_EQ(last_kept, "element at offset " + std::to_string(offsets[IngestStats::kMaxErrors - 1]) +
                           ": bad show record");
}

TEST(JsonLogSource, RealLogTruncated) {
  const std::string all = testing::decoded(testing::rcg("generated/gen19-json-20261122030023-Alpha_1-vs-Beta_1.rcg.gz"));
  IngestStats st;
  const auto v = read(std::string_view(all).substr(0, all.size() / 2), &st);
  EXPECT_GT(v.size(), 200u);
  EXPECT_LT(v.size(), 699u);
  EXPECT_EQ(st.skipped, 1u);
}

}  // namespace
}  // namespace mc::ingest

// decode_json_record reads a flat tree built by nlohmann's SAX parser (no
// DOM per record). It must read what the DOM read: where a key repeats the
// last one counts, a record of two top-level keys and no "type" is not a
// kind, and a value of the wrong type fails the record.
namespace mc::ingest {
namespace {

struct Decoded {
  bool ok = false;
  RecordKind kind = RecordKind::Other;
  WorldState state;
  GameContext ctx;
  MessageRecord msg;
  std::string error;
};

Decoded decode(const std::string& text) {
  Decoded d;
  d.ok = decode_json_record(text, d.ctx, d.state, d.msg, d.kind, d.error);
  return d;
}

const std::string kBall = R"("ball":{"x":1.5,"y":-2})";

TEST(JsonRecords, RepeatedKeysTakeTheLast) {
  Decoded d = decode(R"({"show":{"time":1,)" + kBall + R"(,"players":[]},"show":{"time":2,)" + kBall +
                     R"(,"players":[]}})");
  EXPECT_TRUE(d.ok) << d.error;
  EXPECT_EQ(d.kind, RecordKind::Show);
  EXPECT_EQ(d.state.time, 2);
  // A player's "x" first as text, then as a number: the number counts.
  d = decode(R"({"show":{"time":3,)" + kBall +
             R"(,"players":[{"side":"l","unum":4,"type":0,"state":1,"x":"far","x":7.25,"y":1}]}})");
  EXPECT_TRUE(d.ok) << d.error;
  EXPECT_DOUBLE_EQ(d.state.players[3].x, 7.25);
  // And the other way round: the record fails.
  d = decode(R"({"show":{"time":3,)" + kBall +
             R"(,"players":[{"side":"l","unum":4,"type":0,"state":1,"x":7.25,"x":"far","y":1}]}})");
  EXPECT_FALSE(d.ok);
  EXPECT_EQ(d.error, "bad show record");
  // "type" repeated: the last names the kind.
  d = decode(R"({"type":"msg","type":"playmode","mode":"play_on"})");
  EXPECT_TRUE(d.ok) << d.error;
  EXPECT_EQ(d.kind, RecordKind::PlayMode);
  EXPECT_EQ(d.ctx.play_mode, PlayMode::PlayOn);
}

TEST(JsonRecords, WhatIsNotARecordKind) {
  Decoded d = decode(R"({"show":{"time":1,)" + kBall + R"(,"players":[]},"version":"19"})");
  EXPECT_TRUE(d.ok);
  EXPECT_EQ(d.kind, RecordKind::Other);
  d = decode(R"({"show":[1,2]})");
  EXPECT_TRUE(d.ok);
  EXPECT_EQ(d.kind, RecordKind::Other);
  // Not an object, two values, cut short, empty, a number past double's range.
  // And strings that are not UTF-8: a lone surrogate's escape, its bytes,
  // a byte no UTF-8 has; and a NUL with text after it.
  for (const std::string& bad :
       {std::string(R"({"show":{"time":1})"), std::string("[1,2]"), std::string(R"({"a":1} {"b":2})"), std::string(),
        std::string(R"({"a":1e999})"), std::string(R"({"msg":{"time":1,"message":"\udc00"}})"),
        std::string(R"({"msg":{"time":1,"message":"\ud800"}})"), std::string("{\"msg\":{\"message\":\"\xed\xa0\x80\"}}"),
        std::string("{\"msg\":{\"message\":\"\xff\"}}"), std::string("{\"a\":1}\0{\"b\":2}", 15)}) {
    d = decode(bad);
    EXPECT_FALSE(d.ok) << bad;
    EXPECT_EQ(d.error, "invalid JSON") << bad;
  }
  // A surrogate pair is one code point, and reads as its UTF-8.
  d = decode(R"({"msg":{"time":1,"message":"\ud83d\ude00"}})");
  EXPECT_TRUE(d.ok) << d.error;
  EXPECT_EQ(d.msg.text, "\xf0\x9f\x98\x80");
  // The server parameters, numbers and flags as the DOM wrote them.
  d = decode(R"({"server_param":{"ball_size":0.085,"goal_width":14.02,"synch_mode":true,"x":null,"v":"a","v":"b"}})");
  EXPECT_TRUE(d.ok);
  EXPECT_EQ(d.ctx.params.server.text("ball_size"), "0.085");
  EXPECT_EQ(d.ctx.params.server.text("synch_mode"), "1");
  EXPECT_EQ(d.ctx.params.server.text("v"), "b");
  EXPECT_FALSE(d.ctx.params.server.has("x"));
}

// A hostile record of many keys, 7 MB (a log's records may be 8 MB): reading
// it must not compare every key with every other. The pairwise check took
// 14 s on 100,000 keys, so about 6 min on these 500,000: past the test's
// 300-s timeout. Sorted, it takes about a second.
TEST(JsonRecords, HalfAMillionKeysReadInOnePass) {
  std::string text = R"({"server_param":{)";
  for (int i = 0; i < 500000; ++i) text += "\"k" + std::to_string(i) + "\":" + std::to_string(i) + ",";
  text += R"("k7":"last"}})";
  const Decoded d = decode(text);
  EXPECT_TRUE(d.ok) << d.error;
  EXPECT_EQ(d.ctx.params.server.all().size(), 500000u);
  EXPECT_EQ(d.ctx.params.server.text("k499999"), "499999");
  EXPECT_EQ(d.ctx.params.server.text("k7"), "last");
}

}  // namespace
}  // namespace mc::ingest
