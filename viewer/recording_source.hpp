// A recording file as a source (server/record's RecordingReader, the
// format of SPEC.md section 6), played on its own thread at `speed` times
// real time, with pause and seek. A file that cannot be opened (missing,
// not a recording, damaged hello) is reported on the status line and
// opened again every few seconds; damaged data in the middle stops the
// playback there with a message (seeking past it plays on).
#pragma once

#include <atomic>
#include <condition_variable>
#include <mutex>
#include <string>
#include <thread>

#include "viewer/frame_buffer.hpp"
#include "viewer/source.hpp"

namespace mc::viewer {

struct RecordingOptions {
  int start_time = -1;         // simulation cycle to start at; -1 = the beginning
  bool start_paused = false;   // deliver the first frame, then wait (--screenshot)
  double speed = 1.0;
  bool loop = false;           // start again at the end
};

class RecordingSource : public Source {
 public:
  RecordingSource(std::string path, FrameBuffer& buffer, RecordingOptions options = {},
                  RetryPolicy retry = {2.0, 2.0});
  ~RecordingSource() override;

  void start() override;
  void stop() override;
  void toggle_pause() override;
  void seek_by(double seconds) override;
  void seek_to(int time);
  void set_speed(double speed) override;
  double speed() const override { return speed_.load(); }
  bool paused() const override { return paused_.load(); }
  int attempts() const override { return attempts_.load(); }
  std::string describe() const override { return path_; }

  bool exhausted() const override { return exhausted_.load(); }
  bool opened() const { return opened_.load(); }
  int current_time() const { return time_.load(); }

 private:
  void run();

  std::string path_;
  FrameBuffer& buffer_;
  RecordingOptions options_;
  RetryPolicy retry_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  int seek_request_ = -1;       // guarded by mutex_
  std::atomic<bool> paused_{false}, opened_{false}, exhausted_{false};
  std::atomic<double> speed_{1.0};
  std::atomic<int> attempts_{0}, time_{0};
};

}  // namespace mc::viewer
