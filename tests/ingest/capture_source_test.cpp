// Monitor captures replayed through the live parser (MonitorStream) give
// the same states as the log of the game they watched.
#include "server/ingest/capture_source.hpp"

#include <gtest/gtest.h>

#include <vector>

#include "server/ingest/state_source.hpp"
#include "server/ingest/monitor_stream.hpp"
#include "tests/ingest/state_compare.hpp"
#include "tests/ingest/test_data.hpp"

namespace mc::ingest {
namespace {

using testing::Tolerance;
const std::string kGen = std::string(MATCHCAST_TEST_RCG_DIR) + "/generated/";

std::vector<WorldState> read_all(std::unique_ptr<StateSource> src, bool drop_before_kick_off,
                                 IngestStats* stats = nullptr) {
  std::vector<WorldState> v;
  WorldState s;
  while (src->next(s))
    if (!drop_before_kick_off || s.play_mode != PlayMode::BeforeKickOff) v.push_back(s);
  if (stats) *stats = src->stats();
  return v;
}

std::vector<WorldState> log_states(const std::string& file) {
  std::string err;
  auto src = open_log(kGen + file, err);
  EXPECT_TRUE(src) << err;
  return src ? read_all(std::move(src), false) : std::vector<WorldState>{};
}

// Every log show must appear in the capture, in order; the capture has more
// (before_kick_off lineups, time_over shows until the server exits).
void expect_capture_matches_log(const std::string& capture, const std::string& log, const Tolerance& tol,
                                std::size_t expected_capture_shows = 0) {
  std::string err;
  auto src = open_monitor_capture(kGen + capture, err);
  ASSERT_TRUE(src) << err;
  IngestStats stats;
  const auto mon = read_all(std::move(src), true, &stats);
  EXPECT_EQ(stats.skipped, 0u) << (stats.errors.empty() ? "" : stats.errors[0]);
  if (expected_capture_shows != 0) {
    EXPECT_EQ(stats.shows, expected_capture_shows);
  }
  const auto ref = log_states(log);
  ASSERT_FALSE(ref.empty());
  ASSERT_GE(mon.size(), ref.size());
  for (std::size_t i = 0; i < ref.size(); ++i) {
    const std::string diff = testing::first_difference(ref[i], mon[i], tol);
    ASSERT_EQ(diff, "") << "show " << i;
  }
  // The rest is the server idling after time_over.
  for (std::size_t i = ref.size(); i < mon.size(); ++i) EXPECT_EQ(mon[i].play_mode, PlayMode::TimeOver);
}

TEST(CaptureSource, V5MatchesUlg6Log) {
  expect_capture_matches_log("mon19-v5.dgrams.gz", "gen19-v6long-20261122030200-Alpha_2-vs-Beta_6.rcg.gz",
                             Tolerance{}, 2488);
}

TEST(CaptureSource, V4MatchesUlg5Log) {
  expect_capture_matches_log("mon19-v4.dgrams.gz", "gen19-v5-20261122025405-Alpha_0-vs-Beta_0.rcg.gz", Tolerance{});
}

TEST(CaptureSource, V3MatchesUlg4Log) {
  expect_capture_matches_log("mon19-v3.dgrams.gz", "gen19-v4-20261122025515-Alpha_1-vs-Beta_0.rcg.gz", Tolerance{});
}

TEST(CaptureSource, JsonMatchesUlg6Log) {
  Tolerance t;
  t.counters = false;  // JSON monitor shows carry no command counters
  expect_capture_matches_log("mon19-json.dgrams.gz", "gen19-v6-20261122025254-Alpha_0-vs-Beta_0.rcg.gz", t, 678);
}

TEST(CaptureSource, BinaryV2MatchesUlg6LogWithinQuantisation) {
  Tolerance t;
  t.pos = 1e-4;          // text is quantised to 1e-4, binary to 1/65536
  t.angle = 2e-3;        // text 1e-3 deg, binary radians/65536
  t.stamina = 1e-4;
  t.state_mask = 0xffff;  // 16-bit state field
  t.capacity = false;
  t.counters = false;     // 8 binary counters vs 12 text
  t.details = false;      // no arm / focus / attention in binary
  expect_capture_matches_log("mon19-v2.dgrams.gz", "gen19-v6-20261122025254-Alpha_0-vs-Beta_0.rcg.gz", t);
}

TEST(CaptureSource, BinaryV1MatchesUlg6LogWithinQuantisation) {
  Tolerance t;
  t.pos = 1.0 / 16 + 1e-4;  // SHOWINFO_SCALE 16
  t.angle = 1.0 + 1e-3;     // integer degrees
  t.state_mask = 0xffff;
  t.velocities = t.details = t.capacity = t.counters = false;
  expect_capture_matches_log("mon19-v1.dgrams.gz", "gen19-v6-20261122025254-Alpha_0-vs-Beta_0.rcg.gz", t);
}

TEST(CaptureSource, MixedV3V5CacheBugParsesBoth) {
  std::string err;
  auto a = open_monitor_capture(kGen + "mon19-mixed-v3-with-v5-attached.dgrams.gz", err);
  auto b = open_monitor_capture(kGen + "mon19-mixed-v5-with-v3-attached.dgrams.gz", err);
  ASSERT_TRUE(a && b) << err;
  IngestStats sa, sb;
  const auto va = read_all(std::move(a), false, &sa);
  const auto vb = read_all(std::move(b), false, &sb);
  EXPECT_EQ(sa.shows, 178u);
  EXPECT_EQ(sb.shows, 178u);
  EXPECT_EQ(sa.skipped + sb.skipped, 0u);
  ASSERT_EQ(va.size(), vb.size());
  int with_fp = 0;
  for (std::size_t i = 0; i < va.size(); ++i) {
    EXPECT_EQ(testing::first_difference(va[i], vb[i], Tolerance{}), "");
    with_fp += va[i].players[0].focus_point.has_value();
  }
  EXPECT_EQ(with_fp, 102);  // v5-formatted shows, per the data README
}

TEST(CaptureSource, ParamsArriveBeforeShows) {
  std::string err;
  auto src = open_monitor_capture(kGen + "mon19-v2.dgrams.gz", err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  ASSERT_TRUE(src->next(s));
  EXPECT_EQ(src->params().player_types.size(), 18u);
  EXPECT_NEAR(src->params().goal_width(), 14.02, 1e-4);
  EXPECT_NEAR(src->params().server.number("half_time", 0), 30, 1e-9);
  EXPECT_EQ(s.play_mode, PlayMode::BeforeKickOff);
}

// live-capture/*.txt.gz: "#N t=.. from=.. size=.." then the payload as text.
struct LiveReplay {
  IngestStats stats;
  std::vector<WorldState> states;
  GameParams params;
};
LiveReplay replay_text_dump(const std::string& file) {
  const std::string text = testing::decoded(testing::rcg("live-capture/" + file));
  MonitorStream stream;
  LiveReplay r;
  std::size_t pos = 0;
  std::string payload;
  bool in_record = false;
  auto flush = [&] {
    while (!payload.empty() && payload.back() == '\n') payload.pop_back();
    // The dump prints the terminating NUL as the two characters "\0".
    if (payload.size() >= 2 && payload.compare(payload.size() - 2, 2, "\\0") == 0)
      payload.replace(payload.size() - 2, 2, 1, '\0');
    WorldState s;
    if (in_record && stream.push(payload, s)) r.states.push_back(s);
    payload.clear();
  };
  while (pos < text.size()) {
    std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) nl = text.size();
    const std::string_view line(text.data() + pos, nl - pos);
    pos = nl + 1;
    if (!line.empty() && line[0] == '#') {
      flush();
      in_record = line.size() > 1 && line[1] != ' ';  // "#N ..." opens a record
      continue;
    }
    if (!payload.empty()) payload += '\n';
    payload += line;
  }
  flush();
  r.stats = stream.stats();
  r.params = stream.params();
  return r;
}

TEST(CaptureSource, LiveHeliosCaptureV5) {
  const LiveReplay r = replay_text_dump("helios-live-monitor-v5.txt.gz");
  EXPECT_EQ(r.stats.skipped, 0u) << (r.stats.errors.empty() ? "" : r.stats.errors[0]);
  ASSERT_GT(r.states.size(), 150u);
  EXPECT_EQ(r.params.player_types.size(), 18u);
  EXPECT_EQ(r.states.back().left.name, "HELIOS_A");
  EXPECT_EQ(r.states.back().time, 435);
  EXPECT_TRUE(r.states.back().players[0].focus_point.has_value());
}

TEST(CaptureSource, LivePregameCaptureV4) {
  const LiveReplay r = replay_text_dump("helios-live-monitor-v4-pregame.txt.gz");
  EXPECT_EQ(r.stats.skipped, 0u) << (r.stats.errors.empty() ? "" : r.stats.errors[0]);
  ASSERT_GT(r.states.size(), 100u);
  EXPECT_EQ(r.states[0].play_mode, PlayMode::BeforeKickOff);
  // 29 lineup shows at time 0 (time does not advance before kick-off).
  EXPECT_EQ(r.states[28].time, 0);
  EXPECT_EQ(r.states[28].stoppage, 28);
  EXPECT_EQ(r.states[29].time, 1);
  EXPECT_EQ(r.states[29].stoppage, 0);
  EXPECT_EQ(r.states[29].play_mode, PlayMode::KickOffL);
  EXPECT_TRUE(r.states[29].players[0].capacity.has_value());   // v4
  EXPECT_FALSE(r.states[29].players[0].focus_point.has_value());
}

}  // namespace
}  // namespace mc::ingest
