#include "server/app/log_feed.hpp"

#include <chrono>
#include <optional>
#include <utility>
#include <vector>

#include "anim/animator.hpp"
#include "anim/event_messages.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/mocap/reach_map_publisher.hpp"
#include "proto/control_messages.hpp"
#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"
#include "proto/match_id.hpp"
#include "server/director/director.hpp"
#include "server/ingest/state_source.hpp"
#include "server/relay/log.hpp"

namespace mc::app {
namespace {

using Clock = std::chrono::steady_clock;
// States between "stamina" messages: once a second at 10 Hz, so exactly
// every 20 frames (proto/SPEC.md section 5.3).
constexpr std::uint64_t kStaminaEveryStates = 10;

std::uint64_t unix_ms() {
  using namespace std::chrono;
  return static_cast<std::uint64_t>(
      duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count());
}

// A team as the hello and "teams" messages show it. Broadcast convention:
// a warm and a cold kit, readable from any camera.
proto::TeamHello team_of(const TeamInfo& team, Side side) {
  proto::TeamHello t;
  t.name = team.name;
  t.color = side == Side::Left ? "#d62828" : "#1d4ed8";
  t.color2 = "#ffffff";
  return t;
}

std::string make_hello(const WorldState& first, const GameParams& params, int keyframe_interval,
                       const std::string& match_id) {
  proto::Hello hello;
  hello.skeleton = anim::human_skeleton();
  hello.keyframe_interval = keyframe_interval;
  proto::fill_from_params(params, hello);
  hello.left = team_of(first.left, Side::Left);
  hello.right = team_of(first.right, Side::Right);
  hello.match_id = match_id;
  return proto::to_json(hello);
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

}  // namespace

LogFeed::LogFeed(FeedConfig config, std::shared_ptr<relay::Channel> channel)
    : config_(std::move(config)), channel_(std::move(channel)) {}

LogFeed::~LogFeed() { stop(); }

bool LogFeed::start(std::string& error) {
  live_ = ingest::is_live_spec(config_.log_path);
  auto source = ingest::open_source(config_.log_path, error);
  if (!source) return false;
  WorldState first;
  bool have_first = false;
  if (live_) {
    const auto deadline = Clock::now() + config_.first_state_timeout;
    while (!have_first && Clock::now() < deadline) {
      const auto w = source->next_for(first, std::chrono::milliseconds(100));
      if (w == ingest::StateSource::Wait::End) break;
      have_first = w == ingest::StateSource::Wait::State;
    }
    if (!have_first) {
      error = config_.log_path + ": no game state arrived (is rcssserver running there?)";
      return false;
    }
  } else {
    have_first = source->next(first);
    if (!have_first) {
      error = config_.log_path + ": the log holds no game states";
      return false;
    }
  }
  // Spectators learn the game's name, never the log's path on this machine
  // or the address of a live rcssserver.
  hello_ = make_hello(first, source->params(), config_.keyframe_interval,
                      proto::match_id_of_source(config_.log_path, first.left.name, first.right.name));
  channel_->set_hello(hello_);
  channel_->set_feed_state(relay::FeedState::Live);
  // A live session cannot be replayed from its start: keep the one opened
  // here, first state included, for the playback thread.
  if (live_) {
    first_source_ = std::move(source);
    first_state_ = first;
  }
  thread_ = std::thread([this] { run(); });
  return true;
}

void LogFeed::stop() {
  {
    std::lock_guard lock(mutex_);
    stopping_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) {
    thread_.join();
    channel_->set_feed_state(relay::FeedState::Ended);
  }
}

bool LogFeed::wait_until(Clock::time_point deadline) {
  std::unique_lock lock(mutex_);
  return !wake_.wait_until(lock, deadline, [this] { return stopping_; });
}

void LogFeed::publish_event(const anim::AnimEvent& event, std::int64_t shift) {
  // A card event without a card says nothing to a spectator.
  if (event.type == anim::AnimEventType::Card && event.card == anim::Card::None) return;
  proto::ControlMessage m = anim::to_control_message(event);
  proto::shift_frames(m, shift);
  channel_->publish_control(proto::to_json(m));
}

void LogFeed::announce_feed(bool lost, const std::string& detail) {
  channel_->set_feed_state(lost ? relay::FeedState::Lost : relay::FeedState::Live);
  proto::FeedStatus status;
  status.lost = lost;
  status.seq = next_seq_ ? next_seq_ - 1 : 0;
  status.server_time_ms = unix_ms();
  // The detail names the rcssserver's address: it goes to the log only.
  status.detail = lost ? "no data from the game server; reconnecting" : "the game server is back";
  channel_->publish_control(proto::to_json(proto::ControlMessage{status}));
  relay::log_event(lost ? "feed_lost" : "feed_back", config_.log_path + ": " + detail);
}

void LogFeed::run() {
  do {
    if (!play_once()) return;
    relay::log_event(config_.loop && !live_ ? "feed_loop" : "feed_end", config_.log_path);
  } while (config_.loop && !live_);
  channel_->set_feed_state(relay::FeedState::Ended);
}

bool LogFeed::play_once() {
  std::string error;
  std::unique_ptr<ingest::StateSource> source;
  WorldState state;
  if (first_source_) {
    source = std::move(first_source_);
    state = first_state_;
  } else {
    source = ingest::open_source(config_.log_path, error);
    if (!source) {
      relay::log_event("feed_error", error);
      return wait_until(Clock::now() + std::chrono::seconds(1));
    }
    if (!source->next(state)) return wait_until(Clock::now() + std::chrono::seconds(1));
  }

  anim::Animator animator(anim::human_skeleton(), source->params(), config_.anim);
  proto::FrameEncoder encoder(anim::human_skeleton(),
                              proto::EncoderOptions{config_.keyframe_interval});
  std::vector<PoseFrame> frames;
  std::vector<anim::AnimEvent> events;
  std::size_t next_event = 0;
  std::unique_ptr<anim::mocap::ReachMapPublisher> reach;
  if (config_.reach_model)
    reach = std::make_unique<anim::mocap::ReachMapPublisher>(config_.reach_model, config_.reach_every_states);
  // Messages made from a state (teams, score, stamina, reach maps) go out
  // just before that state's first frame, seq 2 x index (the animator's
  // numbering), numbered like it. Keyed by the frame, not by the cycle:
  // during a stoppage many states share a cycle, and a message keyed by
  // the cycle would leave with the first of them, frames early.
  std::vector<std::pair<std::uint64_t, proto::ControlMessage>> timed_pending;
  const auto interval = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double, std::milli>(kFrameIntervalMs / config_.speed));
  auto deadline = Clock::now();
  // The metadata last sent in this pass (teams and score go out with the
  // pass's first state whatever they are, then when they change).
  const std::uint64_t first_index = state.index;
  std::optional<std::pair<std::string, std::string>> teams_sent;
  std::optional<proto::ScoreUpdate> score_sent;

  // The director's track (issue 20): a state's cue is decided with the same
  // look-ahead as its frames, and goes out just before the frame it names,
  // after that frame's other messages, renumbered like it.
  director::DirectorConfig director_config;
  director_config.lookahead_states = config_.anim.lookahead_cycles;
  director::Director director(director_config);
  std::vector<proto::DirectorCue> cues;

  auto publish = [&](std::vector<PoseFrame>& batch) {
    for (PoseFrame& f : batch) {
      deadline += interval;
      // After a stall (a suspended process, a slow disk, a live feed that
      // paused) do not rush to catch up: resume at the normal pace from now.
      // A live server paces itself; this only spreads its two frames.
      if (Clock::now() - deadline > (live_ ? interval : std::chrono::seconds(1))) deadline = Clock::now();
      if (!wait_until(deadline)) return false;
      // Sequence numbers continue across loops so that clients see no gap;
      // a frame's events go out just before it, renumbered the same way.
      const std::int64_t shift = static_cast<std::int64_t>(next_seq_) - f.seq;
      for (; next_event < events.size() && events[next_event].seq <= f.seq; ++next_event)
        publish_event(events[next_event], shift);
      std::size_t sent = 0;
      for (; sent < timed_pending.size() && timed_pending[sent].first <= f.seq; ++sent) {
        proto::ControlMessage& m = timed_pending[sent].second;
        std::visit([&](auto& msg) { msg.seq = next_seq_; }, m);
        channel_->publish_control(proto::to_json(m));
      }
      timed_pending.erase(timed_pending.begin(), timed_pending.begin() + static_cast<std::ptrdiff_t>(sent));
      std::size_t cued = 0;
      for (; cued < cues.size() && cues[cued].seq <= f.seq; ++cued) {
        proto::ControlMessage m{std::move(cues[cued])};
        proto::shift_frames(m, shift);
        channel_->publish_control(proto::to_json(m));
      }
      cues.erase(cues.begin(), cues.begin() + static_cast<std::ptrdiff_t>(cued));
      f.seq = next_seq_++;
      f.server_time_ms = unix_ms();
      bool key = false;
      std::string bytes = encoder.encode(f, key);
      channel_->publish_frame(std::move(bytes), key);
      ++frames_;
    }
    batch.clear();
    events.erase(events.begin(), events.begin() + static_cast<std::ptrdiff_t>(next_event));
    next_event = 0;
    return true;
  };

  // The next state: from a log at once; from a live server as it comes,
  // passing on feed lost / back meanwhile.
  auto next_state = [&]() -> bool {
    if (!live_) return source->next(state);
    for (;;) {
      {
        std::lock_guard lock(mutex_);
        if (stopping_) return false;
      }
      const auto w = source->next_for(state, std::chrono::milliseconds(100));
      ingest::SourceEvent ev;
      while (source->poll_event(ev)) {
        if (ev.kind == ingest::SourceEvent::Kind::FeedLost) announce_feed(true, ev.detail);
        if (ev.kind == ingest::SourceEvent::Kind::FeedBack) {
          announce_feed(false, ev.detail);
          encoder.force_keyframe();  // spectators resync at once
        }
      }
      if (w == ingest::StateSource::Wait::State) return true;
      if (w == ingest::StateSource::Wait::End) return false;
    }
  };

  do {
    const std::uint64_t first_frame = 2 * state.index;  // the seq the animator gives its substep 0
    // Metadata first, so that a spectator has the scoreboard before the
    // picture: the teams (names; a team may connect late), the score (a
    // goal, a penalty); the relay keeps the latest of each for joiners.
    std::pair<std::string, std::string> names{state.left.name, state.right.name};
    if (teams_sent != names) {
      proto::TeamsUpdate t;
      t.left = team_of(state.left, Side::Left);
      t.right = team_of(state.right, Side::Right);
      timed_pending.emplace_back(first_frame, std::move(t));
      teams_sent = std::move(names);
    }
    const proto::ScoreUpdate score = score_of(state);
    if (!score_sent || score.left != score_sent->left || score.right != score_sent->right ||
        score.pen_left != score_sent->pen_left || score.pen_right != score_sent->pen_right) {
      timed_pending.emplace_back(first_frame, score);
      score_sent = score;
    }
    // Stamina once a second: with the pass's first state, then every 10th.
    if ((state.index - first_index) % kStaminaEveryStates == 0)
      timed_pending.emplace_back(first_frame, proto::stamina_update(state));
    if (reach) {
      proto::ReachMapUpdate m;
      if (reach->push(state, source->params(), m)) timed_pending.emplace_back(first_frame, std::move(m));
    }
    director.push(state, cues);
    animator.push(state, frames, &events);
    if (!publish(frames)) return false;
  } while (next_state());
  director.finish(cues);
  animator.finish(frames, &events);
  if (!publish(frames)) return false;

  const auto& stats = source->stats();
  if (stats.skipped)
    relay::log_event("feed_skipped_records", std::to_string(stats.skipped) + " skipped in " +
                                                 config_.log_path);
  return true;
}

}  // namespace mc::app
