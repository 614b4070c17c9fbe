// A live relay as a source: a Boost.Beast WebSocket client on its own
// thread (one io_context, so every handler runs in order there). It reads
// the hello, decodes binary pose frames with proto's FrameDecoder and
// applies the control messages the renderer cares about (teams, score,
// feed lost/back). A refused, failed or dropped connection is shown on the
// status line and retried with backoff; a corrupt frame is counted and the
// decoder waits for the next keyframe (SPEC.md 4.5).
#pragma once

#include <atomic>
#include <cstdint>
#include <memory>
#include <string>
#include <thread>

#include "viewer/frame_buffer.hpp"
#include "viewer/source.hpp"

namespace mc::viewer {

struct WsUrl {
  std::string host, port = "80", target = "/ws";
};
// Accepts ws://HOST:PORT/PATH?QUERY, http://... (the page's address: the
// stream is at /ws) and HOST:PORT. False + error for anything else.
bool parse_ws_url(const std::string& text, WsUrl& out, std::string& error);

class WsSource : public Source {
 public:
  WsSource(WsUrl url, FrameBuffer& buffer, RetryPolicy retry = {});
  ~WsSource() override;

  void start() override;
  void stop() override;
  // Replay spectators (?recording=NAME) steer the server's replay.
  void toggle_pause() override;
  void seek_by(double seconds) override;
  void set_speed(double speed) override;
  double speed() const override { return speed_.load(); }
  bool paused() const override { return paused_.load(); }
  int attempts() const override { return attempts_.load(); }
  std::string describe() const override;

  std::uint64_t frames() const { return frames_.load(); }
  std::uint64_t corrupt_frames() const { return corrupt_.load(); }

 private:
  struct Session;
  void send_text(std::string text);

  WsUrl url_;
  FrameBuffer& buffer_;
  RetryPolicy retry_;
  std::shared_ptr<Session> session_;
  std::thread thread_;
  std::atomic<int> attempts_{0};
  std::atomic<std::uint64_t> frames_{0}, corrupt_{0};
  std::atomic<double> speed_{1.0};
  std::atomic<bool> paused_{false};  // a replay's state, from its status messages
  std::atomic<int> last_time_{0};
};

}  // namespace mc::viewer
