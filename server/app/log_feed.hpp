// Broadcasts a game: a log played as if it were live (streamed, never read
// whole, paced in real time, looping at the end if asked), or a live
// rcssserver through its monitor port ("udp://HOST:PORT", paced by the
// server). Each state is animated, each 20 Hz frame encoded once and
// published to a channel. A live feed that is lost and comes back is told to
// spectators ("feed" messages); they stay connected meanwhile.
//
// Metadata (proto/SPEC.md section 5.3): before the first frame of each pass
// the feed sends "teams" and "score", then again whenever they change (a
// goal's "score" right after its "goal" event, on the same frame), and
// "stamina" every 20 frames, on the first frame of every 10th state.
//
// This is the glue of the pipeline ingest -> anim -> proto -> relay; each
// stage stays ignorant of the others. The ingest -> anim -> proto part is
// BroadcastPipeline (broadcast_pipeline.hpp), the code the page's
// WebAssembly module runs too: this feed only paces it, stamps real server
// times and publishes.
#pragma once

#include <atomic>
#include <condition_variable>
#include <memory>
#include <mutex>
#include <string>
#include <thread>

#include "anim/anim_events.hpp"
#include "anim/anim_config.hpp"
#include "anim/mocap/reach_overlay.hpp"
#include "server/ingest/state_source.hpp"
#include "server/relay/channel.hpp"

namespace mc::app {

struct FeedConfig {
  // A game log path, or "udp://HOST:PORT[/VERSION]" for a live rcssserver.
  std::string log_path;
  // Playback speed: 1 = real time (10 states, 20 frames per second).
  double speed = 1.0;
  // Start again at the end: the demo is a game that never ends.
  bool loop = true;
  // Live only: how long start() waits for the first state of the game.
  std::chrono::milliseconds first_state_timeout{10000};
  // Frames between keyframes (1 s at 20 Hz): the longest a joiner or a
  // skipping client waits for a picture.
  int keyframe_interval = 20;
  // Look-ahead and detail level (anim/anim_config.hpp): each channel may
  // show its own level, as in the perception study.
  anim::AnimConfig anim;
  // Optional analysis overlay (issue 9): when set, a "reach_map" control
  // message (proto SPEC 5.4) goes out every `reach_every_states` states
  // (4 = 2.5 Hz), just before the first frame at or after its cycle.
  std::shared_ptr<const anim::mocap::ReachModel> reach_model;
  int reach_every_states = 4;
};

class LogFeed {
 public:
  LogFeed(FeedConfig config, std::shared_ptr<relay::Channel> channel);
  ~LogFeed();

  // Opens the log once to check it, publishes the hello, and starts the
  // playback thread. False with `error` when the log cannot be read.
  bool start(std::string& error);
  void stop();

  // Frames published so far (all passes).
  std::uint64_t frames() const { return frames_.load(); }

 private:
  void run();
  // One pass over the log (or one live session); false when stopped.
  bool play_once();
  // Publishes a feed lost/back message and updates the channel's state.
  void announce_feed(bool lost, const std::string& detail);
  // Sleeps until `deadline` or stop(); false when stopped.
  bool wait_until(std::chrono::steady_clock::time_point deadline);

  FeedConfig config_;
  std::shared_ptr<relay::Channel> channel_;
  std::thread thread_;
  std::mutex mutex_;
  std::condition_variable wake_;
  bool stopping_ = false;
  std::atomic<std::uint64_t> frames_{0};
  std::uint32_t next_seq_ = 0;
  std::string hello_;
  bool live_ = false;
  std::unique_ptr<ingest::StateSource> first_source_;  // live: the session start() opened
  WorldState first_state_;
};

}  // namespace mc::app
