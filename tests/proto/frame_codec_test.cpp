#include "proto/frame_codec.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "tests/proto/support/synthetic.hpp"

namespace mc::proto {
namespace {

struct Errors {
  double angle = 0, position = 0;
};

Errors compare(const PoseFrame& a, const PoseFrame& b, int dofs) {
  Errors e;
  const auto pos = [&](float ax, float ay, float az, float bx, float by, float bz) {
    e.position = std::max(e.position, std::sqrt(double(ax - bx) * (ax - bx) + double(ay - by) * (ay - by) +
                                                double(az - bz) * (az - bz)));
  };
  pos(a.ball.x, a.ball.y, a.ball.z, b.ball.x, b.ball.y, b.ball.z);
  for (int i = 0; i < kMaxPlayers; ++i) {
    const auto& p = a.players[static_cast<std::size_t>(i)];
    const auto& q = b.players[static_cast<std::size_t>(i)];
    EXPECT_EQ(p.side, q.side);
    EXPECT_EQ(p.unum, q.unum);
    EXPECT_EQ(p.state, q.state);
    pos(p.x, p.y, p.z, q.x, q.y, q.z);
    double dh = std::fmod(std::abs(double(p.heading) - q.heading), 360.0);
    e.angle = std::max(e.angle, std::min(dh, 360 - dh));
    for (int d = 0; d < dofs; ++d)
      e.angle = std::max(e.angle, std::abs(double(p.angles[static_cast<std::size_t>(d)]) - q.angles[static_cast<std::size_t>(d)]));
  }
  return e;
}

class FrameCodec : public ::testing::Test {
 protected:
  SkeletonDef skeleton = testing::humanoid_skeleton();
  std::vector<PoseFrame> frames = testing::scripted_frames(skeleton, 120);
};

TEST_F(FrameCodec, RoundTripStaysWithinTheErrorBudget) {
  FrameEncoder enc(skeleton);
  FrameDecoder dec(skeleton);
  int keyframes = 0;
  for (const auto& f : frames) {
    bool key = false;
    const std::string bytes = enc.encode(f, key);
    keyframes += key;
    PoseFrame out;
    std::string error;
    ASSERT_TRUE(dec.decode(bytes, out, error)) << error;
    EXPECT_EQ(out.seq, f.seq);
    EXPECT_EQ(out.time, f.time);
    EXPECT_EQ(out.substep, f.substep);
    EXPECT_EQ(out.server_time_ms, f.server_time_ms);
    EXPECT_EQ(out.play_mode, f.play_mode);
    EXPECT_EQ(out.score_left, f.score_left);
    const Errors e = compare(f, out, skeleton.dof_count());
    ASSERT_LE(e.angle, 0.5) << "frame " << f.seq;
    ASSERT_LE(e.position, 0.01) << "frame " << f.seq;
  }
  EXPECT_EQ(keyframes, 6);  // frames 0, 20, ..., 100
}

TEST_F(FrameCodec, DeltasAreMuchSmallerThanKeyframes) {
  FrameEncoder enc(skeleton);
  std::size_t key_bytes = 0, delta_bytes = 0, deltas = 0;
  for (const auto& f : frames) {
    bool key = false;
    const auto n = enc.encode(f, key).size();
    (key ? key_bytes : delta_bytes) += n;
    deltas += !key;
  }
  EXPECT_LT(delta_bytes / deltas * 2, key_bytes / 6);
}

TEST_F(FrameCodec, SeqGapForcesAKeyframeAndForceKeyframeWorks) {
  FrameEncoder enc(skeleton);
  bool key = false;
  enc.encode(frames[0], key);
  EXPECT_TRUE(key);
  enc.encode(frames[1], key);
  EXPECT_FALSE(key);
  enc.encode(frames[3], key);  // frame 2 skipped
  EXPECT_TRUE(key);
  enc.force_keyframe();
  enc.encode(frames[4], key);
  EXPECT_TRUE(key);
  enc.encode(frames[5], key);
  EXPECT_FALSE(key);
}

TEST_F(FrameCodec, DeltaWithoutBaseIsRefusedUntilTheNextKeyframe) {
  FrameEncoder enc(skeleton);
  std::vector<std::string> bytes;
  for (const auto& f : frames) {
    bool key = false;
    bytes.push_back(enc.encode(f, key));
  }
  FrameDecoder dec(skeleton);
  PoseFrame out;
  std::string error;
  EXPECT_FALSE(dec.decode(bytes[5], out, error));
  EXPECT_NE(error.find("without its base"), std::string::npos) << error;
  // A late joiner starts at keyframe 20 and decodes every frame from there.
  EXPECT_TRUE(dec.decode(bytes[20], out, error)) << error;
  EXPECT_TRUE(dec.decode(bytes[21], out, error)) << error;
  // A gap (22 lost) is detected; 23.. are refused until keyframe 40.
  EXPECT_FALSE(dec.decode(bytes[23], out, error));
  EXPECT_NE(error.find("gap"), std::string::npos) << error;
  EXPECT_FALSE(dec.decode(bytes[24], out, error));
  EXPECT_TRUE(dec.decode(bytes[40], out, error)) << error;
  for (int i = 41; i < 60; ++i) ASSERT_TRUE(dec.decode(bytes[static_cast<std::size_t>(i)], out, error)) << error;
  const Errors e = compare(frames[59], out, skeleton.dof_count());
  EXPECT_LE(e.angle, 0.5);
}

TEST_F(FrameCodec, TruncatedFramesAreRefusedAtEveryLength) {
  FrameEncoder enc(skeleton);
  std::vector<std::string> bytes;
  for (int i = 0; i < 3; ++i) {
    bool key = false;
    bytes.push_back(enc.encode(frames[static_cast<std::size_t>(i)], key));
  }
  for (int which = 0; which < 3; ++which) {
    const std::string& full = bytes[static_cast<std::size_t>(which)];
    for (std::size_t len = 0; len < full.size(); ++len) {
      FrameDecoder dec(skeleton);
      PoseFrame out;
      std::string error;
      for (int i = 0; i < which; ++i) ASSERT_TRUE(dec.decode(bytes[static_cast<std::size_t>(i)], out, error));
      // Copy so that AddressSanitizer sees a read past the shorter buffer.
      const std::string cut = full.substr(0, len);
      EXPECT_FALSE(dec.decode(cut, out, error)) << "frame " << which << " cut at " << len;
      EXPECT_FALSE(error.empty());
    }
  }
}

TEST_F(FrameCodec, TrailingBytesAndWrongMagicAreRefused) {
  FrameEncoder enc(skeleton);
  bool key = false;
  std::string bytes = enc.encode(frames[0], key);
  FrameDecoder dec(skeleton);
  PoseFrame out;
  std::string error;
  EXPECT_FALSE(dec.decode(bytes + std::string(3, '\0'), out, error));
  EXPECT_NE(error.find("trailing"), std::string::npos) << error;
  bytes[0] = 'X';
  EXPECT_FALSE(dec.decode(bytes, out, error));
  EXPECT_NE(error.find("magic"), std::string::npos) << error;
}

TEST_F(FrameCodec, UnknownMajorVersionIsRefusedClearly) {
  FrameEncoder enc(skeleton);
  bool key = false;
  std::string bytes = enc.encode(frames[0], key);
  bytes[1] = 2;
  FrameDecoder dec(skeleton);
  PoseFrame out;
  std::string error;
  EXPECT_FALSE(dec.decode(bytes, out, error));
  EXPECT_NE(error.find("unsupported pose-frame protocol major version 2"), std::string::npos) << error;
  FrameHeader h;
  EXPECT_FALSE(peek_header(bytes, h, error));
  EXPECT_EQ(h.major, 2);
}

TEST_F(FrameCodec, KeyframeForAnotherSkeletonIsRefused) {
  FrameEncoder enc(skeleton);
  bool key = false;
  const std::string bytes = enc.encode(frames[0], key);
  SkeletonDef other = skeleton;
  other.joints.pop_back();
  FrameDecoder dec(other);
  PoseFrame out;
  std::string error;
  EXPECT_FALSE(dec.decode(bytes, out, error));
  EXPECT_NE(error.find("different skeleton"), std::string::npos) << error;
}

TEST_F(FrameCodec, PeekHeaderAndStampServerTime) {
  FrameEncoder enc(skeleton);
  bool key = false;
  enc.encode(frames[0], key);
  std::string bytes = enc.encode(frames[1], key);
  FrameHeader h;
  std::string error;
  ASSERT_TRUE(peek_header(bytes, h, error)) << error;
  EXPECT_EQ(h.seq, frames[1].seq);
  EXPECT_FALSE(h.keyframe);
  EXPECT_EQ(h.time, frames[1].time);
  EXPECT_EQ(h.substep, 1);
  EXPECT_EQ(h.server_time_ms, frames[1].server_time_ms);
  ASSERT_TRUE(stamp_server_time(bytes, 1234567890123ull));
  ASSERT_TRUE(peek_header(bytes, h, error));
  EXPECT_EQ(h.server_time_ms, 1234567890123ull);
  std::string tiny = "M";
  EXPECT_FALSE(stamp_server_time(tiny, 1));
  EXPECT_FALSE(peek_header(tiny, h, error));
  EXPECT_NE(error.find("truncated"), std::string::npos);
}

}  // namespace
}  // namespace mc::proto
