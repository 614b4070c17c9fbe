// The hand-off between the source thread and the renderer: playhead,
// interpolation pairs, skip to the newest keyframe, new timelines, bounds.
#include "viewer/frame_buffer.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <thread>

namespace mc::viewer {
namespace {

PoseFrame frame(std::uint32_t seq) {
  PoseFrame f;
  f.seq = seq;
  f.time = static_cast<int>(seq / 2);
  f.ball.x = static_cast<float>(seq);
  return f;
}

TEST(FrameBuffer, NothingToSampleBeforeTheFirstFrame) {
  FrameBuffer buffer;
  Sample s;
  double playhead = -1;
  EXPECT_FALSE(buffer.sample(playhead, 1.0, s));
}

TEST(FrameBuffer, StartsJustBehindTheNewestFrameAndInterpolates) {
  FrameBuffer buffer({.capacity = 100, .delay_frames = 2.0, .max_lag_frames = 40});
  for (std::uint32_t i = 0; i < 10; ++i) buffer.push(frame(i), i == 0);
  Sample s;
  double playhead = -1;
  ASSERT_TRUE(buffer.sample(playhead, 0.0, s));
  EXPECT_DOUBLE_EQ(playhead, 7.0);
  EXPECT_EQ(s.a.seq, 7u);
  EXPECT_EQ(s.b.seq, 8u);
  EXPECT_FLOAT_EQ(s.t, 0.0f);
  ASSERT_TRUE(buffer.sample(playhead, 0.25, s));
  EXPECT_EQ(s.a.seq, 7u);
  EXPECT_NEAR(s.t, 0.25f, 1e-6);
  // The playhead never runs past the newest frame: it holds there.
  ASSERT_TRUE(buffer.sample(playhead, 50.0, s));
  EXPECT_DOUBLE_EQ(playhead, 9.0);
  EXPECT_EQ(s.a.seq, 9u);
  EXPECT_EQ(s.b.seq, 9u);
  EXPECT_FALSE(s.skipped);
}

TEST(FrameBuffer, FallingBehindLiveSkipsToTheNewestKeyframe) {
  FrameBuffer buffer({.capacity = 400, .delay_frames = 2.0, .max_lag_frames = 40});
  buffer.push(frame(0), true);
  Sample s;
  double playhead = -1;
  ASSERT_TRUE(buffer.sample(playhead, 0.0, s));
  // A slow renderer: 110 frames arrive while it draws nothing.
  for (std::uint32_t i = 1; i <= 110; ++i) buffer.push(frame(i), i % 20 == 0);
  ASSERT_TRUE(buffer.sample(playhead, 1.0, s));
  EXPECT_TRUE(s.skipped);
  EXPECT_DOUBLE_EQ(playhead, 100.0);  // the newest keyframe, not the newest frame
  EXPECT_EQ(s.a.seq, 100u);
  EXPECT_EQ(buffer.skips(), 1u);
  // Within the allowed lag nothing jumps.
  ASSERT_TRUE(buffer.sample(playhead, 1.0, s));
  EXPECT_FALSE(s.skipped);
  EXPECT_DOUBLE_EQ(playhead, 101.0);
}

TEST(FrameBuffer, AGapHoldsTheOlderFrameInsteadOfBlendingAcrossIt) {
  FrameBuffer buffer({.capacity = 100, .delay_frames = 0.0, .max_lag_frames = 40});
  buffer.push(frame(10), true);
  buffer.push(frame(15), true);
  Sample s;
  double playhead = -1;
  ASSERT_TRUE(buffer.sample(playhead, 0.0, s));
  playhead = 12.5;
  ASSERT_TRUE(buffer.sample(playhead, 0.0, s));
  EXPECT_EQ(s.a.seq, 10u);
  EXPECT_EQ(s.b.seq, 15u);
  EXPECT_FLOAT_EQ(s.t, 0.0f);
}

TEST(FrameBuffer, ASeqThatDoesNotGrowStartsANewTimeline) {
  FrameBuffer buffer;
  for (std::uint32_t i = 100; i < 110; ++i) buffer.push(frame(i), i == 100);
  Sample s;
  double playhead = -1;
  ASSERT_TRUE(buffer.sample(playhead, 0.0, s));
  const auto timeline = buffer.timeline();
  buffer.push(frame(5), true);  // a seek back, or a restarted relay
  EXPECT_EQ(buffer.size(), 1u);
  EXPECT_GT(buffer.timeline(), timeline);
  ASSERT_TRUE(buffer.sample(playhead, 1.0, s));
  EXPECT_DOUBLE_EQ(playhead, 5.0);
  EXPECT_EQ(s.a.seq, 5u);
}

TEST(FrameBuffer, AFullBufferDropsItsOldestFramesAndCountsThem) {
  FrameBuffer buffer({.capacity = 8, .delay_frames = 2.0, .max_lag_frames = 40});
  for (std::uint32_t i = 0; i < 20; ++i) buffer.push(frame(i), true);
  EXPECT_EQ(buffer.size(), 8u);
  EXPECT_EQ(buffer.dropped(), 12u);
  ASSERT_TRUE(buffer.frame_at_time(0).has_value());
  EXPECT_EQ(buffer.frame_at_time(0)->seq, 12u);  // the oldest still held
  EXPECT_EQ(buffer.frame_at_time(8)->seq, 16u);
  EXPECT_FALSE(buffer.frame_at_time(10).has_value());
}

TEST(FrameBuffer, ANewHelloClearsTheFramesAndBumpsTheGeneration) {
  FrameBuffer buffer;
  buffer.push(frame(1), true);
  proto::Hello hello;
  hello.left.name = "A";
  buffer.set_hello(hello);
  EXPECT_EQ(buffer.size(), 0u);
  auto meta = buffer.meta();
  ASSERT_TRUE(meta.hello);
  EXPECT_EQ(meta.hello->left.name, "A");
  const auto generation = meta.hello_generation;
  proto::TeamHello left, right;
  left.name = "B";
  buffer.set_teams(left, right);
  meta = buffer.meta();
  EXPECT_EQ(meta.hello->left.name, "B");
  EXPECT_GT(meta.hello_generation, generation);
}

// A producer that never waits and a renderer that draws nothing for long
// stretches: the renderer is never more than max_lag frames behind after a
// sample, and the producer is never blocked by it.
TEST(FrameBuffer, ASlowRendererNeverFallsBehindAFastProducer) {
  FrameBuffer buffer({.capacity = 400, .delay_frames = 2.0, .max_lag_frames = 40});
  std::atomic<bool> done{false};
  std::thread producer([&] {
    for (std::uint32_t i = 0; i < 20000; ++i) buffer.push(frame(i), i % 20 == 0);
    done = true;
  });
  Sample s;
  double playhead = -1;
  int samples = 0;
  while (!done || samples == 0) {
    if (buffer.sample(playhead, 0.1, s)) {
      ++samples;
      const double newest_at_most = 20000;
      EXPECT_LE(playhead, newest_at_most);
      EXPECT_GE(static_cast<double>(s.a.seq) + 1, playhead);
    }
    std::this_thread::sleep_for(std::chrono::microseconds(200));
  }
  producer.join();
  ASSERT_TRUE(buffer.sample(playhead, 0.0, s));
  EXPECT_LE(19999.0 - playhead, 40.0);
  EXPECT_GE(buffer.skips(), 1u);
}

}  // namespace
}  // namespace mc::viewer
