// The director in the native viewer (issue 20): the same cues as the page
// (proto::DirectorCue, SPEC.md 5.5), the same shots (web/src/director.js's
// rigs, in C++), the same cuts. A replay cue plays the goal again from the
// viewer's own history of drawn frames, segment by segment from its angles,
// marked REPLAY in the HUD; meanwhile the live stream goes on, and the
// picture returns straight to live after it (the page instead resumes where
// it left and catches up at 3x). No OpenGL here: tests drive it.
#pragma once

#include <cstdint>
#include <deque>
#include <optional>
#include <set>
#include <vector>

#include <glm/vec3.hpp>

#include "anim/leg_blend.hpp"
#include "proto/director_cue.hpp"
#include "proto/hello.hpp"
#include "proto/pose_frame.hpp"

namespace mc::viewer {

// Where the camera stands and looks for a shot, in scene space (X along the
// pitch, Y up, Z towards the main stand), and its vertical field of view.
struct ShotRig {
  glm::vec3 eye{0.0f}, look{0.0f};
  float fov = 40.0f;
};

// The page's shotRig: `frame` gives the ball and the cue's subject; `angle`
// is the replay segment's (replay cues only); aspect = width / height.
ShotRig shot_rig(const proto::DirectorCue& cue, std::optional<proto::ReplayAngle> angle, const PoseFrame& frame,
                 const proto::FieldGeometry& field, float aspect);

// The last frames drawn, by seq, to replay from (20 s at 20 Hz).
class FrameHistory {
 public:
  explicit FrameHistory(std::size_t capacity = 400) : capacity_(capacity) {}
  void add(const PoseFrame& f);  // frames with a seq not above the newest are ignored (but a new timeline resets)
  bool covers(double from, double to) const;
  // The blend of the two frames around `seq`; false when it is not held.
  // With `feet`, the feet's step too (blend_frames).
  bool at(double seq, int dof_count, PoseFrame& out, const anim::LegBlend* feet = nullptr) const;
  void clear() { frames_.clear(); }
  std::size_t size() const { return frames_.size(); }

 private:
  std::size_t capacity_;
  std::deque<PoseFrame> frames_;
};

class DirectorView {
 public:
  struct Step {
    bool cut = false;        // the camera must cut (snap)
    bool replaying = false;  // draw history at `replay_seq`
    double replay_seq = 0;
  };

  // Once per drawn picture: `live_seq` is the live playhead (seq units), dt
  // seconds since the last picture, `rate` the stream's speed (x real time),
  // `enabled` the director's camera is on screen (replays only then).
  Step update(double live_seq, double dt, const std::vector<proto::DirectorCue>& cues, bool enabled,
              const FrameHistory& history, double rate = 1.0);

  // The cue framing the picture (a replay cue while replaying); null before the first.
  const proto::DirectorCue* current() const { return has_current_ ? &current_ : nullptr; }
  // The replay segment's angle while replaying.
  std::optional<proto::ReplayAngle> angle() const;
  bool replaying() const { return replay_.has_value(); }
  std::uint64_t cuts() const { return cuts_; }
  std::uint64_t replays() const { return replays_; }

 private:
  bool show(const proto::DirectorCue& cue, bool jumped);

  proto::DirectorCue current_;
  bool has_current_ = false;
  std::optional<double> last_pos_;
  std::optional<proto::DirectorCue> replay_;
  std::size_t segment_ = 0;
  double replay_pos_ = 0;
  std::set<std::uint32_t> done_;
  std::uint64_t cuts_ = 0, replays_ = 0;
};

}  // namespace mc::viewer
