#include "viewer/log_source.hpp"

#include <algorithm>
#include <chrono>
#include <fstream>

#include "anim/human_skeleton.hpp"
#include "proto/frame_codec.hpp"
#include "proto/hello.hpp"
#include "proto/recording.hpp"
#include "server/app/broadcast_pipeline.hpp"
#include "server/ingest/state_source.hpp"

namespace mc::viewer {
namespace {

using Clock = std::chrono::steady_clock;

std::string file_name(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? path : path.substr(slash + 1);
}

}  // namespace

LogSource::LogSource(std::string path, FrameBuffer& buffer, RecordingOptions options)
    : path_(std::move(path)), buffer_(buffer), options_(options) {
  paused_ = options.start_paused;
  speed_ = std::clamp(options.speed, 0.05, 64.0);
}

LogSource::~LogSource() { stop(); }

void LogSource::start() {
  if (player_.joinable()) return;
  stop_ = false;
  stopping_ = false;
  buffer_.set_status("animating " + file_name(path_) + "...");
  animator_ = std::thread([this] { animate(); });
  player_ = std::thread([this] { play(); });
}

void LogSource::stop() {
  stopping_ = true;
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  grown_.notify_all();
  if (animator_.joinable()) animator_.join();
  if (player_.joinable()) player_.join();
}

void LogSource::toggle_pause() {
  paused_ = !paused_.load();
  wake_.notify_all();
}

void LogSource::seek_to(int time) {
  {
    std::lock_guard lock(mutex_);
    seek_request_ = std::max(0, time);
  }
  wake_.notify_all();
}

void LogSource::seek_by(double seconds) { seek_to(time_.load() + static_cast<int>(seconds * 10.0)); }

void LogSource::set_speed(double speed) {
  speed_ = std::clamp(speed, 0.05, 64.0);
  wake_.notify_all();
}

bool LogSource::complete() const {
  std::lock_guard lock(store_mutex_);
  return complete_;
}

std::string LogSource::error() const {
  std::lock_guard lock(store_mutex_);
  return error_;
}

std::size_t LogSource::frames_made() const {
  std::lock_guard lock(store_mutex_);
  return frames_.size();
}

void LogSource::animate() {
  const auto finish = [this](std::string error) {
    {
      std::lock_guard lock(store_mutex_);
      complete_ = true;
      error_ = std::move(error);
    }
    grown_.notify_all();
    wake_.notify_all();
  };
  std::string error;
  auto source = ingest::open_log(path_, error);
  WorldState state;
  if (source && !source->next(state)) error = path_ + ": the log holds no game states";
  proto::Hello hello;
  app::PipelineOptions options;
  if (error.empty() &&
      !proto::hello_from_json(app::make_hello(state, source->params(), options.keyframe_interval, path_), hello, error))
    error = "the log's hello: " + error;
  if (!error.empty()) {
    buffer_.set_connected(false);
    buffer_.set_status("cannot open log " + (error.find(path_) == std::string::npos ? path_ + ": " + error : error));
    exhausted_ = true;
    finish(error);
    return;
  }
  buffer_.set_hello(hello);

  struct Sink : app::PipelineSink {
    LogSource& s;
    explicit Sink(LogSource& source) : s(source) {}
    void control(std::string json) override {
      std::lock_guard lock(s.store_mutex_);
      s.controls_.push_back(std::move(json));
    }
    void frame(std::string bytes, bool key) override {
      proto::FrameHeader h;
      std::string err;
      proto::peek_header(bytes, h, err);
      std::lock_guard lock(s.store_mutex_);
      s.frames_.push_back({h.time, key, std::move(bytes), s.controls_.size()});
    }
  } sink(*this);
  app::BroadcastPipeline pipeline(source->params(), options);
  // Server times as a relay would stamp a game that started now.
  const auto base = static_cast<std::uint64_t>(
      std::chrono::duration_cast<std::chrono::milliseconds>(std::chrono::system_clock::now().time_since_epoch())
          .count());
  auto stamp = [base](std::uint32_t seq) { return base + std::uint64_t{seq} * 50; };
  do {
    if (stopping_) return;
    pipeline.push(state);
    pipeline.emit_all(stamp, sink);
    if (state.index % 20 == 0) grown_.notify_all();
  } while (source->next(state));
  pipeline.finish();
  pipeline.emit_all(stamp, sink);
  // A log that breaks off (a cut gzip stream) plays up to the break.
  std::string cut;
  for (const auto& e : source->stats().errors)
    if (e.find("ends badly") != std::string::npos) cut = e;
  if (!cut.empty())
    buffer_.set_status("log cut off (" + cut + "): it plays up to cycle " + std::to_string(state.time));
  finish(cut);
}

long LogSource::find_time(int time) const {
  // Times never decrease along the stream: the first frame at or after `time`.
  const auto it = std::lower_bound(frames_.begin(), frames_.end(), time,
                                   [](const Entry& e, int t) { return e.time < t; });
  return it == frames_.end() ? -1 : static_cast<long>(it - frames_.begin());
}

void LogSource::play() {
  proto::FrameDecoder decoder(anim::human_skeleton());
  auto frame = std::make_unique<PoseFrame>();
  std::string error;
  std::size_t next = 0;        // index of the next frame to play
  std::size_t controls_done = 0;
  int pending_seek = options_.start_time;
  bool at_end = false;
  Clock::time_point base_wall = Clock::now();
  std::uint32_t base_seq = 0;
  bool based = false;
  double based_speed = speed_;
  while (true) {
    {
      std::unique_lock lock(mutex_);
      if (stop_) return;
      if (seek_request_ >= 0) {
        pending_seek = seek_request_;
        seek_request_ = -1;
      }
      if (pending_seek < 0 && (paused_ || at_end)) {
        wake_.wait_for(lock, std::chrono::milliseconds(200));
        based = false;  // after a pause, the clock starts again from now
        continue;
      }
    }
    std::vector<std::string> controls;
    bool have = false, complete = false;
    {
      std::unique_lock lock(store_mutex_);
      complete = complete_;
      if (pending_seek >= 0) {
        const long target = find_time(pending_seek);
        if (target >= 0) {
          // Decode from the keyframe at or before it.
          long k = target;
          while (k > 0 && !frames_[static_cast<std::size_t>(k)].key) --k;
          decoder = proto::FrameDecoder(anim::human_skeleton());
          bool ok = true;
          for (long i = k; i <= target && ok; ++i)
            ok = decoder.decode(frames_[static_cast<std::size_t>(i)].bytes, *frame, error);
          pending_seek = -1;
          if (ok) {
            next = static_cast<std::size_t>(target) + 1;
            controls_done = frames_[static_cast<std::size_t>(target)].controls_end;
            have = true;
            at_end = false;
            exhausted_ = false;
            based = false;
            buffer_.clear_frames();
          }
        } else if (complete) {
          buffer_.set_status("cannot seek to " + std::to_string(pending_seek / 10) + " s: the log ends before");
          pending_seek = -1;
          if (paused_) exhausted_ = true;
          continue;
        }
      } else if (next < frames_.size()) {
        const Entry& e = frames_[next];
        for (; controls_done < e.controls_end; ++controls_done) controls.push_back(controls_[controls_done]);
        have = decoder.decode(e.bytes, *frame, error);
        ++next;
        if (!have) buffer_.set_status("frame " + std::to_string(next - 1) + ": " + error);
      } else if (complete) {
        if (options_.loop && !frames_.empty()) {
          pending_seek = 0;
          continue;
        }
        at_end = true;
        if (error_.empty()) buffer_.set_status("end of log");
        continue;
      }
      if (!have && !complete) {
        // The playhead is at the newest frame made: wait for the next ones.
        grown_.wait_for(lock, std::chrono::milliseconds(100));
        based = false;
        continue;
      }
    }
    if (!have) continue;
    for (const auto& c : controls) apply_control_message(c, buffer_);
    if (!based || based_speed != speed_.load() || frame->seq < base_seq) {
      base_wall = Clock::now();
      base_seq = frame->seq;
      based_speed = speed_;
      based = true;
    }
    const auto due = base_wall + std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(
                                     (frame->seq - base_seq) * 0.050 / based_speed));
    {
      std::unique_lock lock(mutex_);
      wake_.wait_until(lock, due, [this] { return stop_ || seek_request_ >= 0; });
      if (stop_) return;
    }
    time_ = frame->time;
    buffer_.set_connected(true);
    if (buffer_.meta().status.rfind("animating ", 0) == 0) buffer_.set_status("");
    // Any frame can be shown alone once decoded: each counts as a keyframe.
    buffer_.push(*frame, true);
  }
}

std::unique_ptr<Source> make_file_source(const std::string& path, FrameBuffer& buffer, RecordingOptions options) {
  // A recording starts with its magic; everything else is taken for a log
  // (whose reader names the problem if it is neither).
  const std::string magic = proto::rec::encode_file_header({}).substr(0, 6);
  std::string head(magic.size(), '\0');
  std::ifstream f(path, std::ios::binary);
  const bool recording = (f && f.read(head.data(), static_cast<std::streamsize>(head.size())) && head == magic) ||
                         path.ends_with(".mcrec");
  if (recording) return std::make_unique<RecordingSource>(path, buffer, options);
  return std::make_unique<LogSource>(path, buffer, options);
}

}  // namespace mc::viewer
