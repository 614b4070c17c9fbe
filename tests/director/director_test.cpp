// The director on made-up moments (kick-off, play, a corner, a goal) and on
// the bundled real game: which shot, on whom, when it cuts, the goal
// sequence scorer -> replay (two angles) -> live, and the spacing of cuts.
#include "server/director/director.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <iostream>
#include <map>
#include <string>
#include <vector>

#include "proto/control_messages.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::director {
namespace {

using proto::DirectorCue;
using proto::Shot;

// A game of 22 players in two lines, the ball at the centre.
WorldState base_state(std::uint64_t index, PlayMode mode) {
  WorldState s;
  s.index = index;
  s.time = static_cast<int>(index);
  s.play_mode = mode;
  s.left.name = "L";
  s.right.name = "R";
  for (int i = 0; i < kMaxPlayers; ++i) {
    PlayerState& p = s.players[static_cast<std::size_t>(i)];
    p.side = i < kPlayersPerSide ? Side::Left : Side::Right;
    p.unum = static_cast<std::uint8_t>(i % kPlayersPerSide + 1);
    p.state = state_bits::kStand;
    p.x = (p.side == Side::Left ? -1 : 1) * (5.0 + 4.0 * (i % kPlayersPerSide));
    p.y = -25.0 + 5.0 * (i % kPlayersPerSide);
  }
  return s;
}

PlayerState& player(WorldState& s, Side side, int unum) {
  return s.players[static_cast<std::size_t>(player_index(side, unum))];
}

struct Track {
  Director director;
  std::vector<DirectorCue> cues;
  std::uint64_t next = 0;
  void push(const WorldState& s) { director.push(s, cues); }
  std::vector<DirectorCue> cuts() const {
    std::vector<DirectorCue> out;
    for (const DirectorCue& c : cues)
      if (c.cut) out.push_back(c);
    return out;
  }
};

TEST(Director, ACueLeavesWhenItsStateHasItsLookAhead) {
  Director d;  // look-ahead 2, like the animator
  std::vector<DirectorCue> out;
  d.push(base_state(0, PlayMode::KickOffL), out);
  d.push(base_state(1, PlayMode::KickOffL), out);
  EXPECT_TRUE(out.empty()) << "state 0 waits for states 1 and 2";
  d.push(base_state(2, PlayMode::KickOffL), out);
  ASSERT_EQ(out.size(), 1u);
  EXPECT_EQ(out[0].seq, 0u) << "numbered like the animator's frames: 2 x state index";
  d.finish(out);
  for (const DirectorCue& c : out) EXPECT_LE(c.seq, 4u);
}

TEST(Director, KickOffIsWideThenPlayIsTrackedNoSoonerThanThreeSeconds) {
  Track r;
  for (std::uint64_t i = 0; i < 10; ++i) r.push(base_state(i, PlayMode::KickOffL));
  for (std::uint64_t i = 10; i < 80; ++i) {
    WorldState s = base_state(i, PlayMode::PlayOn);
    s.ball.x = 0.3 * static_cast<double>(i - 10);  // the left team carries it towards +x
    s.ball.vx = 0.3;
    if (i == 10) player(s, Side::Left, 10).state |= state_bits::kKick;
    r.push(s);
  }
  const auto cuts = r.cuts();
  ASSERT_GE(cuts.size(), 2u);
  EXPECT_EQ(cuts[0].shot, Shot::Wide);
  EXPECT_EQ(cuts[0].seq, 0u);
  EXPECT_EQ(cuts[1].shot, Shot::Tracking);
  EXPECT_EQ(cuts[1].seq, 60u) << "the wide shot holds 3 s although play began after 1 s";
  EXPECT_EQ(cuts[1].attack, Side::Left) << "the framing leads towards the goal the kicker's team attacks";
  EXPECT_EQ(cuts[1].subject_unum, 0) << "tracking follows the ball";
  EXPECT_GT(cuts[1].framing.lead, 0);
}

TEST(Director, ACornerIsShotFromBehindTheTakerTheLookAheadNames) {
  Track r;
  for (std::uint64_t i = 0; i < 40; ++i) r.push(base_state(i, PlayMode::PlayOn));
  for (std::uint64_t i = 40; i < 70; ++i) {
    WorldState s = base_state(i, PlayMode::CornerKickR);
    s.ball.x = -52;
    s.ball.y = 33;
    // Right 7 stands nearest, right 10 takes it: he kicks at state 60.
    player(s, Side::Right, 7).x = -50;
    player(s, Side::Right, 7).y = 30;
    player(s, Side::Right, 10).x = -45;
    player(s, Side::Right, 10).y = 30;
    if (i == 60) player(s, Side::Right, 10).state |= state_bits::kKick;
    r.push(s);
  }
  const auto cuts = r.cuts();
  const auto corner = std::find_if(cuts.begin(), cuts.end(), [](const DirectorCue& c) { return c.shot == Shot::SetPiece; });
  ASSERT_NE(corner, cuts.end());
  EXPECT_EQ(corner->seq, 80u) << "on the corner's first frame (the last cut was 4 s before)";
  EXPECT_EQ(corner->attack, Side::Right);
  EXPECT_EQ(corner->goal, Side::Left) << "looking at the left team's goal";
  EXPECT_EQ(corner->subject_side, Side::Right);
  EXPECT_EQ(corner->subject_unum, 7) << "before the kick is in sight, the nearest of his team";
  // Once the kick is within the look-ahead the taker becomes the subject: a reframe.
  bool reframed = false;
  for (const DirectorCue& c : r.cues)
    if (!c.cut && c.shot == Shot::SetPiece && c.subject_unum == 10) {
      reframed = true;
      EXPECT_GE(c.seq, 2u * 58);
      EXPECT_LE(c.seq, 2u * 60);
    }
  EXPECT_TRUE(reframed) << "the taker seen kicking in the look-ahead";
}

TEST(Director, AGoalShowsTheScorerThenReplaysItFromTwoAnglesThenCutsBackToLive) {
  Track r;
  std::uint64_t i = 0;
  for (; i < 100; ++i) r.push(base_state(i, PlayMode::PlayOn));
  // Left 9 shoots at state 100; the ball is in at state 110 (1-0).
  for (; i < 110; ++i) {
    WorldState s = base_state(i, PlayMode::PlayOn);
    s.ball.x = 40 + static_cast<double>(i - 100);
    s.ball.vx = 2;
    if (i == 100) player(s, Side::Left, 9).state |= state_bits::kKick;
    if (i == 104) player(s, Side::Right, 4).state |= state_bits::kKick;  // a touch of the other team: not the scorer
    r.push(s);
  }
  for (; i < 170; ++i) {
    WorldState s = base_state(i, i < 160 ? PlayMode::GoalL : PlayMode::KickOffR);
    s.left.score = 1;
    r.push(s);
  }
  r.director.finish(r.cues);

  const auto cuts = r.cuts();
  const auto scorer = std::find_if(cuts.begin(), cuts.end(), [](const DirectorCue& c) { return c.shot == Shot::Scorer; });
  ASSERT_NE(scorer, cuts.end());
  ASSERT_NE(scorer, cuts.begin());
  const std::uint32_t shot_cut = (scorer - 1)->seq;
  EXPECT_EQ((scorer - 1)->shot, Shot::Attack) << "the shot was on the attack";
  EXPECT_EQ(scorer->seq, std::max(220u, shot_cut + 30)) << "on the goal's first frame, or 1.5 s after the last cut";
  EXPECT_EQ(scorer->subject_side, Side::Left);
  EXPECT_EQ(scorer->subject_unum, 9) << "the scoring team's last touch";
  const auto replay = scorer + 1;
  ASSERT_NE(replay, cuts.end());
  EXPECT_EQ(replay->shot, Shot::Replay);
  EXPECT_EQ(replay->seq, scorer->seq + 60) << "3 s of the scorer";
  const int at = static_cast<int>(replay->seq);
  EXPECT_EQ(replay->goal, Side::Right) << "the goal scored into";
  ASSERT_EQ(replay->replay.size(), 2u);
  // Relative to the replay's frame: the goal's frame is 220.
  EXPECT_EQ(replay->replay[0].from, 220 - 180 - at);
  EXPECT_EQ(replay->replay[0].to, 220 - 60 - at);
  EXPECT_EQ(replay->replay[0].angle, proto::ReplayAngle::BehindGoal);
  EXPECT_DOUBLE_EQ(replay->replay[0].speed, 1.0);
  EXPECT_EQ(replay->replay[1].from, 220 - 60 - at);
  EXPECT_EQ(replay->replay[1].to, 220 + 10 - at);
  EXPECT_EQ(replay->replay[1].angle, proto::ReplayAngle::LowSide);
  EXPECT_LT(replay->replay[1].speed, 1.0) << "the finish in slow motion";
  const auto back = replay + 1;
  ASSERT_NE(back, cuts.end());
  EXPECT_EQ(back->seq, replay->seq + 2) << "the shot to come back to, on the next state";
  EXPECT_EQ(back->shot, Shot::Wide) << "the goal's stoppage: wide";
}

TEST(Director, AnOwnGoalsScorerIsTheLastTouch) {
  Track r;
  std::uint64_t i = 0;
  for (; i < 100; ++i) r.push(base_state(i, PlayMode::PlayOn));
  for (; i < 120; ++i) {
    WorldState s = base_state(i, i < 110 ? PlayMode::PlayOn : PlayMode::GoalL);
    if (i == 105) player(s, Side::Right, 3).state |= state_bits::kKick;
    if (i >= 110) s.left.score = 1;
    r.push(s);
  }
  r.director.finish(r.cues);
  const auto it = std::find_if(r.cues.begin(), r.cues.end(), [](const DirectorCue& c) { return c.shot == Shot::Scorer; });
  ASSERT_NE(it, r.cues.end());
  EXPECT_EQ(it->subject_side, Side::Right);
  EXPECT_EQ(it->subject_unum, 3);
}

TEST(Director, AShotComingAtGoalTightensTheFrame) {
  Track r;
  std::uint64_t i = 0;
  for (; i < 80; ++i) {
    WorldState s = base_state(i, PlayMode::PlayOn);
    s.ball.x = -10;
    if (i == 1) player(s, Side::Left, 8).state |= state_bits::kKick;
    r.push(s);
  }
  for (; i < 90; ++i) {
    WorldState s = base_state(i, PlayMode::PlayOn);
    s.ball.x = 20 + 2.5 * static_cast<double>(i - 80);  // a shot from 32 m at 2.5 m/cycle
    s.ball.vx = 2.5;
    if (i == 80) player(s, Side::Left, 8).state |= state_bits::kKick;
    r.push(s);
  }
  const auto cuts = r.cuts();
  ASSERT_GE(cuts.size(), 2u);
  const DirectorCue& last = cuts.back();
  EXPECT_EQ(last.shot, Shot::Attack);
  EXPECT_EQ(last.goal, Side::Right);
  EXPECT_LE(last.seq, 2u * 80) << "seen in the look-ahead, before the ball is near the goal";
  EXPECT_LT(last.framing.distance, proto::Framing(framing_of(Shot::Tracking)).distance);
}

TEST(Director, TheRunningShotIsRepeatedForJoiners) {
  Track r;
  for (std::uint64_t i = 0; i < 200; ++i) r.push(base_state(i, PlayMode::BeforeKickOff));
  ASSERT_GE(r.cues.size(), 9u);
  EXPECT_TRUE(r.cues[0].cut);
  for (std::size_t k = 1; k < r.cues.size(); ++k) {
    EXPECT_FALSE(r.cues[k].cut);
    EXPECT_EQ(r.cues[k].shot, Shot::Wide);
    EXPECT_EQ(r.cues[k].seq - r.cues[k - 1].seq, 40u);
  }
}

// The bundled game (HELIOS_A 1-5 HELIOS_B): every goal gets its scorer and
// replay, cuts keep their spacing, every cue is valid on the wire.
TEST(Director, TheRealGameIsDirectedLikeABroadcast) {
  const std::string log = std::string(MATCHCAST_SOURCE_DIR) + "/data/20261122030423-HELIOS_A_1-vs-HELIOS_B_5.rcg.gz";
  std::string error;
  auto source = ingest::open_source(log, error);
  ASSERT_TRUE(source) << error;
  Director d;
  std::vector<DirectorCue> cues;
  WorldState s;
  int goals = 0, prev_score = 0;
  while (source->next(s)) {
    if (s.left.score + s.right.score > prev_score) ++goals;
    prev_score = s.left.score + s.right.score;
    d.push(s, cues);
  }
  d.finish(cues);
  ASSERT_EQ(goals, 6);

  std::map<Shot, int> shots;
  const DirectorCue* last_cut = nullptr;
  const DirectorCue* prev = nullptr;
  for (const DirectorCue& c : cues) {
    // On the wire and back, unchanged.
    proto::ControlMessage m;
    std::string e;
    ASSERT_TRUE(proto::control_from_json(proto::to_json(proto::ControlMessage{c}), m, e)) << e;
    const auto& back = std::get<DirectorCue>(m);
    EXPECT_EQ(back.seq, c.seq);
    EXPECT_EQ(back.shot, c.shot);
    EXPECT_EQ(back.replay.size(), c.replay.size());
    if (prev != nullptr) {
      EXPECT_GE(c.seq, prev->seq);
      EXPECT_LE(c.seq - prev->seq, 40u) << "a joiner has the shot within 2 s";
    }
    prev = &c;
    if (!c.cut) continue;
    ++shots[c.shot];
    if (last_cut != nullptr) {
      const std::uint32_t gap = c.seq - last_cut->seq;
      if (c.shot == Shot::Scorer) {
        EXPECT_GE(gap, 30u);
      } else if (last_cut->shot == Shot::Replay) {
        EXPECT_EQ(gap, 2u) << "the shot to come back to follows the replay";
      } else {
        EXPECT_GE(gap, 60u) << "cut at " << c.seq;
      }
    }
    if (c.shot == Shot::Replay) {
      ASSERT_EQ(c.replay.size(), 2u);
      EXPECT_EQ(last_cut->shot, Shot::Scorer);
      EXPECT_EQ(c.seq - last_cut->seq, 60u);
      EXPECT_EQ(c.replay[0].to, c.replay[1].from);
      EXPECT_EQ(c.replay[1].to - c.replay[0].from, 190) << "the goal's last 9 s and half a second after it";
    }
    last_cut = &c;
  }
  EXPECT_EQ(shots[Shot::Scorer], 6);
  EXPECT_EQ(shots[Shot::Replay], 6);
  EXPECT_GE(shots[Shot::Wide], 7) << "the kick-off and after each goal";
  EXPECT_GE(shots[Shot::SetPiece], 10) << "corners and free kicks";
  EXPECT_GE(shots[Shot::Attack], 10);
  EXPECT_GE(shots[Shot::Tracking], 20);
  // A broadcast pace: 12 000 frames of game, a cut every 3 to 15 s on average.
  EXPECT_GT(d.cuts(), 12000u / 300);
  EXPECT_LT(d.cuts(), 12000u / 60);
  std::cout << "cuts " << d.cuts() << ", cues " << cues.size() << ": wide " << shots[Shot::Wide] << ", tracking "
            << shots[Shot::Tracking] << ", set_piece " << shots[Shot::SetPiece] << ", attack " << shots[Shot::Attack]
            << ", scorer " << shots[Shot::Scorer] << ", replay " << shots[Shot::Replay] << "\n";
}

TEST(Director, BadCuesAreRefusedOnTheWire) {
  proto::ControlMessage m;
  std::string e;
  EXPECT_FALSE(proto::control_from_json(R"({"type":"director","seq":1,"time":1,"cut":true,"shot":"dolly"})", m, e));
  EXPECT_NE(e.find("shot"), std::string::npos) << e;
  EXPECT_FALSE(proto::control_from_json(
      R"({"type":"director","seq":1,"time":1,"cut":true,"shot":"replay","replay":[{"from":5,"to":2,"angle":"low_side","speed":1}]})",
      m, e));
  EXPECT_FALSE(proto::control_from_json(
      R"({"type":"director","seq":1,"time":1,"cut":true,"shot":"replay","replay":[{"from":-5,"to":2,"angle":"low_side","speed":99}]})",
      m, e));
  EXPECT_FALSE(proto::control_from_json(
      R"({"type":"director","seq":1,"time":1,"cut":true,"shot":"tracking","subject":{"side":"left","unum":12}})", m, e));
  EXPECT_TRUE(proto::control_from_json(R"({"type":"director","seq":1,"time":1,"cut":false,"shot":"wide"})", m, e)) << e;
}

}  // namespace
}  // namespace mc::director
