// A game log (.rcg, .rcg.gz, any version) as a source: the server's pipeline
// runs in-process (ingest::open_log -> app::BroadcastPipeline: the same
// frames a relay would send), on its own thread, into an in-memory list of
// encoded frames (a whole game is about 4 MB). A second thread plays that
// list like a recording, at `speed`, with pause and seek, while the rest of
// the game is still being animated: the playhead waits at the newest frame.
//
// A file that is not a log, or a log that breaks off, is a line on the
// status line (a cut log plays up to the break, and says where it is).
#pragma once

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include "viewer/frame_buffer.hpp"
#include "viewer/recording_source.hpp"
#include "viewer/source.hpp"

namespace mc::viewer {

class LogSource : public Source {
 public:
  LogSource(std::string path, FrameBuffer& buffer, RecordingOptions options = {});
  ~LogSource() override;

  void start() override;
  void stop() override;
  void toggle_pause() override;
  void seek_by(double seconds) override;
  void seek_to(int time);
  void set_speed(double speed) override;
  double speed() const override { return speed_.load(); }
  bool paused() const override { return paused_.load(); }
  bool exhausted() const override { return exhausted_.load(); }
  int attempts() const override { return 1; }
  std::string describe() const override { return path_; }

  // The whole log has been animated (or it failed: then error() says why).
  bool complete() const;
  std::string error() const;
  std::size_t frames_made() const;
  int current_time() const { return time_.load(); }

 private:
  struct Entry {
    int time = 0;
    bool key = false;
    std::string bytes;          // the encoded frame
    std::size_t controls_end;   // controls_[.. controls_end) go out before this frame
  };
  void animate();  // producer thread
  void play();     // player thread
  // The index of the first frame at or after `time`, or -1 (not made yet or none).
  long find_time(int time) const;

  std::string path_;
  FrameBuffer& buffer_;
  RecordingOptions options_;

  mutable std::mutex store_mutex_;
  std::condition_variable grown_;  // frames added, or the animation ended
  std::vector<Entry> frames_;
  std::vector<std::string> controls_;
  bool complete_ = false;
  std::string error_;

  std::mutex mutex_;
  std::condition_variable wake_;
  bool stop_ = false;
  int seek_request_ = -1;  // guarded by mutex_
  std::atomic<bool> paused_{false}, exhausted_{false}, stopping_{false};
  std::atomic<double> speed_{1.0};
  std::atomic<int> time_{0};
  std::thread animator_, player_;
};

// A file SOURCE: a recording (.mcrec, by its magic) or a game log (anything
// else): the source that plays it.
std::unique_ptr<Source> make_file_source(const std::string& path, FrameBuffer& buffer, RecordingOptions options);

}  // namespace mc::viewer
