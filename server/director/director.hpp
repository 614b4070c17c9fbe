// The broadcast director (issue 20): 2D states in, the director track out,
// one proto::DirectorCue per cut or reframe (SPEC.md section 5.5).
//
// It sees the game as the animator does: a state is decided once
// `lookahead_states` following states have arrived, so it knows 200 ms of
// the future (who takes a free kick, a shot on its way, a goal) when it
// chooses the shot of that state's frames. Pure and deterministic: no clock,
// no I/O; equal states give equal cues.
//
// The shots and their triggers (web/README.md has the same table):
//  * wide      before and at each kick-off, at half time and at the end;
//  * tracking  during play: the ball from the main stand, the framing led
//              towards the goal the team in possession attacks;
//  * set_piece corners, free kicks, penalties and the fouls and offsides
//              that lead to them: behind the taker (the player who kicks in
//              the look-ahead, else his team's player nearest the ball);
//  * attack    the ball within 28 m of the goal its team attacks, or a shot
//              on its way to it (left again beyond 34 m): tighter;
//  * scorer    at a goal: the scorer (his team's last touch), 3 s;
//  * replay    then the goal's last 9 s again: 6 s from behind the goal,
//              then its last 3.5 s at 0.6x from a low side view; clients
//              then return to live and catch up. The cue after it (the
//              next state's) is the shot to return to.
// Cuts come at least `min_cut_frames` (3 s) apart; a goal may cut after
// `goal_cut_frames`. Between cuts a shot may change its subject or its
// framing's lead (a reframe, cut = false) at most once a second, and the
// running shot is repeated every `repeat_frames` for spectators who join.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <vector>

#include "proto/director_cue.hpp"
#include "proto/world_state.hpp"
#include "server/director/shot_rules.hpp"

namespace mc::director {

struct DirectorConfig {
  // Following states a decision waits for: the animator's look-ahead, so a
  // cue is decided when its frames leave (anim/anim_config.hpp).
  int lookahead_states = 2;
  // 3 s between cuts: a TV director's calm pace; a goal may cut sooner.
  int min_cut_frames = 60;
  int goal_cut_frames = 30;
  // A reframe at most once a second; the running shot again every 2 s.
  int reframe_frames = 20;
  int repeat_frames = 40;
  // The goal sequence: the scorer 3 s, then the replay of the goal's last
  // 9 s: [goal - 9 s, goal - 3 s] from behind the goal at 1x, then
  // [goal - 3 s, goal + 0.5 s] from the low side at 0.6x (12 s in all).
  int scorer_frames = 60;
  int replay_back_frames = 180;
  int replay_split_frames = 60;
  int replay_after_frames = 10;
  double replay_slow_speed = 0.6;
  // The attack shot: on within this distance of the goal, off beyond the second.
  double attack_enter_m = 28;
  double attack_leave_m = 34;
};

// The framing each shot uses (SPEC.md 5.5 says what the numbers mean).
proto::Framing framing_of(proto::Shot shot);

class Director {
 public:
  explicit Director(DirectorConfig config = {});

  // The next state in stream order (state.index counts from the pass's
  // first state). Appends the cues of the state that became decided, if
  // any, numbered like the animator's frames: seq = 2 x state index.
  void push(const WorldState& state, std::vector<proto::DirectorCue>& out);
  // End of input: decides the states still waiting for their look-ahead.
  void finish(std::vector<proto::DirectorCue>& out);

  // Cuts decided so far (for tests and logs).
  std::uint64_t cuts() const { return cuts_; }

 private:
  struct Goal {
    std::uint64_t index = 0;  // the state whose score is higher
    Side side = Side::Neutral;
  };
  struct TouchAt {
    std::uint64_t index = 0;
    Touch who;
  };
  // The shot a moment asks for, before spacing and the goal sequence.
  struct Wish {
    proto::Shot shot = proto::Shot::Wide;
    Touch subject;  // unum 0: the ball
    Side attack = Side::Neutral;
    Side goal = Side::Neutral;
  };

  void observe(const WorldState& state);
  void decide(std::vector<proto::DirectorCue>& out);
  Wish wish_for(std::size_t k);  // also moves the attack shot's hysteresis
  Side possession(std::uint64_t index) const;
  Touch scorer_of(const Goal& g) const;
  void emit(Wish w, bool cut, std::vector<proto::DirectorCue>& out);
  proto::DirectorCue replay_cue() const;

  DirectorConfig config_;
  // States not decided yet, the oldest first, after the last decided one
  // (kept for its kicks): window_[0] is the last decided state.
  std::deque<WorldState> window_;
  bool have_decided_ = false;
  std::uint64_t first_index_ = 0;
  bool first_ = true;
  std::vector<TouchAt> touches_;  // the last 30 s
  std::vector<Goal> goals_;       // seen, not yet decided
  // What is on screen.
  std::optional<proto::DirectorCue> current_;
  Wish current_wish_;
  std::int64_t last_cut_frame_ = 0;
  std::int64_t last_reframe_frame_ = 0;
  std::int64_t last_sent_frame_ = 0;
  bool attack_on_ = false;
  // The goal sequence: scorer from `scorer_from`, then the replay, then
  // the shot to return to on the next state.
  enum class Phase : std::uint8_t { Normal, ScorerDue, Scorer, AfterReplay };
  Phase phase_ = Phase::Normal;
  Goal goal_;
  Touch scorer_;
  std::int64_t scorer_from_ = 0;
  std::int64_t frame_ = 0;  // the frame being decided (2 x index)
  int time_ = 0;
  std::uint64_t cuts_ = 0;
};

}  // namespace mc::director
