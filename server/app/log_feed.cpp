#include "server/app/log_feed.hpp"

#include <chrono>
#include <vector>

#include "anim/mocap/reach_map_publisher.hpp"
#include "proto/control_messages.hpp"
#include "proto/match_id.hpp"
#include "server/app/broadcast_pipeline.hpp"
#include "server/ingest/state_source.hpp"
#include "server/relay/log.hpp"

namespace mc::app {
namespace {

using Clock = std::chrono::steady_clock;

std::uint64_t unix_ms() {
  using namespace std::chrono;
  return static_cast<std::uint64_t>(
      duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count());
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

  // ingest -> anim -> proto (broadcast_pipeline.hpp, the same code as the
  // page's WebAssembly module); this feed paces it and stamps real times.
  PipelineOptions options;
  options.keyframe_interval = config_.keyframe_interval;
  options.anim = config_.anim;
  BroadcastPipeline pipeline(source->params(), options, next_seq_);
  std::unique_ptr<anim::mocap::ReachMapPublisher> reach;
  if (config_.reach_model)
    reach = std::make_unique<anim::mocap::ReachMapPublisher>(config_.reach_model, config_.reach_every_states);
  const auto interval = std::chrono::duration_cast<Clock::duration>(
      std::chrono::duration<double, std::milli>(kFrameIntervalMs / config_.speed));
  auto deadline = Clock::now();

  struct ToChannel : PipelineSink {
    LogFeed& feed;
    explicit ToChannel(LogFeed& f) : feed(f) {}
    void control(std::string json) override { feed.channel_->publish_control(std::move(json)); }
    void frame(std::string bytes, bool key) override {
      feed.channel_->publish_frame(std::move(bytes), key);
      ++feed.frames_;
    }
  } sink(*this);

  // Each waiting frame at its time, its messages just before it.
  auto publish = [&]() {
    while (pipeline.has_frame()) {
      deadline += interval;
      // After a stall (a suspended process, a slow disk, a live feed that
      // paused) do not rush to catch up: resume at the normal pace from now.
      // A live server paces itself; this only spreads its two frames.
      if (Clock::now() - deadline > (live_ ? interval : std::chrono::seconds(1))) deadline = Clock::now();
      if (!wait_until(deadline)) return false;
      // Sequence numbers continue across loops so that clients see no gap.
      pipeline.emit_next(unix_ms(), sink);
      next_seq_ = pipeline.next_seq();
    }
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
          pipeline.force_keyframe();  // spectators resync at once
        }
      }
      if (w == ingest::StateSource::Wait::State) return true;
      if (w == ingest::StateSource::Wait::End) return false;
    }
  };

  do {
    if (reach) {
      proto::ReachMapUpdate m;
      if (reach->push(state, source->params(), m)) pipeline.add_state_message(std::move(m));
    }
    pipeline.push(state);
    if (!publish()) return false;
  } while (next_state());
  pipeline.finish();
  if (!publish()) return false;

  const auto& stats = source->stats();
  if (stats.skipped)
    relay::log_event("feed_skipped_records", std::to_string(stats.skipped) + " skipped in " +
                                                 config_.log_path);
  return true;
}

}  // namespace mc::app
