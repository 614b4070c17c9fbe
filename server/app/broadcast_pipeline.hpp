// A game's 2D states in, what its spectators receive out: the hello, the
// encoded 20 Hz pose frames and the control messages between them, in the
// order they go on the wire. This is the ingest -> anim -> proto part of the
// pipeline with nothing around it: no clock, no pacing, no sockets, no
// threads. The server's log feed paces it and stamps real server times; the
// page's WebAssembly module (wasm/) runs the same code as fast as it can, so
// that for the same states, options and server times both make the same
// bytes (tests/app/broadcast_pipeline_test.cpp, tests/web/wasm_frames).
//
// What goes before each frame (proto/SPEC.md sections 5.2, 5.3):
//  * the animator's events of that frame (kick, goal, play mode, card),
//    renumbered like the frame; a card event without a card is dropped;
//  * messages made from a state, just before that state's first frame
//    (seq 2 x index in the animator's numbering): "teams" with the pass's
//    first state and whenever a name changes, "score" likewise, "stamina"
//    with the first state and every 10th state after it (once a second),
//    and whatever the caller adds with add_state_message() (reach maps);
//  * the director's cues (server/director, SPEC.md 5.5) for that frame,
//    decided with the animator's look-ahead, renumbered like the frame.
#pragma once

#include <cstdint>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "anim/anim_config.hpp"
#include "anim/anim_events.hpp"
#include "anim/animator.hpp"
#include "proto/control_messages.hpp"
#include "proto/frame_codec.hpp"
#include "proto/game_params.hpp"
#include "proto/pose_frame.hpp"
#include "proto/world_state.hpp"
#include "server/director/director.hpp"

namespace mc::app {

struct PipelineOptions {
  // Frames between keyframes (1 s at 20 Hz): the longest a joiner waits.
  int keyframe_interval = 20;
  // Look-ahead, detail level, mocap mode (anim/anim_config.hpp).
  anim::AnimConfig anim;
};

// The hello of a game whose first state is `first` (SPEC.md section 5.1):
// the human skeleton, the field and parameters, the teams in the broadcast
// kits (a warm red left, a cold blue right).
std::string make_hello(const WorldState& first, const GameParams& params, int keyframe_interval,
                       const std::string& match_id);

// Where a pipeline's output goes, in wire order.
class PipelineSink {
 public:
  virtual ~PipelineSink() = default;
  virtual void control(std::string json) = 0;
  virtual void frame(std::string bytes, bool keyframe) = 0;
};

class BroadcastPipeline {
 public:
  // `params` as the source announced them once the first state was read.
  // Frames are numbered from `first_seq` on (a looping feed continues its
  // numbering so that spectators see no gap).
  BroadcastPipeline(const GameParams& params, PipelineOptions options, std::uint32_t first_seq = 0);
  ~BroadcastPipeline();
  BroadcastPipeline(const BroadcastPipeline&) = delete;
  BroadcastPipeline& operator=(const BroadcastPipeline&) = delete;

  // A message made from the next state pushed (a reach map): it goes out
  // just before that state's first frame, after the metadata, numbered
  // like that frame.
  void add_state_message(proto::ControlMessage message);
  // The next state in stream order; the frames that became final (two per
  // state once the look-ahead is filled) wait in the queue.
  void push(const WorldState& state);
  // End of input: the frames still held back by the look-ahead are queued.
  void finish();

  // A frame is waiting to be emitted.
  bool has_frame() const { return next_frame_ < frames_.size(); }
  // Emits the control messages due before the next waiting frame, then the
  // frame itself, numbered next_seq() and stamped with `server_time_ms`.
  void emit_next(std::uint64_t server_time_ms, PipelineSink& sink);
  // Emits every waiting frame, frame n stamped with server_time_ms(seq).
  template <typename ServerTime>
  void emit_all(ServerTime&& server_time_ms, PipelineSink& sink) {
    while (has_frame()) emit_next(server_time_ms(next_seq_), sink);
  }

  // The next frame is a keyframe (a live feed that came back: spectators
  // resync at once).
  void force_keyframe() { encoder_.force_keyframe(); }
  // The seq the next emitted frame gets.
  std::uint32_t next_seq() const { return next_seq_; }
  // Frames emitted so far.
  std::uint64_t frames_emitted() const { return emitted_; }

 private:
  void queue_state_messages(const WorldState& state);
  void compact();

  anim::Animator animator_;
  director::Director director_;
  proto::FrameEncoder encoder_;
  std::uint32_t next_seq_;
  std::uint64_t emitted_ = 0;
  std::vector<PoseFrame> frames_;        // final frames, animator numbering
  std::size_t next_frame_ = 0;           // first of frames_ not emitted yet
  std::vector<anim::AnimEvent> events_;  // their events, in frame order
  std::size_t next_event_ = 0;
  // Messages made from a state, keyed by the animator seq of its first frame.
  std::vector<std::pair<std::uint64_t, proto::ControlMessage>> timed_;
  std::size_t next_timed_ = 0;
  std::vector<proto::ControlMessage> extra_;  // add_state_message() for the next push
  std::vector<proto::DirectorCue> cues_;      // animator numbering, in order
  std::size_t next_cue_ = 0;
  // What this pass has announced so far.
  bool first_state_ = true;
  std::uint64_t first_index_ = 0;
  std::optional<std::pair<std::string, std::string>> teams_sent_;
  std::optional<proto::ScoreUpdate> score_sent_;
};

}  // namespace mc::app
