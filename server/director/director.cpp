#include "server/director/director.hpp"

#include <algorithm>
#include <utility>

namespace mc::director {
namespace {

using proto::Shot;

// Touches older than this (30 s of states) are forgotten: a replay reaches
// 9 s back, a scorer's touch a few seconds.
constexpr std::uint64_t kTouchMemoryStates = 300;
// A scorer is his team's last touch within the replay's 9 s.
constexpr std::uint64_t kScorerReachStates = 90;
// Without a recorded touch, the player nearest a ball this close has it.
constexpr double kCloseToBallM = 1.2;

bool same_touch(const Touch& a, const Touch& b) { return a.side == b.side && a.unum == b.unum; }

}  // namespace

proto::Framing framing_of(Shot shot) {
  switch (shot) {
    case Shot::Wide: return {62, 30, 40, 0};
    case Shot::Tracking: return {40, 17, 26, 9};
    case Shot::SetPiece: return {8, 3.2, 50, 0};
    case Shot::Attack: return {26, 10, 30, 5};
    case Shot::Scorer: return {4, 1.8, 32, 0};
    case Shot::Replay: return {};
  }
  return {};
}

Director::Director(DirectorConfig config) : config_(config) {
  config_.lookahead_states = std::max(0, config_.lookahead_states);
}

void Director::push(const WorldState& state, std::vector<proto::DirectorCue>& out) {
  observe(state);
  const std::size_t undecided = window_.size() - (have_decided_ ? 1 : 0);
  if (undecided > static_cast<std::size_t>(config_.lookahead_states)) decide(out);
}

void Director::finish(std::vector<proto::DirectorCue>& out) {
  while (window_.size() > (have_decided_ ? 1u : 0u)) decide(out);
}

void Director::observe(const WorldState& state) {
  const WorldState* prev = window_.empty() ? nullptr : &window_.back();
  if (first_) {
    first_ = false;
    first_index_ = state.index;
  }
  if (const auto t = touch_in(prev, state)) touches_.push_back({state.index, *t});
  if (prev != nullptr) {
    if (state.left.score > prev->left.score) goals_.push_back({state.index, Side::Left});
    if (state.right.score > prev->right.score) goals_.push_back({state.index, Side::Right});
  }
  window_.push_back(state);
  const auto old = std::find_if(touches_.begin(), touches_.end(), [&](const TouchAt& t) {
    return t.index + kTouchMemoryStates >= state.index;
  });
  touches_.erase(touches_.begin(), old);
}

Side Director::possession(std::uint64_t index) const {
  for (auto it = touches_.rbegin(); it != touches_.rend(); ++it)
    if (it->index <= index) return it->who.side;
  return Side::Neutral;
}

Touch Director::scorer_of(const Goal& g) const {
  const TouchAt* last_any = nullptr;
  for (auto it = touches_.rbegin(); it != touches_.rend(); ++it) {
    if (it->index > g.index) continue;
    if (last_any == nullptr) last_any = &*it;
    if (it->index + kScorerReachStates < g.index) break;
    if (it->who.side == g.side) return it->who;
  }
  if (last_any != nullptr) return last_any->who;  // an own goal
  return {};
}

Director::Wish Director::wish_for(std::size_t k) {
  const WorldState& s = window_[k];
  const WorldState& newest = window_.back();
  Wish w;
  switch (moment_of(s.play_mode)) {
    case Moment::Overview:
    case Moment::Goal:
      w.shot = Shot::Wide;
      w.attack = restarting_side(s.play_mode);
      attack_on_ = false;
      return w;
    case Moment::SetPiece: {
      const Side side = restarting_side(s.play_mode);
      w.shot = Shot::SetPiece;
      w.attack = side;
      w.goal = opponent(side);
      // The taker: who kicks in the look-ahead, else his team's nearest.
      for (const TouchAt& t : touches_)
        if (t.index > s.index && t.who.side == side) {
          w.subject = t.who;
          break;
        }
      if (w.subject.unum == 0)
        if (const auto n = nearest_to_ball(newest, side)) w.subject = n->who;
      attack_on_ = false;
      return w;
    }
    case Moment::Play:
      break;
  }
  Side side = restarting_side(s.play_mode);
  if (side == Side::Neutral) side = possession(s.index);
  if (side == Side::Neutral) {
    if (const auto n = nearest_to_ball(s, Side::Neutral); n && n->distance < kCloseToBallM) side = n->who.side;
  }
  w.attack = side;
  bool attack = false;
  if (attack_on_) {
    attack = attack_on(s, side, config_.attack_leave_m);
  } else {
    for (std::size_t i = k; i < window_.size() && !attack; ++i)
      attack = attack_on(window_[i], side, config_.attack_enter_m);
  }
  attack_on_ = attack;
  w.shot = attack ? Shot::Attack : Shot::Tracking;
  if (attack) w.goal = opponent(side);
  return w;
}

void Director::emit(Wish w, bool cut, std::vector<proto::DirectorCue>& out) {
  proto::DirectorCue c;
  c.seq = static_cast<std::uint32_t>(frame_);
  c.time = time_;
  c.cut = cut;
  c.shot = w.shot;
  c.subject_side = w.subject.unum != 0 ? w.subject.side : Side::Neutral;
  c.subject_unum = w.subject.unum;
  c.attack = w.attack;
  c.goal = w.goal;
  c.framing = framing_of(w.shot);
  const bool changed = !current_ || !(w.shot == current_wish_.shot && same_touch(w.subject, current_wish_.subject) &&
                                       w.attack == current_wish_.attack && w.goal == current_wish_.goal);
  out.push_back(c);
  current_ = c;
  current_wish_ = w;
  last_sent_frame_ = frame_;
  if (cut) {
    last_cut_frame_ = frame_;
    ++cuts_;
  } else if (changed) {
    last_reframe_frame_ = frame_;
  }
}

proto::DirectorCue Director::replay_cue() const {
  proto::DirectorCue c;
  c.seq = static_cast<std::uint32_t>(frame_);
  c.time = time_;
  c.cut = true;
  c.shot = Shot::Replay;
  c.subject_side = scorer_.unum != 0 ? scorer_.side : Side::Neutral;
  c.subject_unum = scorer_.unum;
  c.attack = goal_.side;
  c.goal = opponent(goal_.side);
  const std::int64_t g = 2 * static_cast<std::int64_t>(goal_.index);
  const std::int64_t first = 2 * static_cast<std::int64_t>(first_index_);
  const std::int64_t split = g - config_.replay_split_frames;
  auto add = [&](std::int64_t from, std::int64_t to, proto::ReplayAngle angle, double speed) {
    from = std::max(from, first);
    if (from >= to) return;
    c.replay.push_back({static_cast<int>(from - frame_), static_cast<int>(to - frame_), angle, speed});
  };
  add(g - config_.replay_back_frames, split, proto::ReplayAngle::BehindGoal, 1.0);
  add(split, g + config_.replay_after_frames, proto::ReplayAngle::LowSide, config_.replay_slow_speed);
  return c;
}

void Director::decide(std::vector<proto::DirectorCue>& out) {
  const std::size_t k = have_decided_ ? 1 : 0;
  const WorldState& s = window_[k];
  frame_ = 2 * static_cast<std::int64_t>(s.index);
  time_ = s.time;

  // A goal reaches the decided state: its sequence starts.
  while (!goals_.empty() && goals_.front().index <= s.index) {
    goal_ = goals_.front();
    goals_.erase(goals_.begin());
    scorer_ = scorer_of(goal_);
    if (scorer_.unum == 0)
      if (const auto n = nearest_to_ball(s, goal_.side)) scorer_ = n->who;
    phase_ = Phase::ScorerDue;
  }
  const bool goal_coming = !goals_.empty();
  const bool repeat_due = frame_ - last_sent_frame_ >= config_.repeat_frames;

  switch (phase_) {
    case Phase::ScorerDue:
      if (!current_ || frame_ - last_cut_frame_ >= config_.goal_cut_frames) {
        emit(Wish{Shot::Scorer, scorer_, goal_.side, opponent(goal_.side)}, true, out);
        phase_ = Phase::Scorer;
        scorer_from_ = frame_;
      } else if (repeat_due) {
        emit(current_wish_, false, out);
      }
      break;
    case Phase::Scorer:
      if (frame_ - scorer_from_ >= config_.scorer_frames) {
        const proto::DirectorCue c = replay_cue();
        if (!c.replay.empty()) {
          out.push_back(c);
          last_cut_frame_ = frame_;
          last_sent_frame_ = frame_;
          ++cuts_;
        }
        phase_ = Phase::AfterReplay;
      } else if (repeat_due) {
        emit(current_wish_, false, out);
      }
      break;
    case Phase::AfterReplay:
      // The shot the clients come back to after the replay: a cut, whatever
      // the spacing (the replay itself took its time).
      emit(wish_for(k), true, out);
      phase_ = Phase::Normal;
      break;
    case Phase::Normal: {
      Wish w = wish_for(k);
      if (!current_) {
        emit(w, true, out);
        break;
      }
      // A goal in the look-ahead: hold the shot that shows it coming.
      if (goal_coming) w = current_wish_;
      const Wish& now = current_wish_;
      if (w.shot != now.shot) {
        if (frame_ - last_cut_frame_ >= config_.min_cut_frames) {
          emit(w, true, out);
          break;
        }
      } else if (!same_touch(w.subject, now.subject) || w.attack != now.attack || w.goal != now.goal) {
        if (frame_ - std::max(last_cut_frame_, last_reframe_frame_) >= config_.reframe_frames) {
          emit(w, false, out);
          break;
        }
      }
      if (repeat_due) emit(current_wish_, false, out);
      break;
    }
  }

  if (have_decided_) window_.pop_front();
  have_decided_ = true;
}

}  // namespace mc::director
