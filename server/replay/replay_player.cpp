#include "server/replay/replay_player.hpp"

#include <algorithm>
#include <chrono>
#include <nlohmann/json.hpp>

#include "proto/control_messages.hpp"
#include "proto/match_id.hpp"

namespace mc::replay {
namespace {

// A jump to a goal starts this many cycles before it, to see the build-up.
constexpr int kGoalLeadCycles = 50;
// Pressing "previous goal" within this many cycles after a goal's lead-in
// goes to the goal before it, as a video player's "previous" does.
constexpr int kPrevGoalSlack = 30;
// At most one seek is done in this much time (see request_seek()).
constexpr std::chrono::milliseconds kSeekWindow{50};

std::uint64_t unix_ms() {
  using namespace std::chrono;
  return static_cast<std::uint64_t>(duration_cast<milliseconds>(system_clock::now().time_since_epoch()).count());
}

}  // namespace

void RecordingSummary::note(const PoseFrame& f) {
  if (empty) {
    first_time = f.time;
    score_left = f.score_left;
    score_right = f.score_right;
    empty = false;
  }
  if (f.score_left > score_left) goals.push_back({f.time, Side::Left});
  if (f.score_right > score_right) goals.push_back({f.time, Side::Right});
  score_left = f.score_left;
  score_right = f.score_right;
  last_time = f.time;
}

bool summarize(record::RecordingReader& reader, RecordingSummary& out, std::string& error) {
  out = {};
  PoseFrame f;
  reader.rewind();
  while (reader.next(f, error)) out.note(f);
  reader.rewind();
  if (!error.empty()) return false;
  if (out.empty) {
    error = "the recording holds no frames";
    return false;
  }
  return true;
}

ReplayPlayer::ReplayPlayer(boost::asio::any_io_executor executor, std::string name,
                           std::unique_ptr<record::RecordingReader> reader, RecordingSummary summary,
                           bool follow)
    : timer_(executor),
      seek_timer_(executor),
      name_(std::move(name)),
      name_json_(nlohmann::json(name_).dump(-1, ' ', false, nlohmann::json::error_handler_t::replace)),
      reader_(std::move(reader)),
      summary_(std::move(summary)),
      channel_(std::make_shared<relay::Channel>("replay:" + name_)),
      follow_(follow) {
  // A recording made before match_ids were public may name a server path.
  // The reader parsed the hello already: only a match_id with a path needs
  // the text parsed and written again (hello_without_paths returns any
  // other text unchanged), which was most of a replay's start.
  const bool has_path = reader_->hello().match_id.find_first_of("/\\") != std::string::npos;
  channel_->set_hello(has_path ? proto::hello_without_paths(reader_->hello_json()) : reader_->hello_json());
  channel_->set_feed_state(relay::FeedState::Live);
}

// Made on the first frame sent: a spectator who leaves before (or a
// player that only answers messages) never builds its model.
proto::FrameEncoder& ReplayPlayer::encoder() {
  if (!encoder_) encoder_ = std::make_unique<proto::FrameEncoder>(reader_->hello().skeleton);
  return *encoder_;
}

void ReplayPlayer::start() {
  publish_status();
  schedule();
}

void ReplayPlayer::schedule() {
  if (closed_ || paused_) return;
  timer_.expires_after(std::chrono::duration_cast<std::chrono::steady_clock::duration>(
      std::chrono::duration<double, std::milli>(kFrameIntervalMs / speed_)));
  timer_.async_wait([self = shared_from_this()](boost::system::error_code ec) { self->on_tick(ec); });
}

void ReplayPlayer::on_tick(boost::system::error_code ec) {
  if (ec || closed_ || paused_) return;
  if (pending_seek_) {
    // The jump is this tick's picture once its window is over (the seek
    // timer then finds it done); until then the picture holds. Ticks come
    // up to 160 times a second at speed 8: doing the seek on each would
    // undo the window.
    if (std::chrono::steady_clock::now() - last_seek_ >= kSeekWindow) {
      seek_pending();
      publish_status();
    }
    return schedule();
  }
  if (!send_next()) {
    if (follow_) {
      // Caught up with a recording still being written: wait for its next
      // chunk, holding the last picture.
      if (++frames_since_status_ >= 20) publish_status();
      return schedule();
    }
    // The end of the recording: hold the last picture, paused.
    paused_ = true;
    publish_status();
    return;
  }
  // The first frame, then once a second: a late status is cheap, a missing
  // one leaves the spectator's seek bar blank.
  if (seq_ == 1 || ++frames_since_status_ >= 20) publish_status();
  schedule();
}

bool ReplayPlayer::send_next() {
  PoseFrame f;
  std::string error;
  controls_.clear();
  if (!reader_->next(f, error, &controls_)) {
    if (!follow_ || !error.empty() || !reader_->refresh(error) || !reader_->next(f, error, &controls_))
      return false;
  }
  if (follow_ && f.time > summary_.last_time) summary_.note(f);
  // Recorded events name recorded frames: renumber them like the frame.
  const std::int64_t shift = static_cast<std::int64_t>(seq_) - f.seq;
  for (const auto& text : controls_) {
    proto::ControlMessage m;
    std::string ignored;
    if (!proto::control_from_json(text, m, ignored)) continue;
    proto::shift_frames(m, shift);
    channel_->publish_control(proto::to_json(m));
  }
  f.seq = seq_++;
  f.server_time_ms = unix_ms();
  time_ = f.time;
  publish(f);
  return true;
}

// Encoded first, then published: as the arguments of one call, the
// keyframe flag could be (and with GCC was) read before encode() set it,
// and every keyframe went out marked as a delta; a slow spectator's skip
// then never found a keyframe to resume at.
void ReplayPlayer::publish(const PoseFrame& f) {
  bool key = false;
  std::string bytes = encoder().encode(f, key);
  channel_->publish_frame(std::move(bytes), key);
}

void ReplayPlayer::request_seek(int time) {
  const auto now = std::chrono::steady_clock::now();
  if (!pending_seek_ && now - last_seek_ >= kSeekWindow) {
    last_seek_ = now;
    return seek(time);
  }
  // Shown at once as the position (the status, the next goal from here);
  // the picture follows when the window ends or at the next tick.
  time_ = clamp_time(time);
  if (!pending_seek_) {
    seek_timer_.expires_at(last_seek_ + kSeekWindow);
    seek_timer_.async_wait([self = shared_from_this()](boost::system::error_code ec) { self->on_seek_timer(ec); });
  }
  pending_seek_ = time_;
}

void ReplayPlayer::on_seek_timer(boost::system::error_code ec) {
  if (ec || closed_ || !pending_seek_) return;
  seek_pending();
  publish_status();
}

void ReplayPlayer::seek_pending() {
  const int time = *pending_seek_;
  pending_seek_.reset();
  last_seek_ = std::chrono::steady_clock::now();
  seek(time);
}

int ReplayPlayer::clamp_time(int time) {
  std::string error;
  // A recording still growing (follow) may reach past the summary: its last chunk is reachable.
  if (follow_ && reader_->refresh(error))
    return std::clamp(time, summary_.first_time, std::max(summary_.last_time, reader_->last_chunk_time()));
  return std::clamp(time, summary_.first_time, summary_.last_time);
}

void ReplayPlayer::seek(int time) {
  PoseFrame f;
  std::string error;
  time = clamp_time(time);
  if (!reader_->seek(time, f, error)) return;
  // seek() decoded the frame at `time`: send it as the new picture. A jump
  // breaks the delta chain, so it goes out as a keyframe.
  f.seq = seq_++;
  f.server_time_ms = unix_ms();
  time_ = f.time;
  if (follow_ && f.time > summary_.last_time) summary_.note(f);
  encoder().force_keyframe();
  publish(f);
}

void ReplayPlayer::on_message(const relay::SpectatorMessage& message) {
  if (closed_ || message.type != "replay") return;  // not for us: spectators' other messages are ignored
  const std::string& action = message.action;
  const bool was_paused = paused_;
  if (action == "pause") {
    paused_ = true;
  } else if (action == "play") {
    paused_ = false;
  } else if (action == "toggle") {
    paused_ = !paused_;
  } else if (action == "seek" && message.time) {
    // Clamped before the conversion: a double past int's range (1e300) is
    // undefined behaviour when cast; NaN cannot come from JSON.
    request_seek(static_cast<int>(std::clamp(*message.time, -1e9, 1e9)));
  } else if (action == "speed" && message.speed) {
    speed_ = std::clamp(*message.speed, 0.25, 8.0);
  } else if (action == "next_goal") {
    for (const auto& g : summary_.goals)
      if (g.time - kGoalLeadCycles > time_) {
        request_seek(g.time - kGoalLeadCycles);
        break;
      }
  } else if (action == "prev_goal") {
    for (auto it = summary_.goals.rbegin(); it != summary_.goals.rend(); ++it)
      if (it->time - kGoalLeadCycles + kPrevGoalSlack < time_) {
        request_seek(it->time - kGoalLeadCycles);
        break;
      }
  } else {
    return;
  }
  if (was_paused && !paused_) {
    timer_.cancel();
    schedule();
  } else if (!paused_ && action == "speed") {
    timer_.cancel();
    schedule();
  }
  publish_status();
}

// Written as text, keys in the order nlohmann's object would sort them: a
// status goes out on every frame's second and every spectator action, and
// a JSON tree for nine keys was most of its cost.
void ReplayPlayer::publish_status() {
  frames_since_status_ = 0;
  const auto flag = [](bool b) { return b ? "true" : "false"; };
  std::string s;
  s.reserve(160 + 24 * summary_.goals.size() + name_json_.size());
  s += R"({"first_time":)";
  s += std::to_string(summary_.first_time);
  s += R"(,"goals":[)";
  for (std::size_t i = 0; i < summary_.goals.size(); ++i) {
    s += i == 0 ? R"({"side":")" : R"(,{"side":")";
    s += summary_.goals[i].side == Side::Left ? 'l' : 'r';
    s += R"(","time":)";
    s += std::to_string(summary_.goals[i].time);
    s += '}';
  }
  s += R"(],"last_time":)";
  s += std::to_string(summary_.last_time);
  s += R"(,"live_edge":)";
  s += flag(follow_ && time_ >= summary_.last_time);
  s += R"(,"name":)";
  s += name_json_;
  s += R"(,"paused":)";
  s += flag(paused_);
  s += R"(,"speed":)";
  s += nlohmann::json(speed_).dump();
  s += R"(,"time":)";
  s += std::to_string(time_);
  s += R"(,"type":"replay"})";
  channel_->publish_control(std::move(s));
}

void ReplayPlayer::close() {
  closed_ = true;
  timer_.cancel();
  seek_timer_.cancel();
}

}  // namespace mc::replay
