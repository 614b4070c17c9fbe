// The hand-off between a source thread (network or recording) and the render
// thread: decoded frames in stream order, the stream's hello, and a status
// line. The producer never waits for the renderer: pushing is O(1) under a
// short lock, and a full buffer drops its oldest frames.
//
// The render thread keeps a playhead in frame units (seq, fractional) and
// asks sample() for the two frames around it. The playhead runs at the
// display's rate, `delay_frames` behind the newest frame (a small jitter
// buffer); when it falls more than `max_lag_frames` behind (a slow GPU, a
// paused window) it jumps to the newest keyframe, so the picture never
// drifts behind live. In between, a playhead more than `catch_up_after`
// frames behind plays faster (up to twice the rate) to close the gap
// smoothly: a relay that sends faster than real time, a clock drift.
#pragma once

#include <cstdint>
#include <deque>
#include <memory>
#include <mutex>
#include <optional>
#include <string>

#include "proto/hello.hpp"
#include "proto/pose_frame.hpp"
#include "viewer/broadcast_track.hpp"

namespace mc::viewer {

struct BufferConfig {
  std::size_t capacity = 400;   // frames kept (20 s at 20 Hz, ~2.5 MB)
  double delay_frames = 2.0;    // jitter buffer: 100 ms behind the newest frame
  double max_lag_frames = 40;   // past this the playhead skips to the newest keyframe
  double catch_up_after = 6;    // past this (frames behind newest) it plays faster
};

// What the renderer needs besides poses; copied out under the lock.
struct StreamMeta {
  std::shared_ptr<const proto::Hello> hello;  // null until the first hello
  std::uint64_t hello_generation = 0;         // grows with each new hello
  std::string status;                         // "" or a human-readable line (errors, feed lost)
  bool connected = false;                     // a source is delivering frames
  int pen_left = 0, pen_right = 0;
};

// A playhead that has not started: the next sample() places it.
inline constexpr double kPlayheadUnset = -1e300;

// The two frames around the playhead and the blend factor between them.
struct Sample {
  PoseFrame a, b;
  float t = 0;             // 0 = a, 1 = b
  double playhead = 0;     // seq units after this call
  double newest = 0;       // seq of the newest frame held
  bool skipped = false;    // this call jumped to the newest keyframe
};

class FrameBuffer {
 public:
  explicit FrameBuffer(BufferConfig config = {}) : config_(config) {}

  // --- producer side (any thread) ---
  // A new stream: drops every frame and publishes the hello.
  void set_hello(const proto::Hello& hello);
  // Frames arrive in seq order. A seq that does not grow (a new timeline: a
  // seek, a restarted relay) drops the older frames first.
  void push(const PoseFrame& frame, bool keyframe);
  // Drops every frame (a seek); the playhead restarts at the next frame.
  void clear_frames();
  void set_status(std::string status);
  void set_connected(bool connected);
  void set_teams(const proto::TeamHello& left, const proto::TeamHello& right);
  void set_penalties(int left, int right);

  // --- consumer side (render thread) ---
  StreamMeta meta() const;
  // Advances `playhead` (seq units) by `frames` and fills `out`. False when
  // there is no frame yet. Start with `playhead` = kPlayheadUnset.
  bool sample(double& playhead, double frames, Sample& out);
  // The first frame at or after simulation time `time` still held (for
  // --screenshot --at), or nullopt.
  std::optional<PoseFrame> frame_at_time(int time) const;

  std::uint64_t skips() const;       // playhead jumps to a newest keyframe
  std::uint64_t dropped() const;     // frames dropped because the buffer was full
  std::size_t size() const;
  std::uint64_t timeline() const;    // grows with each clear (seek, new stream)
  // Stamina and director cues from the same stream (thread-safe itself).
  BroadcastTrack& track() { return track_; }

 private:
  struct Entry {
    PoseFrame frame;
    bool keyframe = false;
  };
  void clear_locked();

  BufferConfig config_;
  mutable std::mutex mutex_;
  std::deque<Entry> frames_;
  StreamMeta meta_;
  std::uint64_t skips_ = 0, dropped_ = 0, timeline_ = 0, seen_timeline_ = ~0ull;
  BroadcastTrack track_;
};

}  // namespace mc::viewer
