// Recordings that cannot fill the disk: one file per game (each pass of a
// looping log), and retention that deletes the oldest past a size or an age,
// never the file being written, with a log line for each.
#include "server/app/recordings.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <filesystem>
#include <fstream>
#include <thread>

#include "server/app/log_feed.hpp"
#include "server/record/recording_reader.hpp"
#include "server/relay/channel_registry.hpp"

namespace fs = std::filesystem;

namespace mc::app {
namespace {

// 277 cycles: at 20x a pass takes about 1.4 s.
const std::string kShortLog = std::string(MATCHCAST_TEST_RCG_DIR) + "/real/20200428141309-HELIOS_base_2-vs-null.rcg.gz";

class RecordingsTest : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("mc-recordings-" + std::to_string(::getpid()) + "-" +
                                        ::testing::UnitTest::GetInstance()->current_test_info()->name());
    fs::remove_all(dir_);
    fs::create_directories(dir_);
  }
  void TearDown() override { fs::remove_all(dir_); }

  void make_file(const std::string& name, std::size_t bytes, std::chrono::seconds age) {
    std::ofstream(dir_ / name, std::ios::binary) << std::string(bytes, 'x');
    fs::last_write_time(dir_ / name, fs::file_time_type::clock::now() - age);
  }
  std::vector<std::string> names() const {
    std::vector<std::string> out;
    for (const auto& e : fs::directory_iterator(dir_)) out.push_back(e.path().filename().string());
    std::sort(out.begin(), out.end());
    return out;
  }

  fs::path dir_;
};

TEST(RetentionOptions, ParseSizesAndDurations) {
  std::uint64_t b = 1;
  EXPECT_TRUE(parse_byte_size("0", b));
  EXPECT_EQ(b, 0u);
  EXPECT_TRUE(parse_byte_size("1048576", b));
  EXPECT_EQ(b, 1048576u);
  EXPECT_TRUE(parse_byte_size("300M", b));
  EXPECT_EQ(b, 300ull << 20);
  EXPECT_TRUE(parse_byte_size("2g", b));
  EXPECT_EQ(b, 2ull << 30);
  for (const char* bad : {"", "M", "12MB", "-1", "1.5G", "99999999999999999999"}) EXPECT_FALSE(parse_byte_size(bad, b)) << bad;
  std::chrono::seconds s{};
  EXPECT_TRUE(parse_duration("90", s));
  EXPECT_EQ(s.count(), 90);
  EXPECT_TRUE(parse_duration("30m", s));
  EXPECT_EQ(s.count(), 1800);
  EXPECT_TRUE(parse_duration("7d", s));
  EXPECT_EQ(s.count(), 7 * 86400);
  for (const char* bad : {"", "d", "7w", "1h30m"}) EXPECT_FALSE(parse_duration(bad, s)) << bad;
}

TEST_F(RecordingsTest, PastTheSizeTheOldestGoFirstButNeverTheOneBeingWritten) {
  make_file("live-1.mcrec", 1000, std::chrono::seconds(500));
  make_file("live-2.mcrec", 1000, std::chrono::seconds(400));
  make_file("other-3.mcrec", 1000, std::chrono::seconds(300));
  make_file("live-4.mcrec", 1000, std::chrono::seconds(200));
  make_file("notes.txt", 5000, std::chrono::seconds(900));  // not a recording: never touched
  // The oldest is being written (a channel whose game runs long): kept.
  ::testing::internal::CaptureStderr();
  const auto deleted = apply_retention(dir_.string(), {2500, std::chrono::seconds(0)}, {"live-1.mcrec"});
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(deleted, (std::vector<std::string>{"live-2.mcrec", "other-3.mcrec"}));
  EXPECT_EQ(names(), (std::vector<std::string>{"live-1.mcrec", "live-4.mcrec", "notes.txt"}));
  EXPECT_NE(log.find("\"event\":\"recording_deleted\""), std::string::npos) << log;
  EXPECT_NE(log.find("live-2.mcrec: 1000 bytes"), std::string::npos) << log;
  EXPECT_NE(log.find("over --record-max-bytes (2500)"), std::string::npos) << log;
  // Within the bound: nothing more goes.
  EXPECT_TRUE(apply_retention(dir_.string(), {2500, std::chrono::seconds(0)}, {}).empty());
}

TEST_F(RecordingsTest, PastTheAgeOldRecordingsGo) {
  make_file("a.mcrec", 10, std::chrono::hours(50));
  make_file("b.mcrec", 10, std::chrono::hours(30));
  make_file("c.mcrec", 10, std::chrono::hours(1));
  ::testing::internal::CaptureStderr();
  const auto deleted = apply_retention(dir_.string(), {0, std::chrono::hours(24)}, {});
  const std::string log = ::testing::internal::GetCapturedStderr();
  EXPECT_EQ(deleted, (std::vector<std::string>{"a.mcrec", "b.mcrec"}));
  EXPECT_EQ(names(), std::vector<std::string>{"c.mcrec"});
  EXPECT_NE(log.find("older than --record-max-age (86400 s)"), std::string::npos) << log;
  // No policy: nothing is ever deleted.
  make_file("d.mcrec", 10, std::chrono::hours(5000));
  EXPECT_TRUE(apply_retention(dir_.string(), {}, {}).empty());
}

TEST_F(RecordingsTest, ALoopingLogMakesOneReadableFilePerPassAndRetentionBoundsThem) {
  auto channels = std::make_shared<relay::ChannelRegistry>();
  FeedConfig config;
  config.log_path = kShortLog;
  config.speed = 20;
  config.loop = true;
  LogFeed feed(config, channels->open("live"));
  std::string error;
  ASSERT_TRUE(feed.start(error)) << error;
  replay::ReplayCatalog catalog(dir_.string());
  // A pass makes ~78 KB: the bound keeps two of them and the current one.
  const std::uint64_t max_bytes = 200 * 1024;
  Recordings recordings(dir_.string(), {max_bytes, std::chrono::seconds(0)}, &catalog);
  ::testing::internal::CaptureStderr();
  ASSERT_TRUE(recordings.record(channels->find("live")));
  std::vector<std::string> opened;
  for (int i = 0; i < 3000 && opened.size() < 6; ++i) {
    const std::string now = recordings.current()["live"];
    if (opened.empty() || opened.back() != now) opened.push_back(now);
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  feed.stop();
  recordings.stop_all();
  const std::string log = ::testing::internal::GetCapturedStderr();
  ASSERT_GE(opened.size(), 6u) << "fewer passes than expected in 30 s";
  EXPECT_NE(log.find("\"event\":\"recording_deleted\""), std::string::npos);

  // What is left: the newest files, within the bound (plus the one that
  // was being written), each readable from start to end, one pass each.
  const auto left = names();
  ASSERT_GE(left.size(), 2u);
  std::uint64_t total = 0;
  for (const auto& name : left) total += fs::file_size(dir_ / name);
  EXPECT_LE(total, max_bytes + fs::file_size(dir_ / opened.back()));
  for (const auto& name : left)
    EXPECT_NE(std::find(opened.end() - static_cast<std::ptrdiff_t>(left.size()) - 1, opened.end(), name), opened.end())
        << name << " is not among the newest";
  int complete = 0;
  for (const auto& name : left) {
    record::RecordingReader reader;
    ASSERT_TRUE(reader.open((dir_ / name).string(), error)) << name << ": " << error;
    EXPECT_FALSE(reader.recovered()) << name << " was not closed with its index";
    EXPECT_EQ(reader.hello().match_id, "20200428141309-HELIOS_base_2-vs-null");
    PoseFrame f;
    int first = -1, last = -1;
    while (reader.next(f, error)) {
      if (first < 0) first = f.time;
      EXPECT_GE(f.time, last) << name << ": the clock goes back inside one file";
      last = f.time;
    }
    EXPECT_TRUE(error.empty()) << name << ": " << error;
    EXPECT_EQ(reader.skipped_frames(), 0u) << name;
    // Every file but the last (cut by the stop) holds one whole pass.
    if (name != opened.back()) {
      EXPECT_LE(first, 1) << name;
      EXPECT_GE(last, 270) << name;
      ++complete;
    }
  }
  EXPECT_GE(complete, 1);
}

}  // namespace
}  // namespace mc::app
