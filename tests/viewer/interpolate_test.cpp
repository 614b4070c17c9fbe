// Render-time blending of two frames: the web page's rules (interp.js).
#include "viewer/interpolate.hpp"

#include <gtest/gtest.h>

namespace mc::viewer {
namespace {

PoseFrame make(std::uint32_t seq, float x, float heading, float angle) {
  PoseFrame f;
  f.seq = seq;
  f.time = static_cast<int>(seq / 2);
  f.play_mode = seq % 2 ? PlayMode::PlayOn : PlayMode::KickOffL;
  f.ball = {x, -x, 0.1f};
  for (int i = 0; i < kMaxPlayers; ++i) {
    auto& p = f.players[i];
    p.side = i < kPlayersPerSide ? Side::Left : Side::Right;
    p.unum = static_cast<std::uint8_t>(i % kPlayersPerSide + 1);
    p.state = 1;
    p.x = x;
    p.y = 2 * x;
    p.heading = heading;
    p.angles[0] = angle;
    p.angles[1] = -angle;
  }
  return f;
}

TEST(Interpolate, BlendsPositionsAnglesAndTheBall) {
  const PoseFrame a = make(10, 0.0f, 0.0f, 10.0f), b = make(11, 1.0f, 20.0f, 30.0f);
  PoseFrame out;
  blend_frames(a, b, 0.25f, 2, out);
  EXPECT_FLOAT_EQ(out.ball.x, 0.25f);
  EXPECT_FLOAT_EQ(out.ball.y, -0.25f);
  EXPECT_FLOAT_EQ(out.players[3].x, 0.25f);
  EXPECT_FLOAT_EQ(out.players[3].y, 0.5f);
  EXPECT_FLOAT_EQ(out.players[3].heading, 5.0f);
  EXPECT_FLOAT_EQ(out.players[3].angles[0], 15.0f);
  EXPECT_FLOAT_EQ(out.players[3].angles[1], -15.0f);
  // Discrete data comes from a until the playhead reaches b.
  EXPECT_EQ(out.seq, 10u);
  EXPECT_EQ(out.play_mode, PlayMode::KickOffL);
  blend_frames(a, b, 1.0f, 2, out);
  EXPECT_EQ(out.play_mode, PlayMode::PlayOn);
  EXPECT_EQ(out.seq, 11u);
}

TEST(Interpolate, HeadingTurnsTheShortWayRound) {
  EXPECT_NEAR(lerp_heading(170.0f, -170.0f, 0.5f), 180.0f, 1e-4);
  EXPECT_NEAR(lerp_heading(-170.0f, 170.0f, 0.5f), -180.0f, 1e-4);
  EXPECT_NEAR(lerp_heading(10.0f, 350.0f, 0.5f), 0.0f, 1e-4);
  EXPECT_NEAR(lerp_heading(0.0f, 90.0f, 0.5f), 45.0f, 1e-4);
}

TEST(Interpolate, ATeleportIsNotSlidAcrossThePitch) {
  const PoseFrame a = make(10, 0.0f, 0.0f, 0.0f), b = make(11, 30.0f, 0.0f, 0.0f);
  PoseFrame out;
  blend_frames(a, b, 0.4f, 2, out);
  EXPECT_FLOAT_EQ(out.players[0].x, 0.0f);
  blend_frames(a, b, 0.6f, 2, out);
  EXPECT_FLOAT_EQ(out.players[0].x, 30.0f);
  // The ball is never a teleport: it flies.
  EXPECT_FLOAT_EQ(out.ball.x, 18.0f);
}

TEST(Interpolate, ADifferentPlayerInTheSlotIsNotBlended) {
  const PoseFrame a = make(10, 0.0f, 0.0f, 0.0f);
  PoseFrame b = make(11, 1.0f, 0.0f, 0.0f);
  b.players[2].unum = 9;
  PoseFrame out;
  blend_frames(a, b, 0.5f, 2, out);
  EXPECT_FLOAT_EQ(out.players[2].x, 0.0f);
  EXPECT_FLOAT_EQ(out.players[3].x, 0.5f);
}

TEST(Interpolate, TIsClampedAndAHostileDofCountIsBounded) {
  const PoseFrame a = make(10, 0.0f, 0.0f, 0.0f), b = make(11, 1.0f, 0.0f, 10.0f);
  PoseFrame out;
  blend_frames(a, b, 7.0f, 1000, out);
  EXPECT_FLOAT_EQ(out.players[0].x, 1.0f);
  blend_frames(a, b, -3.0f, -5, out);
  EXPECT_FLOAT_EQ(out.players[0].x, 0.0f);
  EXPECT_FLOAT_EQ(out.players[0].angles[0], 0.0f);
}

}  // namespace
}  // namespace mc::viewer
