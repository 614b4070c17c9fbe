// The viewer follows the same director track as the page: the same rigs
// (numbers from web/src/director.js's shotRig for the same cases), the same
// cuts, and a goal's replay from its own history, then back to live.
#include "viewer/director_view.hpp"

#include <gtest/gtest.h>

#include "server/director/director.hpp"

namespace mc::viewer {
namespace {

using proto::DirectorCue;
using proto::Shot;

DirectorCue cue(std::uint32_t seq, Shot shot, Side attack = Side::Neutral, Side goal = Side::Neutral) {
  DirectorCue c;
  c.seq = seq;
  c.shot = shot;
  c.attack = attack;
  c.goal = goal;
  c.framing = director::framing_of(shot);
  return c;
}

void expect_rig(const ShotRig& r, glm::vec3 eye, glm::vec3 look, float fov) {
  EXPECT_NEAR(r.eye.x, eye.x, 1e-3);
  EXPECT_NEAR(r.eye.y, eye.y, 1e-3);
  EXPECT_NEAR(r.eye.z, eye.z, 1e-3);
  EXPECT_NEAR(r.look.x, look.x, 1e-3);
  EXPECT_NEAR(r.look.y, look.y, 1e-3);
  EXPECT_NEAR(r.look.z, look.z, 1e-3);
  EXPECT_NEAR(r.fov, fov, 1e-3);
}

TEST(DirectorView, TheShotsAreThePages) {
  const proto::FieldGeometry field;
  const float aspect = 16.0f / 9.0f;
  PoseFrame f;
  f.ball = {10, 5, 0};
  expect_rig(shot_rig(cue(0, Shot::Tracking, Side::Left), std::nullopt, f, field, aspect), {19, 17, 43}, {19, 0, 3}, 26);
  f.ball = {-20, 10, 0};
  expect_rig(shot_rig(cue(0, Shot::Wide), std::nullopt, f, field, aspect), {-7, 30, 77.4f}, {-7, 0, 2}, 40);
  f.ball = {-52, 33, 0};
  DirectorCue sp = cue(0, Shot::SetPiece, Side::Right, Side::Left);
  sp.subject_side = Side::Right;
  sp.subject_unum = 10;
  auto& taker = f.players[static_cast<std::size_t>(player_index(Side::Right, 10))];
  taker.state = 1;
  taker.x = -51;
  taker.y = 32;
  expect_rig(shot_rig(sp, std::nullopt, f, field, aspect), {-50.6254f, 3.2f, 39.9912f}, {-51.7492f, 0.6f, 16.0175f}, 50);
  f.ball = {35, -4, 0};
  expect_rig(shot_rig(cue(0, Shot::Attack, Side::Left, Side::Right), std::nullopt, f, field, aspect), {33.325f, 10, 23.2f},
             {41.125f, 0.5f, -2.8f}, 30);
  DirectorCue sc = cue(0, Shot::Scorer, Side::Right, Side::Left);
  sc.subject_side = Side::Right;
  sc.subject_unum = 10;
  taker.x = 15;
  taker.y = -10;
  expect_rig(shot_rig(sc, std::nullopt, f, field, aspect), {13.2111f, 1.8f, -6.4223f}, {15, 1.1f, -10}, 32);
  f.ball = {-40, -6, 0};
  const DirectorCue rp = cue(0, Shot::Replay, Side::Right, Side::Left);
  expect_rig(shot_rig(rp, proto::ReplayAngle::BehindGoal, f, field, aspect), {-61.5f, 9, -1.5f}, {-38.5f, 0, -3}, 55);
  expect_rig(shot_rig(rp, proto::ReplayAngle::LowSide, f, field, aspect), {-37, 1.3f, 37}, {-40, 0.6f, -6}, 23.643f);
}

TEST(DirectorView, CutsFollowTheLivePictureAndAGoalIsReplayedFromTheHistory) {
  std::vector<DirectorCue> cues = {cue(0, Shot::Wide), cue(60, Shot::Tracking, Side::Left), cue(240, Shot::Scorer)};
  DirectorCue r = cue(300, Shot::Replay, Side::Right, Side::Left);
  r.replay = {{-240, -120, proto::ReplayAngle::BehindGoal, 1.0}, {-120, -50, proto::ReplayAngle::LowSide, 0.6}};
  cues.push_back(r);
  cues.push_back(cue(302, Shot::Wide));
  FrameHistory history;
  DirectorView d;
  std::vector<Shot> shown;
  int replay_pictures = 0;
  bool saw_low = false;
  double live = 0;
  for (int i = 0; i < 1200 && live < 560; ++i) {
    PoseFrame f;
    f.seq = static_cast<std::uint32_t>(live);
    history.add(f);
    const auto step = d.update(live, 0.05, cues, true, history);
    if (step.replaying) {
      ++replay_pictures;
      EXPECT_GE(step.replay_seq, 60);
      EXPECT_LE(step.replay_seq, 251);
      if (d.angle() == proto::ReplayAngle::LowSide) saw_low = true;
    }
    if (step.cut && d.current()) shown.push_back(d.current()->shot);
    live += 1;  // the live stream goes on meanwhile (20 frames/s, a picture every 50 ms)
  }
  ASSERT_GE(shown.size(), 5u);
  EXPECT_EQ(shown[0], Shot::Wide);
  EXPECT_EQ(shown[1], Shot::Tracking);
  EXPECT_EQ(shown[2], Shot::Scorer);
  EXPECT_EQ(shown[3], Shot::Replay);
  EXPECT_TRUE(saw_low) << "the second angle";
  // 120 frames at 1x and 70 at 0.6x: 237 pictures of 50 ms.
  EXPECT_NEAR(replay_pictures, 237, 3);
  EXPECT_EQ(d.replays(), 1u);
  EXPECT_EQ(shown.back(), Shot::Wide) << "then back to live, on the live shot";
  EXPECT_FALSE(d.replaying());
}

TEST(DirectorView, NoReplayWithoutTheDirectorOnScreenOrWithoutHistory) {
  DirectorCue r = cue(300, Shot::Replay);
  r.replay = {{-240, -120, proto::ReplayAngle::BehindGoal, 1.0}};
  const std::vector<DirectorCue> cues = {cue(0, Shot::Wide), r};
  FrameHistory full;
  for (std::uint32_t s = 0; s < 400; ++s) {
    PoseFrame f;
    f.seq = s;
    full.add(f);
  }
  DirectorView manual;
  manual.update(290, 0.05, cues, false, full);
  EXPECT_FALSE(manual.update(310, 0.05, cues, false, full).replaying);
  FrameHistory late;  // joined at frame 200
  for (std::uint32_t s = 200; s < 400; ++s) {
    PoseFrame f;
    f.seq = s;
    late.add(f);
  }
  DirectorView joiner;
  joiner.update(290, 0.05, cues, true, late);
  EXPECT_FALSE(joiner.update(310, 0.05, cues, true, late).replaying);
  DirectorView on;
  on.update(290, 0.05, cues, true, full);
  EXPECT_TRUE(on.update(310, 0.05, cues, true, full).replaying);
  EXPECT_FALSE(on.update(311, 0.05, cues, false, full).replaying) << "a manual camera ends it";
}

}  // namespace
}  // namespace mc::viewer
