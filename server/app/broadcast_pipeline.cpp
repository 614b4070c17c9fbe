#include "server/app/broadcast_pipeline.hpp"

#include <variant>

#include "anim/event_messages.hpp"
#include "anim/human_skeleton.hpp"
#include "proto/hello.hpp"

namespace mc::app {
namespace {

// States between "stamina" messages: once a second at 10 Hz, so exactly
// every 20 frames (proto/SPEC.md section 5.3).
constexpr std::uint64_t kStaminaEveryStates = 10;

// `s` with each byte that is not part of well-formed UTF-8 replaced by '?'.
// A binary log's team name is 16 raw bytes and a text log's any token, and
// JSON (nlohmann's dump) refuses what is not UTF-8.
std::string valid_utf8(const std::string& s) {
  std::string out;
  out.reserve(s.size());
  const auto* p = reinterpret_cast<const unsigned char*>(s.data());
  const std::size_t n = s.size();
  for (std::size_t i = 0; i < n;) {
    const unsigned c = p[i];
    std::size_t len = c < 0x80 ? 1 : (c >> 5) == 0x6 ? 2 : (c >> 4) == 0xE ? 3 : (c >> 3) == 0x1E ? 4 : 0;
    bool ok = len != 0 && i + len <= n && !(len == 2 && c < 0xC2);
    for (std::size_t k = 1; ok && k < len; ++k) ok = (p[i + k] & 0xC0) == 0x80;
    if (ok && len == 3) {  // no overlong forms, no surrogates
      const unsigned c1 = p[i + 1];
      ok = !(c == 0xE0 && c1 < 0xA0) && !(c == 0xED && c1 >= 0xA0);
    }
    if (ok && len == 4) {  // no overlong forms, nothing past U+10FFFF
      const unsigned c1 = p[i + 1];
      ok = !(c == 0xF0 && c1 < 0x90) && !(c == 0xF4 && c1 >= 0x90) && c <= 0xF4;
    }
    if (ok) {
      out.append(s, i, len);
      i += len;
    } else {
      out += '?';
      ++i;
    }
  }
  return out;
}

// A team as the hello and "teams" messages show it. Broadcast convention:
// a warm and a cold kit, readable from any camera.
proto::TeamHello team_of(const TeamInfo& team, Side side) {
  proto::TeamHello t;
  t.name = valid_utf8(team.name);
  t.color = side == Side::Left ? "#d62828" : "#1d4ed8";
  t.color2 = "#ffffff";
  return t;
}

proto::ScoreUpdate score_of(const WorldState& state) {
  proto::ScoreUpdate s;
  s.time = state.time;
  s.left = state.left.score;
  s.right = state.right.score;
  s.pen_left = state.left.pen_score;
  s.pen_right = state.right.pen_score;
  return s;
}

bool same_score(const proto::ScoreUpdate& a, const proto::ScoreUpdate& b) {
  return a.left == b.left && a.right == b.right && a.pen_left == b.pen_left && a.pen_right == b.pen_right;
}

}  // namespace

std::string make_hello(const WorldState& first, const GameParams& params, int keyframe_interval,
                       const std::string& match_id) {
  proto::Hello hello;
  hello.skeleton = anim::human_skeleton();
  hello.keyframe_interval = keyframe_interval;
  proto::fill_from_params(params, hello);
  hello.left = team_of(first.left, Side::Left);
  hello.right = team_of(first.right, Side::Right);
  hello.match_id = valid_utf8(match_id);
  return proto::to_json(hello);
}

BroadcastPipeline::BroadcastPipeline(const GameParams& params, PipelineOptions options, std::uint32_t first_seq)
    : animator_(anim::human_skeleton(), params, options.anim),
      director_([&] {
        director::DirectorConfig d;
        d.lookahead_states = options.anim.lookahead_cycles;  // a cue is decided when its frames leave
        return d;
      }()),
      encoder_(anim::human_skeleton(), proto::EncoderOptions{options.keyframe_interval}),
      next_seq_(first_seq) {}

BroadcastPipeline::~BroadcastPipeline() = default;

void BroadcastPipeline::add_state_message(proto::ControlMessage message) {
  extra_.push_back(std::move(message));
}

void BroadcastPipeline::queue_state_messages(const WorldState& state) {
  const std::uint64_t first_frame = 2 * state.index;  // the animator's seq of its substep 0
  if (first_state_) {
    first_state_ = false;
    first_index_ = state.index;
  }
  // Metadata first, so that a spectator has the scoreboard before the
  // picture: the teams (a team may connect late), the score.
  std::pair<std::string, std::string> names{state.left.name, state.right.name};
  if (teams_sent_ != names) {
    proto::TeamsUpdate t;
    t.left = team_of(state.left, Side::Left);
    t.right = team_of(state.right, Side::Right);
    timed_.emplace_back(first_frame, std::move(t));
    teams_sent_ = std::move(names);
  }
  const proto::ScoreUpdate score = score_of(state);
  if (!score_sent_ || !same_score(score, *score_sent_)) {
    timed_.emplace_back(first_frame, score);
    score_sent_ = score;
  }
  if ((state.index - first_index_) % kStaminaEveryStates == 0)
    timed_.emplace_back(first_frame, proto::stamina_update(state));
}

void BroadcastPipeline::push(const WorldState& state) {
  compact();
  queue_state_messages(state);
  // Then what the caller added for this state (a reach map).
  for (proto::ControlMessage& m : extra_) timed_.emplace_back(2 * state.index, std::move(m));
  extra_.clear();
  director_.push(state, cues_);
  animator_.push(state, frames_, &events_);
}

void BroadcastPipeline::finish() {
  compact();
  director_.finish(cues_);
  animator_.finish(frames_, &events_);
}

void BroadcastPipeline::emit_next(std::uint64_t server_time_ms, PipelineSink& sink) {
  if (!has_frame()) return;
  PoseFrame& f = frames_[next_frame_++];
  // A frame's events go out just before it, renumbered like it.
  const std::int64_t shift = static_cast<std::int64_t>(next_seq_) - f.seq;
  for (; next_event_ < events_.size() && events_[next_event_].seq <= f.seq; ++next_event_) {
    const anim::AnimEvent& event = events_[next_event_];
    // A card event without a card says nothing to a spectator.
    if (event.type == anim::AnimEventType::Card && event.card == anim::Card::None) continue;
    proto::ControlMessage m = anim::to_control_message(event);
    proto::shift_frames(m, shift);
    sink.control(proto::to_json(m));
  }
  for (; next_timed_ < timed_.size() && timed_[next_timed_].first <= f.seq; ++next_timed_) {
    proto::ControlMessage& m = timed_[next_timed_].second;
    std::visit([&](auto& msg) { msg.seq = next_seq_; }, m);
    sink.control(proto::to_json(m));
  }
  // The director's cues last, just before the frame they name.
  for (; next_cue_ < cues_.size() && cues_[next_cue_].seq <= f.seq; ++next_cue_) {
    proto::ControlMessage m{cues_[next_cue_]};
    proto::shift_frames(m, shift);
    sink.control(proto::to_json(m));
  }
  f.seq = next_seq_++;
  f.server_time_ms = server_time_ms;
  bool key = false;
  std::string bytes = encoder_.encode(f, key);
  ++emitted_;
  sink.frame(std::move(bytes), key);
}

void BroadcastPipeline::compact() {
  // Drop what has gone out, so that the queues stay a few frames long.
  if (next_frame_ == frames_.size()) {
    frames_.clear();
    next_frame_ = 0;
  }
  events_.erase(events_.begin(), events_.begin() + static_cast<std::ptrdiff_t>(next_event_));
  next_event_ = 0;
  timed_.erase(timed_.begin(), timed_.begin() + static_cast<std::ptrdiff_t>(next_timed_));
  next_timed_ = 0;
  cues_.erase(cues_.begin(), cues_.begin() + static_cast<std::ptrdiff_t>(next_cue_));
  next_cue_ = 0;
}

}  // namespace mc::app
