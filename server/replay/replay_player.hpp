// One spectator's private replay of a recording: it reads the file, paces
// the frames at 20 Hz times the chosen speed, and obeys the spectator's
// controls. Frames are decoded and encoded again for the spectator, so that
// after any jump the stream restarts cleanly at a keyframe with a continuous
// sequence. Everything runs on the spectator's strand: no locks.
//
// Spectator -> server (text, JSON):
//   {"type":"replay","action":"pause"|"play"|"toggle"}
//   {"type":"replay","action":"seek","time":CYCLE}
//   {"type":"replay","action":"speed","speed":0.25..8}
//   {"type":"replay","action":"next_goal"|"prev_goal"}
// Server -> spectator, on every change and once a second:
//   {"type":"replay","name":..,"time":..,"paused":..,"speed":..,
//    "first_time":..,"last_time":..,"goals":[{"time":..,"side":"l"|"r"}]}
//   (a time shift adds "live_edge":true while it has caught up with the
//   recording, which trails the live feed by up to one chunk, ~1 s)
#pragma once

#include <boost/asio/any_io_executor.hpp>
#include <boost/asio/steady_timer.hpp>
#include <chrono>
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "proto/frame_codec.hpp"
#include "server/record/recording_reader.hpp"
#include "server/relay/replay_source.hpp"

namespace mc::replay {

// Where a goal happened in a recording.
struct GoalMark {
  int time = 0;       // simulation cycle of the goal
  Side side = Side::Neutral;  // the team that scored
};

// What a recording holds, found once by reading it through.
struct RecordingSummary {
  int first_time = 0, last_time = 0;
  std::vector<GoalMark> goals;
  int score_left = 0, score_right = 0;  // at last_time
  bool empty = true;                    // no frame seen yet

  // Takes in one more frame in stream order (a goal is a score change).
  void note(const PoseFrame& f);
};

// Reads the whole recording and notes its time range and goals (score
// changes in the frame headers). False + error on a damaged file.
bool summarize(record::RecordingReader& reader, RecordingSummary& out, std::string& error);

class ReplayPlayer : public relay::ReplaySource, public std::enable_shared_from_this<ReplayPlayer> {
 public:
  // `follow`: the recording is still being written (a live channel's time
  // shift). At its end the player waits for more instead of pausing, and
  // the summary grows with the frames it reads.
  ReplayPlayer(boost::asio::any_io_executor executor, std::string name,
               std::unique_ptr<record::RecordingReader> reader, RecordingSummary summary,
               bool follow = false);

  // Starts producing frames (call once, after construction).
  void start();

  std::shared_ptr<relay::Channel> channel() override { return channel_; }
  void on_message(const relay::SpectatorMessage& message) override;
  void close() override;

  // For tests and status: the simulation time of the last frame sent, or
  // of the seek about to be done (see request_seek()).
  int time() const { return time_; }
  bool paused() const { return paused_; }
  double speed() const { return speed_; }

 private:
  void schedule();
  void on_tick(boost::system::error_code ec);
  bool send_next();
  void publish(const PoseFrame& f);  // encodes f and sends it on the channel
  // A spectator's jump. Scrubbing the seek bar sends a seek per mouse move,
  // and each costs a decode from the keyframe before it (up to 220 frames,
  // a few ms): the first seek of a 50 ms window is done at once, later ones
  // only set the target, which is done when the window ends. So a drag is
  // followed at 20 pictures a second, and a flood of seeks costs at most
  // 20 seeks a second.
  void request_seek(int time);
  void on_seek_timer(boost::system::error_code ec);
  void seek_pending();
  int clamp_time(int time);
  void seek(int time);
  void publish_status();
  proto::FrameEncoder& encoder();

  boost::asio::steady_timer timer_;
  boost::asio::steady_timer seek_timer_;  // ends the window of request_seek()
  std::chrono::steady_clock::time_point last_seek_{};
  std::optional<int> pending_seek_;
  std::string name_;
  std::string name_json_;  // name_ as a JSON string, for the status
  std::unique_ptr<record::RecordingReader> reader_;
  RecordingSummary summary_;
  std::shared_ptr<relay::Channel> channel_;
  // See encoder(). On the heap, made when needed: its model is tens of KB.
  std::unique_ptr<proto::FrameEncoder> encoder_;
  std::vector<std::string> controls_;
  std::uint32_t seq_ = 0;
  int time_ = 0;
  int frames_since_status_ = 0;
  double speed_ = 1.0;
  bool paused_ = false;
  bool closed_ = false;
  bool follow_ = false;
};

}  // namespace mc::replay
