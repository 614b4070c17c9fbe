// A replay player steered by whatever a spectator sends: messages of the
// wrong shape are ignored, never thrown on (an exception on the relay's
// thread ends the server), and out-of-range numbers are clamped. The inputs
// are those replay_spectator_messages_fuzz found.
#include "server/replay/replay_player.hpp"
#include "server/relay/spectator_message.hpp"

#include <gtest/gtest.h>

#include <boost/asio/io_context.hpp>
#include <nlohmann/json.hpp>
#include <thread>

#include "tests/relay/channel_collector.hpp"

namespace mc::replay {
namespace {

// The player's seek window (replay_player.cpp).
constexpr std::chrono::milliseconds kWindow{50};

const std::string kGolden = std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/recording_v3.mcrec";

// What the session does with a spectator's text: read it once, then hand
// what it says to the replay.
void send(ReplayPlayer& p, std::string_view text) {
  if (const auto m = relay::read_spectator_message(text)) p.on_message(*m);
}

// The golden recording, open, and what it holds.
std::unique_ptr<record::RecordingReader> golden(RecordingSummary& summary) {
  auto reader = std::make_unique<record::RecordingReader>();
  std::string error;
  EXPECT_TRUE(reader->open(kGolden, error)) << error;
  EXPECT_TRUE(summarize(*reader, summary, error)) << error;
  return reader;
}

// A player of the golden recording, started. `summary_out` gets what the
// recording holds; `watch` everything the player's channel sends.
std::shared_ptr<ReplayPlayer> player(boost::asio::io_context& ioc, RecordingSummary* summary_out = nullptr,
                                     std::shared_ptr<relay::testing::ChannelCollector> watch = nullptr) {
  RecordingSummary summary;
  auto reader = golden(summary);
  if (summary_out) *summary_out = summary;
  auto p = std::make_shared<ReplayPlayer>(ioc.get_executor(), "golden.mcrec", std::move(reader), summary);
  if (watch) p->channel()->join(watch);
  p->start();
  return p;
}

// A started player of the golden recording and everything its channel
// sends; closed at the end.
class WatchedPlayer : public ::testing::Test {
 protected:
  void SetUp() override { p = player(ioc, &summary, collector); }
  void TearDown() override {
    p->close();
    ioc.poll();
  }
  boost::asio::io_context ioc;
  RecordingSummary summary;
  std::shared_ptr<relay::testing::ChannelCollector> collector = std::make_shared<relay::testing::ChannelCollector>();
  std::shared_ptr<ReplayPlayer> p;
};

TEST(ReplayPlayer, MessagesOfTheWrongShapeAreIgnoredNotThrownOn) {
  boost::asio::io_context ioc;
  auto p = player(ioc);
  for (const char* text : {R"({"type":1200})", R"({"type":null,"action":"seek"})", R"({"type":"replay","action":7})",
                           R"({"type":"replay"})", R"([1,2])", R"("replay")", "", "{", R"({"type":"replay","action":"seek","time":"x"})"}) {
    EXPECT_NO_THROW(send(*p, text)) << text;
  }
  EXPECT_FALSE(p->paused());
  send(*p, R"({"type":"replay","action":"pause"})");
  EXPECT_TRUE(p->paused());
  p->close();
  ioc.poll();
}

TEST(ReplayPlayer, ASeekFarOutsideTheRecordingIsClampedToIt) {
  boost::asio::io_context ioc;
  auto p = player(ioc);
  send(*p, R"({"type":"replay","action":"seek","time":1e300})");
  const int last = p->time();
  EXPECT_GT(last, 0);
  send(*p, R"({"type":"replay","action":"seek","time":-1e300})");
  EXPECT_LT(p->time(), last);
  p->close();
  ioc.poll();
}

// Scrubbing the seek bar sends a seek per mouse move, and each seek decodes
// from a keyframe: the player does the first of a 50 ms window at once and
// only the last of the rest, when the window ends. A flood of seeks costs
// two seeks, not a hundred, and ends where the spectator let go.
TEST_F(WatchedPlayer, AFloodOfSeeksIsDoneAsTheFirstAndTheLast) {
  ASSERT_GT(summary.last_time - summary.first_time, 2);
  send(*p, R"({"type":"replay","action":"pause"})");
  const auto frames = [&] {
    std::size_t n = 0;
    for (const auto& m : collector->snapshot()) n += m.binary() ? 1 : 0;
    return n;
  };
  const std::size_t before = frames();
  const int target = summary.first_time + 1;
  const auto start = std::chrono::steady_clock::now();
  for (int i = 0; i < 100; ++i) {
    const int t = i == 99 ? target : summary.last_time - i % 3;
    send(*p, R"({"type":"replay","action":"seek","time":)" + std::to_string(t) + "}");
  }
  // The flood takes about a millisecond; on a machine that stalls it
  // longer, each window that ends during it may do one more seek.
  const auto stalls = static_cast<std::size_t>((std::chrono::steady_clock::now() - start) / kWindow);
  EXPECT_GE(frames(), before + 1);  // the first seek's picture, at once
  EXPECT_LE(frames(), before + 1 + stalls);
  EXPECT_EQ(p->time(), target);     // the position is already the last one asked for
  ioc.run_for(std::chrono::milliseconds(300));
  const std::size_t settled = frames();
  EXPECT_GE(settled, before + 2);  // and the last seek's picture
  EXPECT_LE(settled, before + 2 + stalls);
  EXPECT_EQ(p->time(), target);
  EXPECT_TRUE(p->paused());
  // After a quiet window a seek is done at once again (run_for returned
  // when the paused player had nothing left to wait for).
  std::this_thread::sleep_for(kWindow + std::chrono::milliseconds(10));
  send(*p, R"({"type":"replay","action":"seek","time":)" + std::to_string(summary.last_time) + "}");
  EXPECT_EQ(frames(), settled + 1);
}

// Playing at speed 8 the player ticks every 6 ms: a drag then must still
// cost at most one seek per 50 ms window (a seek's picture is a keyframe;
// between seeks the player sends deltas, far fewer than its keyframe
// interval). It also checks that a replay's keyframes go out marked as
// keyframes, which a slow spectator's skip needs to resume.
TEST_F(WatchedPlayer, ADragWhilePlayingFastIsStillOneSeekPerWindow) {
  send(*p, R"({"type":"replay","action":"speed","speed":8})");
  const auto start = std::chrono::steady_clock::now();
  constexpr int kSeeks = 60;
  for (int i = 0; i < kSeeks; ++i) {
    // A seek every 2 ms or more, back and forth over the first cycles.
    send(*p, R"({"type":"replay","action":"seek","time":)" + std::to_string(summary.first_time + i % 3) + "}");
    ioc.run_for(std::chrono::milliseconds(2));
  }
  const auto elapsed = std::chrono::steady_clock::now() - start;
  p->close();  // no more frames from here
  std::size_t keyframes = 0;
  for (const auto& m : collector->snapshot()) keyframes += m.kind == relay::Message::Kind::Keyframe ? 1 : 0;
  const auto windows = static_cast<std::size_t>(elapsed / kWindow) + 1;
  EXPECT_GE(keyframes, 2u);  // the first seek's picture and at least one later one
  EXPECT_LE(keyframes, windows + 1)
      << kSeeks << " seeks in " << std::chrono::duration<double>(elapsed).count() << " s";
}

TEST(ReplayPlayer, ItsStatusIsTheJsonASpectatorsSeekBarReads) {
  // The status is written as text: it must read as the same JSON object a
  // tree would have written (nlohmann's own dump of it is byte for byte the
  // same), with every field a spectator uses. A name that needs escaping
  // stays a string.
  boost::asio::io_context ioc;
  RecordingSummary summary;
  auto reader = golden(summary);
  const std::size_t recorded = summary.goals.size();  // the golden game's own
  summary.goals.push_back({summary.first_time + 3, Side::Right});
  summary.goals.push_back({summary.first_time + 5, Side::Left});
  const std::string name = "g\"o\\al\n.mcrec";
  auto p = std::make_shared<ReplayPlayer>(ioc.get_executor(), name, std::move(reader), summary);
  auto collector = std::make_shared<relay::testing::ChannelCollector>();
  p->channel()->join(collector);
  p->start();
  send(*p, R"({"type":"replay","action":"speed","speed":0.5})");
  send(*p, R"({"type":"replay","action":"pause"})");
  p->close();
  ioc.poll();
  std::vector<nlohmann::json> statuses;
  for (const auto& m : collector->snapshot()) {
    if (m.binary()) continue;
    const auto j = nlohmann::json::parse(*m.bytes, nullptr, false);
    ASSERT_TRUE(j.is_object()) << *m.bytes;
    if (j.value("type", "") != "replay") continue;
    EXPECT_EQ(j.dump(), *m.bytes);
    statuses.push_back(j);
  }
  ASSERT_EQ(statuses.size(), 3u);  // start, speed, pause
  const auto& last = statuses.back();
  EXPECT_EQ(last["name"], name);
  EXPECT_EQ(last["paused"], true);
  EXPECT_EQ(last["speed"], 0.5);
  EXPECT_EQ(last["first_time"], summary.first_time);
  EXPECT_EQ(last["last_time"], summary.last_time);
  EXPECT_EQ(last["live_edge"], false);
  ASSERT_EQ(last["goals"].size(), recorded + 2);
  EXPECT_EQ(last["goals"][recorded]["side"], "r");
  EXPECT_EQ(last["goals"][recorded]["time"], summary.first_time + 3);
  EXPECT_EQ(last["goals"][recorded + 1]["side"], "l");
  EXPECT_EQ(statuses.front()["speed"], 1.0);
  EXPECT_EQ(statuses.front()["paused"], false);
}

}  // namespace
}  // namespace mc::replay
