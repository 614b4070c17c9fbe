#include "viewer/recording_source.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

#include "server/record/recording_reader.hpp"

namespace mc::viewer {

using Clock = std::chrono::steady_clock;

RecordingSource::RecordingSource(std::string path, FrameBuffer& buffer, RecordingOptions options,
                                 RetryPolicy retry)
    : path_(std::move(path)), buffer_(buffer), options_(options), retry_(retry) {
  paused_ = options.start_paused;
  speed_ = std::clamp(options.speed, 0.05, 64.0);
}

RecordingSource::~RecordingSource() { stop(); }

void RecordingSource::start() {
  if (thread_.joinable()) return;
  stop_ = false;
  thread_ = std::thread([this] { run(); });
}

void RecordingSource::stop() {
  {
    std::lock_guard lock(mutex_);
    stop_ = true;
  }
  wake_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void RecordingSource::toggle_pause() {
  paused_ = !paused_.load();
  wake_.notify_all();
}

void RecordingSource::seek_to(int time) {
  {
    std::lock_guard lock(mutex_);
    seek_request_ = std::max(0, time);
  }
  wake_.notify_all();
}

void RecordingSource::seek_by(double seconds) { seek_to(time_.load() + static_cast<int>(seconds * 10.0)); }

void RecordingSource::set_speed(double speed) {
  speed_ = std::clamp(speed, 0.05, 64.0);
  wake_.notify_all();
}

void RecordingSource::run() {
  auto frame = std::make_unique<PoseFrame>();
  std::vector<std::string> controls;
  std::string error;
  while (true) {
    {
      std::unique_lock lock(mutex_);
      if (stop_) return;
    }
    ++attempts_;
    record::RecordingReader reader;
    if (!reader.open(path_, error)) {
      char delay[32];
      std::snprintf(delay, sizeof delay, "%.0f", retry_.initial_s);
      buffer_.set_connected(false);
      // The reader's errors usually name the file already.
      const std::string what = error.find(path_) == std::string::npos ? path_ + ": " + error : error;
      buffer_.set_status("cannot open recording " + what + "; retrying in " + delay + " s");
      std::unique_lock lock(mutex_);
      wake_.wait_for(lock, std::chrono::duration<double>(retry_.initial_s), [this] { return stop_; });
      continue;
    }
    opened_ = true;
    buffer_.set_hello(reader.hello());
    buffer_.set_status(reader.recovered() ? "recording was not closed: index rebuilt" : "");
    int pending_seek = options_.start_time;
    bool at_end = false;
    // Pacing: the frame `base_seq` is shown at `base_wall`, later frames
    // 50 ms / speed apart.
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
      bool ok;
      controls.clear();
      if (pending_seek >= 0) {
        ok = reader.seek(pending_seek, *frame, error);
        if (!ok && error.empty()) error = "no frame at or after that time";
        if (!ok) {
          buffer_.set_status("cannot seek to " + std::to_string(pending_seek / 10) + " s: " + error);
          pending_seek = -1;
          if (paused_) exhausted_ = true;
          continue;
        }
        pending_seek = -1;
        at_end = false;
        exhausted_ = false;
        based = false;
        buffer_.clear_frames();
        buffer_.set_status("");
      } else {
        ok = reader.next(*frame, error, &controls);
        if (!ok) {
          if (error.empty() && options_.loop) {
            reader.rewind();
            continue;
          }
          at_end = true;
          buffer_.set_status(error.empty() ? "end of recording"
                                           : "recording damaged after " + std::to_string(time_.load() / 10) +
                                                 " s: " + error + " (seek past it to go on)");
          continue;
        }
      }
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
      // Any frame of a recording can be shown alone: each counts as a keyframe.
      time_ = frame->time;
      buffer_.set_connected(true);
      buffer_.push(*frame, true);
    }
  }
}

}  // namespace mc::viewer
