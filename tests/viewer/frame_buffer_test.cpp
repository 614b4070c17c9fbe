// The hand-off between the source thread and the renderer: playhead,
// interpolation pairs, skip to the newest keyframe, new timelines, bounds.
#include "viewer/frame_buffer.hpp"

#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
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
  double playhead = kPlayheadUnset;
  EXPECT_FALSE(buffer.sample(playhead, 1.0, s));
}

TEST(FrameBuffer, StartsJustBehindTheNewestFrameAndInterpolates) {
  FrameBuffer buffer({.capacity = 100, .delay_frames = 2.0, .max_lag_frames = 40, .catch_up_after = 6});
  for (std::uint32_t i = 0; i < 10; ++i) buffer.push(frame(i), i == 0);
  Sample s;
  double playhead = kPlayheadUnset;
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
  FrameBuffer buffer({.capacity = 400, .delay_frames = 2.0, .max_lag_frames = 40, .catch_up_after = 6});
  buffer.push(frame(0), true);
  Sample s;
  double playhead = kPlayheadUnset;
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
  EXPECT_NEAR(playhead, 101.4, 1e-9);  // 4 frames past catch_up_after: 1.4x
}

TEST(FrameBuffer, FramesArrivingFasterThanRealTimeAreCaughtUpSmoothly) {
  FrameBuffer buffer({.capacity = 400, .delay_frames = 2.0, .max_lag_frames = 40, .catch_up_after = 6});
  std::uint32_t seq = 0;
  buffer.push(frame(seq), true);
  Sample s;
  double playhead = kPlayheadUnset;
  ASSERT_TRUE(buffer.sample(playhead, 0.0, s));
  // A relay at 1.5x: three frames arrive for every two the display advances.
  double max_lag = 0;
  for (int tick = 0; tick < 400; ++tick) {
    for (int k = 0; k < (tick % 2 ? 2 : 1); ++k) {
      ++seq;
      buffer.push(frame(seq), seq % 20 == 0);
    }
    ASSERT_TRUE(buffer.sample(playhead, 1.0, s));
    max_lag = std::max(max_lag, s.newest - playhead);
  }
  EXPECT_EQ(buffer.skips(), 0u);  // no jumps: it played faster instead
  EXPECT_LT(max_lag, 20.0);
  // At the rate of the stream there is no speed-up: it stays at the delay.
  FrameBuffer steady({.capacity = 400, .delay_frames = 2.0, .max_lag_frames = 40, .catch_up_after = 6});
  steady.push(frame(0), true);
  playhead = kPlayheadUnset;
  ASSERT_TRUE(steady.sample(playhead, 0.0, s));
  for (std::uint32_t i = 1; i < 100; ++i) {
    steady.push(frame(i), i % 20 == 0);
    ASSERT_TRUE(steady.sample(playhead, 1.0, s));
  }
  EXPECT_NEAR(s.newest - playhead, 2.0, 1e-9);
}

TEST(FrameBuffer, AGapHoldsTheOlderFrameInsteadOfBlendingAcrossIt) {
  FrameBuffer buffer({.capacity = 100, .delay_frames = 0.0, .max_lag_frames = 40, .catch_up_after = 6});
  buffer.push(frame(10), true);
  buffer.push(frame(15), true);
  Sample s;
  double playhead = kPlayheadUnset;
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
  double playhead = kPlayheadUnset;
  ASSERT_TRUE(buffer.sample(playhead, 0.0, s));
  const auto timeline = buffer.timeline();
  buffer.push(frame(5), true);  // a seek back, or a restarted relay
  EXPECT_EQ(buffer.size(), 1u);
  EXPECT_GT(buffer.timeline(), timeline);
  ASSERT_TRUE(buffer.sample(playhead, 1.0, s));
  EXPECT_DOUBLE_EQ(playhead, 3.0);  // the delay behind it; its first frame holds
  EXPECT_EQ(s.a.seq, 5u);
  EXPECT_FLOAT_EQ(s.t, 0.0f);
}

TEST(FrameBuffer, AFullBufferDropsItsOldestFramesAndCountsThem) {
  FrameBuffer buffer({.capacity = 8, .delay_frames = 2.0, .max_lag_frames = 40, .catch_up_after = 6});
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

// A producer that never waits for the renderer once it draws, and a
// renderer that draws nothing for long stretches: the renderer is never
// more than max_lag frames behind after a sample, and the producer is
// never blocked by it. The producer waits (a bounded while) for the first
// sample only: on a loaded machine it could otherwise push all its frames
// before the renderer started, and a renderer that starts at the newest
// frame has nothing to catch up (a CI run saw no skip).
TEST(FrameBuffer, ASlowRendererNeverFallsBehindAFastProducer) {
  FrameBuffer buffer({.capacity = 400, .delay_frames = 2.0, .max_lag_frames = 40, .catch_up_after = 6});
  std::atomic<bool> done{false}, sampled{false};
  std::thread producer([&] {
    for (std::uint32_t i = 0; i < 20000; ++i) {
      buffer.push(frame(i), i % 20 == 0);
      if (i == 100) {
        const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(10);
        while (!sampled && std::chrono::steady_clock::now() < until) std::this_thread::yield();
      }
    }
    done = true;
  });
  Sample s;
  double playhead = kPlayheadUnset;
  int samples = 0;
  while (!done || samples == 0) {
    if (buffer.sample(playhead, 0.1, s)) {
      sampled = true;
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
