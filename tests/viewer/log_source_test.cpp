// A game log as a source (the pipeline in-process): it plays as a recording
// does (frames in order, the frame at a time for --screenshot, pause, seek,
// speed), the frames are the server pipeline's, and bad files get a message.
#include "viewer/log_source.hpp"

#include <gtest/gtest.h>

#include <chrono>
#include <fstream>
#include <iterator>
#include <thread>

#include "anim/human_skeleton.hpp"
#include "proto/frame_codec.hpp"
#include "wasm/log_reference.hpp"

namespace mc::viewer {
namespace {

const std::string kV5 =
    std::string(MATCHCAST_TEST_RCG_DIR) + "/generated/gen19-v5-20261122025405-Alpha_0-vs-Beta_0.rcg.gz";

template <class F>
bool eventually(F done, double seconds = 30) {
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

TEST(LogSource, PlaysALogFromItsFirstFrameInOrder) {
  FrameBuffer buffer;
  LogSource source(kV5, buffer, {.start_time = -1, .start_paused = false, .speed = 8.0, .loop = false});
  source.start();
  ASSERT_TRUE(eventually([&] { return buffer.meta().hello && buffer.size() > 40; })) << buffer.meta().status;
  const auto first = buffer.frame_at_time(0);
  ASSERT_TRUE(first);
  EXPECT_LE(first->time, 2);
  EXPECT_EQ(buffer.meta().hello->left.name, "Alpha");
  source.stop();
}

TEST(LogSource, TheFrameAtATimeIsTheServerPipelinesFrame) {
  // The server pipeline's frames of the same log, decoded.
  std::string ref, error;
  wasm::LogSessionOptions o;
  ASSERT_TRUE(wasm::broadcast_log_file(kV5, o, ref, error)) << error;
  proto::FrameDecoder dec(anim::human_skeleton());
  std::optional<PoseFrame> want;
  for (std::size_t i = 0; i + 5 <= ref.size();) {
    const char kind = ref[i];
    const std::uint32_t n = static_cast<std::uint8_t>(ref[i + 1]) | static_cast<std::uint8_t>(ref[i + 2]) << 8 |
                            static_cast<std::uint8_t>(ref[i + 3]) << 16 |
                            static_cast<std::uint32_t>(static_cast<std::uint8_t>(ref[i + 4])) << 24;
    if (kind == 'k' || kind == 'f') {
      PoseFrame f;
      ASSERT_TRUE(dec.decode(std::string_view(ref).substr(i + 5, n), f, error)) << error;
      if (!want && f.time >= 300) want = f;
    }
    i += 5 + n;
  }
  ASSERT_TRUE(want);

  FrameBuffer buffer;
  LogSource source(kV5, buffer, {.start_time = 300, .start_paused = true, .speed = 1.0, .loop = false});
  source.start();
  ASSERT_TRUE(eventually([&] { return buffer.frame_at_time(300).has_value(); })) << buffer.meta().status;
  const PoseFrame got = *buffer.frame_at_time(300);
  EXPECT_EQ(got.seq, want->seq);
  EXPECT_EQ(got.time, want->time);
  for (int p = 0; p < kMaxPlayers; ++p) {
    EXPECT_EQ(got.players[p].x, want->players[p].x) << p;
    EXPECT_EQ(got.players[p].angles, want->players[p].angles) << p;
  }
  // Paused after it; a seek moves it; play goes on from there.
  std::this_thread::sleep_for(std::chrono::milliseconds(200));
  EXPECT_EQ(buffer.size(), 1u);
  source.seek_to(100);
  ASSERT_TRUE(eventually([&] { return buffer.frame_at_time(0) && buffer.frame_at_time(0)->time == 100; }));
  source.set_speed(4);
  source.toggle_pause();
  ASSERT_TRUE(eventually([&] { return buffer.size() > 10; }));
  EXPECT_GT(source.current_time(), 100);
  source.stop();
}

TEST(LogSource, TheWholeLogIsAnimatedAndTheEndIsSaid) {
  FrameBuffer buffer;
  LogSource source(kV5, buffer, {.start_time = 590, .start_paused = false, .speed = 8.0, .loop = false});
  source.start();
  ASSERT_TRUE(eventually([&] { return buffer.meta().status == "end of log"; })) << buffer.meta().status;
  EXPECT_TRUE(source.complete());
  EXPECT_EQ(source.frames_made(), 2u * 599);  // two frames per show
  source.stop();
}

TEST(LogSource, NotALogSaysSoAndGivesUp) {
  FrameBuffer buffer;
  LogSource source(write_file("junk.rcg", std::string(5000, 'x')), buffer, {});
  source.start();
  ASSERT_TRUE(eventually([&] { return source.exhausted(); }));
  EXPECT_NE(buffer.meta().status.find("not a game log"), std::string::npos) << buffer.meta().status;
  EXPECT_FALSE(buffer.meta().hello);
  source.stop();
}

TEST(LogSource, ACutLogPlaysToTheCutAndSaysWhere) {
  std::ifstream in(kV5, std::ios::binary);
  const std::string gz{std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
  const std::string cut = write_file("cut.rcg.gz", gz.substr(0, gz.size() / 2));
  FrameBuffer buffer;
  LogSource source(cut, buffer, {.start_time = -1, .start_paused = false, .speed = 64.0, .loop = false});
  source.start();
  ASSERT_TRUE(eventually([&] { return source.complete(); }));
  EXPECT_NE(buffer.meta().status.find("log cut off"), std::string::npos) << buffer.meta().status;
  EXPECT_NE(buffer.meta().status.find("plays up to cycle"), std::string::npos) << buffer.meta().status;
  EXPECT_GT(source.frames_made(), 200u);
  EXPECT_LT(source.frames_made(), 2u * 599);
  source.stop();
}

TEST(LogSource, AFileSourceIsARecordingByItsMagicAndALogOtherwise) {
  FrameBuffer buffer;
  auto log = make_file_source(kV5, buffer, {});
  EXPECT_NE(dynamic_cast<LogSource*>(log.get()), nullptr);
  const std::string rec = std::string(MATCHCAST_SOURCE_DIR) + "/tests/proto/golden/recording_v1.mcrec";
  auto recording = make_file_source(rec, buffer, {});
  EXPECT_NE(dynamic_cast<RecordingSource*>(recording.get()), nullptr);
}

}  // namespace
}  // namespace mc::viewer
