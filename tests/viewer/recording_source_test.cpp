// A recording file as a source: playback, seek, pause, and damaged files
// that give a clear message and a retry instead of a crash.
#include "viewer/recording_source.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <thread>

namespace mc::viewer {
namespace {

const std::string kGolden = std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/recording_v1.mcrec";

// Waits up to `seconds` for `done`.
template <class F>
bool eventually(F done, double seconds = 10) {
  const auto end = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  while (std::chrono::steady_clock::now() < end) {
    if (done()) return true;
    std::this_thread::sleep_for(std::chrono::milliseconds(10));
  }
  return done();
}

std::string write_file(const std::string& name, const std::string& bytes) {
  const std::string path = testing::TempDir() + "/" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

std::string read_file(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST(RecordingSource, PlaysTheGoldenRecording) {
  FrameBuffer buffer;
  RecordingSource source(kGolden, buffer, {.start_time = -1, .start_paused = false, .speed = 8.0, .loop = false});
  source.start();
  ASSERT_TRUE(eventually([&] { return buffer.meta().status == "end of recording"; })) << buffer.meta().status;
  EXPECT_TRUE(source.opened());
  EXPECT_TRUE(buffer.meta().hello);
  EXPECT_EQ(buffer.size(), 20u);  // every frame of the file
  source.stop();
}

TEST(RecordingSource, ScreenshotModeDeliversTheFrameAtATimeAndWaits) {
  FrameBuffer buffer;
  RecordingSource source(kGolden, buffer, {.start_time = 5, .start_paused = true, .speed = 1.0, .loop = false});
  source.start();
  ASSERT_TRUE(eventually([&] { return buffer.frame_at_time(5).has_value(); }));
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(buffer.size(), 1u);  // paused after it
  EXPECT_EQ(buffer.frame_at_time(0)->time, 5);
  // Seek while paused: the buffer starts a new timeline at that time.
  source.seek_to(2);
  ASSERT_TRUE(eventually([&] { return buffer.frame_at_time(0) && buffer.frame_at_time(0)->time == 2; }));
  source.toggle_pause();
  EXPECT_FALSE(source.paused());
  ASSERT_TRUE(eventually([&] { return buffer.size() > 3; }));
  source.stop();
}

TEST(RecordingSource, ASeekPastTheEndWhilePausedSaysSoAndGivesUp) {
  FrameBuffer buffer;
  RecordingSource source(kGolden, buffer, {.start_time = 99999, .start_paused = true, .speed = 1.0, .loop = false});
  source.start();
  ASSERT_TRUE(eventually([&] { return source.exhausted(); }));
  EXPECT_NE(buffer.meta().status.find("cannot seek"), std::string::npos) << buffer.meta().status;
  EXPECT_EQ(buffer.size(), 0u);
  source.seek_to(3);  // a later seek that works clears it
  ASSERT_TRUE(eventually([&] { return buffer.size() == 1u; }));
  EXPECT_FALSE(source.exhausted());
  source.stop();
}

TEST(RecordingSource, ACorruptFileGivesAClearMessageAndARetry) {
  const std::string path = write_file("viewer_corrupt.mcrec", std::string(5000, '\x5a'));
  FrameBuffer buffer;
  RecordingSource source(path, buffer, {}, RetryPolicy{0.05, 0.05});
  source.start();
  ASSERT_TRUE(eventually([&] { return source.attempts() >= 3; }));
  const std::string status = buffer.meta().status;
  EXPECT_NE(status.find("cannot open recording " + path), std::string::npos) << status;
  EXPECT_NE(status.find("retrying"), std::string::npos) << status;
  EXPECT_FALSE(buffer.meta().hello);
  EXPECT_EQ(buffer.size(), 0u);
  const auto t0 = std::chrono::steady_clock::now();
  source.stop();
  EXPECT_LT(std::chrono::steady_clock::now() - t0, std::chrono::seconds(2));
}

TEST(RecordingSource, AMissingFileIsRetriedUntilItAppears) {
  const std::string path = testing::TempDir() + "/viewer_appears.mcrec";
  std::remove(path.c_str());
  FrameBuffer buffer;
  RecordingSource source(path, buffer, {.start_time = -1, .start_paused = false, .speed = 8.0, .loop = false},
                         RetryPolicy{0.05, 0.05});
  source.start();
  ASSERT_TRUE(eventually([&] { return source.attempts() >= 2; }));
  EXPECT_NE(buffer.meta().status.find("cannot open recording"), std::string::npos);
  write_file("viewer_appears.mcrec", read_file(kGolden));
  ASSERT_TRUE(eventually([&] { return buffer.size() >= 10; }));
  EXPECT_TRUE(source.opened());
  source.stop();
}

TEST(RecordingSource, ACutFilePlaysUpToTheCutAndDamageMidFileStopsWithAMessage) {
  const std::string golden = read_file(kGolden);
  // Cut: the writer was killed. The reader rebuilds the index.
  const std::string cut = write_file("viewer_cut.mcrec", golden.substr(0, golden.size() - 200));
  FrameBuffer buffer;
  RecordingSource source(cut, buffer, {.start_time = -1, .start_paused = false, .speed = 8.0, .loop = false});
  source.start();
  ASSERT_TRUE(eventually([&] { return buffer.meta().status.find("end of recording") != std::string::npos; }))
      << buffer.meta().status;
  EXPECT_GT(buffer.size(), 0u);
  EXPECT_LT(buffer.size(), 20u);
  source.stop();

  // Flipped bytes in the middle of the data: a message, no crash, no hang.
  std::string damaged = golden;
  for (std::size_t i = damaged.size() / 2; i < damaged.size() / 2 + 64; ++i) damaged[i] = static_cast<char>(~damaged[i]);
  const std::string bad = write_file("viewer_damaged.mcrec", damaged);
  FrameBuffer buffer2;
  RecordingSource source2(bad, buffer2, {.start_time = -1, .start_paused = false, .speed = 8.0, .loop = false},
                          RetryPolicy{0.05, 0.05});
  source2.start();
  ASSERT_TRUE(eventually([&] {
    const auto s = buffer2.meta().status;
    return s.find("damaged") != std::string::npos || s.find("end of recording") != std::string::npos ||
           s.find("cannot open") != std::string::npos;
  })) << buffer2.meta().status;
  source2.stop();
}

}  // namespace
}  // namespace mc::viewer
