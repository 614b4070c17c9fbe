// BroadcastPipeline: the wire order (metadata before a state's first frame,
// events before their frame), numbering from first_seq, the server times it
// is given, keyframes, equal output for equal input, and team names that
// are not UTF-8.
#include "server/app/broadcast_pipeline.hpp"

#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "anim/human_skeleton.hpp"
#include "proto/frame_codec.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::app {
namespace {

const std::string kLog =
    std::string(MATCHCAST_TEST_RCG_DIR) + "/generated/gen19-v6long-20261122030200-Alpha_2-vs-Beta_6.rcg.gz";

struct Item {
  bool frame = false, key = false;
  std::string bytes;
};

struct Collect : PipelineSink {
  std::vector<Item> items;
  void control(std::string json) override { items.push_back({false, false, std::move(json)}); }
  void frame(std::string bytes, bool key) override { items.push_back({true, key, std::move(bytes)}); }
};

// The whole log through a pipeline numbered from `first_seq`, frame n
// stamped 1000 + 50 n.
std::vector<Item> run(std::uint32_t first_seq, int keyframe_interval = 20) {
  std::string error;
  auto source = ingest::open_log(kLog, error);
  EXPECT_TRUE(source) << error;
  WorldState s;
  EXPECT_TRUE(source->next(s));
  PipelineOptions o;
  o.keyframe_interval = keyframe_interval;
  BroadcastPipeline p(source->params(), o, first_seq);
  Collect sink;
  auto stamp = [](std::uint32_t seq) { return 1000 + std::uint64_t{seq} * 50; };
  EXPECT_FALSE(p.has_frame());
  do {
    p.push(s);
    p.emit_all(stamp, sink);
  } while (source->next(s));
  p.finish();
  p.emit_all(stamp, sink);
  EXPECT_EQ(p.frames_emitted(), 2 * source->stats().shows);
  return sink.items;
}

TEST(BroadcastPipeline, MetadataThenFramesNumberedFromFirstSeqWithTheGivenTimes) {
  const auto items = run(5000);
  ASSERT_GT(items.size(), 4000u);
  // Before the first frame: teams, score, stamina (proto/SPEC.md 5.3).
  ASSERT_FALSE(items[0].frame);
  std::vector<std::string> types;
  for (std::size_t i = 0; i < items.size() && !items[i].frame; ++i)
    types.push_back(nlohmann::json::parse(items[i].bytes).at("type"));
  ASSERT_GE(types.size(), 3u);
  EXPECT_EQ(types[0], "teams");
  EXPECT_EQ(types[1], "score");
  EXPECT_EQ(types[2], "stamina");

  proto::FrameDecoder dec(anim::human_skeleton());
  std::uint32_t want_seq = 5000;
  int frames = 0, keys = 0, goals = 0, scores = 0;
  std::uint32_t last_frame_seq = 0;
  for (const Item& it : items) {
    if (!it.frame) {
      const auto j = nlohmann::json::parse(it.bytes);
      // A control message is numbered like the frame it goes out before.
      EXPECT_EQ(j.at("seq").get<std::uint32_t>(), want_seq) << it.bytes;
      goals += j.at("type") == "goal";
      scores += j.at("type") == "score";
      continue;
    }
    PoseFrame f;
    std::string error;
    ASSERT_TRUE(dec.decode(it.bytes, f, error)) << error;
    EXPECT_EQ(f.seq, want_seq);
    EXPECT_EQ(f.server_time_ms, 1000 + std::uint64_t{f.seq} * 50);
    EXPECT_EQ(it.key, frames % 20 == 0) << frames;
    keys += it.key;
    last_frame_seq = f.seq;
    ++want_seq;
    ++frames;
  }
  EXPECT_EQ(last_frame_seq, 5000u + frames - 1);
  EXPECT_EQ(goals, 8);           // 2-6
  EXPECT_EQ(scores, 1 + goals);  // the first, then one per goal
  EXPECT_EQ(keys, (frames + 19) / 20);
}

TEST(BroadcastPipeline, EqualInputEqualBytesAndOnlyTheNumberingDependsOnFirstSeq) {
  const auto a = run(0), b = run(0);
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) ASSERT_TRUE(a[i].bytes == b[i].bytes) << i;
  const auto c = run(0, 40);
  std::size_t keys = 0;
  for (const Item& it : c) keys += it.key;
  std::size_t keys_a = 0;
  for (const Item& it : a) keys_a += it.key;
  EXPECT_LT(keys, keys_a);
}

TEST(BroadcastPipeline, TeamNamesThatAreNotUtf8BecomeValidJson) {
  WorldState s;
  s.left.name = "\xff\xfe" "Alpha\xc3";  // stray bytes, a cut two-byte sequence
  s.right.name = "B\xc3\xa9ta";          // "Béta", valid
  const std::string hello = make_hello(s, GameParams{}, 20, "game\xff.rcg");
  const auto j = nlohmann::json::parse(hello);  // throws on invalid UTF-8
  EXPECT_EQ(j.at("teams").at("left").at("name"), "??Alpha?");
  EXPECT_EQ(j.at("teams").at("right").at("name"), "B\xc3\xa9ta");
  EXPECT_EQ(j.at("match_id"), "game?.rcg");
}

}  // namespace
}  // namespace mc::app
