// Where frames come from: a live relay (ws_source.hpp) or a recording file
// (recording_source.hpp). A source runs on its own thread and only writes
// into a FrameBuffer, so the renderer never waits for it and it never waits
// for the renderer. Errors (refused or dropped connection, damaged file)
// become the buffer's status line and a retry, never an exception.
#pragma once

#include <string>
#include <string_view>

namespace mc::viewer {

class FrameBuffer;

// Applies a control message (JSON text) that changes what is drawn: team
// names and colours, penalty score, feed lost/back. Events and unknown
// types are ignored (SPEC.md 5.3: clients skip what they do not know).
void apply_control_message(std::string_view text, FrameBuffer& buffer);

// How long a source waits before trying again after a failure: `initial`
// doubling up to `max`, reset after a success.
struct RetryPolicy {
  double initial_s = 0.5;
  double max_s = 5.0;
};

class Source {
 public:
  virtual ~Source() = default;
  virtual void start() = 0;
  // Stops the thread; returns within about a second.
  virtual void stop() = 0;

  // Playback controls. A live relay ignores them unless it serves a replay
  // (?recording=NAME), which it steers by its replay messages.
  virtual void toggle_pause() {}
  virtual void seek_by(double /*seconds*/) {}
  virtual void set_speed(double /*speed*/) {}
  virtual double speed() const { return 1.0; }
  virtual bool paused() const { return false; }
  // True when nothing more will come without a user action (a paused
  // recording whose seek failed): --screenshot stops waiting.
  virtual bool exhausted() const { return false; }
  // Number of connection or open attempts so far (tests watch retries).
  virtual int attempts() const = 0;
  virtual std::string describe() const = 0;
};

}  // namespace mc::viewer
