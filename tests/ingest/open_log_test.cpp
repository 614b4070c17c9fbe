// open_log() over every file in tests/data/rcg/: format sniffing and the
// values listed in that folder's README (shows, time range, final score,
// team names, play-mode changes).
#include "server/ingest/state_source.hpp"

#include <gtest/gtest.h>

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <future>
#include <iterator>
#include <sstream>
#include <thread>
#include <vector>

namespace mc::ingest {
namespace {

const std::string kData = std::string(MATCHCAST_TEST_RCG_DIR) + "/";

struct Expected {
  std::string file;
  std::uint64_t shows;
  int first_time, last_time;
  std::string left, right;  // "" = null team
  int lscore, rscore;
  std::vector<PlayMode> must_see;  // play modes that must occur
};

struct Summary {
  std::uint64_t shows = 0;
  int first_time = -1, last_time = -1;
  WorldState last;
  std::vector<PlayMode> modes;  // distinct, in order of first appearance
  int max_stoppage = 0;
  std::uint64_t skipped = 0;
  std::vector<std::string> messages;
  std::string first_error;
};

Summary summarise(const std::string& path) {
  Summary s;
  std::string err;
  auto src = open_log(path, err);
  EXPECT_TRUE(src) << err;
  if (!src) return s;
  WorldState w;
  std::uint64_t expect_index = 0;
  int prev_time = -1000;
  while (src->next(w)) {
    EXPECT_EQ(w.index, expect_index++);
    EXPECT_GE(w.time, prev_time) << "time goes back at index " << w.index;
    prev_time = w.time;
    if (s.first_time < 0) s.first_time = w.time;
    s.last_time = w.time;
    s.max_stoppage = std::max(s.max_stoppage, w.stoppage);
    if (std::find(s.modes.begin(), s.modes.end(), w.play_mode) == s.modes.end())
      s.modes.push_back(w.play_mode);
    s.last = w;
    SourceEvent ev;
    while (src->poll_event(ev)) s.messages.push_back(ev.message.text);
  }
  SourceEvent ev;
  while (src->poll_event(ev)) s.messages.push_back(ev.message.text);
  s.shows = src->stats().shows;
  s.skipped = src->stats().skipped;
  if (!src->stats().errors.empty()) s.first_error = src->stats().errors[0];
  return s;
}

using PM = PlayMode;
const std::vector<Expected> kExpected = {
    {"full/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz", 6689, 1, 6000, "HELIOS_A", "HELIOS_B", 1, 5,
     {PM::KickOffL, PM::GoalR, PM::GoalL, PM::FoulChargeL, PM::TimeOver}},
    {"full/20261122031059-HELIOS_A_4-vs-HELIOS_B_3.rcg.gz", 6889, 1, 6000, "HELIOS_A", "HELIOS_B", 4, 3,
     {PM::KickOffL, PM::GoalR, PM::GoalL, PM::TimeOver}},
    {"real/20190926074949-HELIOS_base_0-vs-kn2c_4.rcg.gz", 1140, 1, 940, "HELIOS_base", "kn2c", 0, 4,
     {PM::KickOffL, PM::GoalR}},
    {"real/20190926072846-HELIOS_base_1-vs-kn2c_0.rcg.gz", 706, 1, 626, "HELIOS_base", "kn2c", 1, 0,
     {PM::FoulChargeR, PM::FreeKickL, PM::KickInL}},
    {"real/20200428141309-HELIOS_base_2-vs-null.rcg.gz", 343, 1, 277, "HELIOS_base", "", 2, 0,
     {PM::GoalL}},
    {"real/20190314135110-CYRUS_0-vs-HELIOS2018_1.rcg.gz", 540, 1, 485, "CYRUS", "HELIOS2018", 0, 1, {}},
    {"real/incomplete-PSG_3-vs-Real_1.rcg.gz", 1698, 1, 1433, "PSG", "Real", 3, 1,
     {PM::FreeKickFaultL}},
    {"real/201811102352-Time_Santa_3-vs-Time_Sprot_0.rcg.gz", 594, 1, 441, "Time_Santa", "Time_Sprot", 3, 0,
     {PM::PlayOn}},
    {"generated/gen19-v1-20261122025913-Alpha_0-vs-Beta_0.rcg.gz", 599, 1, 600, "Alpha", "Beta", 0, 0,
     {PM::KickOffL, PM::TimeOver}},
    {"generated/gen19-v2-20261122025747-Alpha_1-vs-Beta_2.rcg.gz", 749, 1, 600, "Alpha", "Beta", 1, 2,
     {PM::GoalL, PM::GoalR}},
    {"generated/gen19-v3-20261122025631-Alpha_0-vs-Beta_1.rcg.gz", 649, 1, 600, "Alpha", "Beta", 0, 1,
     {PM::GoalR}},
    {"generated/gen19-v4-20261122025515-Alpha_1-vs-Beta_0.rcg.gz", 649, 1, 600, "Alpha", "Beta", 1, 0,
     {PM::GoalL}},
    {"generated/gen19-v5-20261122025405-Alpha_0-vs-Beta_0.rcg.gz", 599, 1, 600, "Alpha", "Beta", 0, 0, {}},
    {"generated/gen19-v6-20261122025254-Alpha_0-vs-Beta_0.rcg.gz", 599, 1, 600, "Alpha", "Beta", 0, 0, {}},
    {"generated/gen19-v6long-20261122030200-Alpha_2-vs-Beta_6.rcg.gz", 2409, 1, 1800, "Alpha", "Beta", 2, 6,
     {PM::GoalL, PM::GoalR, PM::FreeKickFaultL, PM::FreeKickFaultR, PM::GoalKickL}},
    {"generated/gen19-json-20261122030023-Alpha_1-vs-Beta_1.rcg.gz", 699, 1, 600, "Alpha", "Beta", 1, 1,
     {PM::GoalL, PM::GoalR}},
};

class EveryLog : public ::testing::TestWithParam<Expected> {};

TEST_P(EveryLog, MatchesReadme) {
  const Expected& e = GetParam();
  const Summary s = summarise(kData + e.file);
  EXPECT_EQ(s.shows, e.shows);
  EXPECT_EQ(s.first_time, e.first_time);
  EXPECT_EQ(s.last_time, e.last_time);
  EXPECT_EQ(s.last.left.name, e.left);
  EXPECT_EQ(s.last.right.name, e.right);
  EXPECT_EQ(s.last.left.score, e.lscore);
  EXPECT_EQ(s.last.right.score, e.rscore);
  EXPECT_EQ(s.skipped, 0u) << s.first_error;
  for (PlayMode pm : e.must_see)
    EXPECT_NE(std::find(s.modes.begin(), s.modes.end(), pm), s.modes.end())
        << "play mode " << play_mode_name(pm) << " never seen";
}

INSTANTIATE_TEST_SUITE_P(Rcg, EveryLog, ::testing::ValuesIn(kExpected),
                         [](const auto& info) {
                           std::string n = info.param.file.substr(info.param.file.find('/') + 1, 24);
                           for (char& c : n)
                             if (!std::isalnum(static_cast<unsigned char>(c))) c = '_';
                           return n + "_" + std::to_string(info.index);
                         });

// A log that can be read only once, such as `--log <(zcat game.rcg.gz)` or
// a named pipe: open_log() sniffs its first bytes and hands the parser the
// same stream. (It used to open the path a second time for the parser: the
// writer of a pipe then met a closed reader, and the second open waited for
// a writer that never came.)
TEST(OpenLog, APipeIsReadOnceAndWhole) {
  const std::string file = kData + "generated/gen19-json-20261122030023-Alpha_1-vs-Beta_1.rcg.gz";
  const Summary want = summarise(file);
  ASSERT_EQ(want.shows, 699u);
  char dir[] = "/tmp/mc-open-log-pipe-XXXXXX";
  ASSERT_NE(::mkdtemp(dir), nullptr);
  const std::string fifo = std::string(dir) + "/log";
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::signal(SIGPIPE, SIG_IGN);  // a closed reader is an error to the writer, not a signal
  std::thread writer([&] {
    std::ifstream in(file, std::ios::binary);
    const std::string bytes{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
    const int fd = ::open(fifo.c_str(), O_WRONLY);
    if (fd < 0) return;
    for (std::size_t at = 0; at < bytes.size();) {
      const ssize_t k = ::write(fd, bytes.data() + at, bytes.size() - at);
      if (k <= 0) break;
      at += static_cast<std::size_t>(k);
    }
    ::close(fd);
  });
  std::promise<Summary> done;
  auto got = done.get_future();
  std::thread reader([&] { done.set_value(summarise(fifo)); });
  if (got.wait_for(std::chrono::seconds(20)) != std::future_status::ready) {
    ADD_FAILURE() << "open_log() is waiting for a second writer of the pipe";
    const int fd = ::open(fifo.c_str(), O_WRONLY | O_NONBLOCK);  // lets it see the end
    if (fd >= 0) ::close(fd);
  }
  writer.join();
  reader.join();
  const Summary s = got.get();
  EXPECT_EQ(s.shows, want.shows);
  EXPECT_EQ(s.last_time, want.last_time);
  EXPECT_EQ(s.last.left.score, want.last.left.score);
  EXPECT_EQ(s.last.right.score, want.last.right.score);
  std::filesystem::remove_all(dir);
}

TEST(OpenLog, FileWithNoShows) {
  const Summary s = summarise(kData + "real/20190926071807-HELIOS_base_0-vs-null.rcg");
  EXPECT_EQ(s.shows, 0u);
  ASSERT_FALSE(s.messages.empty());
  EXPECT_NE(s.messages.back().find("(result "), std::string::npos);
}

TEST(OpenLog, HandTruncatedFileJumpsToResult) {
  const Summary s = summarise(kData + "real/20190314135110-CYRUS_0-vs-HELIOS2018_1.rcg.gz");
  ASSERT_FALSE(s.messages.empty());
  EXPECT_EQ(s.messages.back(), "(result 201903141351 CYRUS_0-vs-HELIOS2018_1)");
}

TEST(OpenLog, DisconnectedPlayersAreParked) {
  // HELIOS_base vs null: the right team never connected.
  const Summary s = summarise(kData + "real/20200428141309-HELIOS_base_2-vs-null.rcg.gz");
  for (int u = 1; u <= 11; ++u) {
    const PlayerState& p = s.last.players[player_index(Side::Right, u)];
    EXPECT_FALSE(p.active());
    EXPECT_DOUBLE_EQ(p.y, -37.0);
  }
}

TEST(OpenLog, SevenPlayerTeams) {
  std::string err;
  auto src = open_log(kData + "real/201811102352-Time_Santa_3-vs-Time_Sprot_0.rcg.gz", err);
  ASSERT_TRUE(src) << err;
  WorldState s;
  ASSERT_TRUE(src->next(s));
  int left = 0, right = 0;
  for (int u = 1; u <= 11; ++u) {
    left += s.players[player_index(Side::Left, u)].active();
    right += s.players[player_index(Side::Right, u)].active();
  }
  EXPECT_EQ(left, 7);
  EXPECT_EQ(right, 7);
  EXPECT_EQ(s.play_mode, PlayMode::PlayOn);  // no kick_off line in this log
}

TEST(OpenLog, GoalPausesRepeatTime) {
  const Summary s = summarise(kData + "generated/gen19-v6long-20261122030200-Alpha_2-vs-Beta_6.rcg.gz");
  EXPECT_GE(s.max_stoppage, 40);
}

}  // namespace
}  // namespace mc::ingest
