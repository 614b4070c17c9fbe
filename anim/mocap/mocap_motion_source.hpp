// The animator's mocap mode (anim/motion_source.hpp) on CMU kicks: each kick
// of the game takes the kicking foot's path, the pelvis height, the torso
// lean and the arm swing of one captured kick (MocapRetargetJob), bent by IK
// so that the kicking ankle is on the keyframe plan's contact point at the
// contact instant (tau = 0). The clips are right-footed; a left-footed kick
// plays its clip mirrored. Pure and read-only after construction: one source
// serves every animator (the clips are loaded by the caller, see
// io/motion_source_files.hpp).
#pragma once

#include <vector>

#include "anim/mocap/mocap_clip.hpp"
#include "anim/mocap/motion_graph.hpp"
#include "anim/motion_source.hpp"

namespace mc::anim::mocap {

class MocapMotionSource final : public MotionSource {
 public:
  // Right-footed kick clips (any frame rate) with the cgspeed joint names;
  // the contact frame of each is found by kick_contact_frame. Clips the
  // retargeting cannot use (missing joints, under 2 frames) are left out.
  explicit MocapMotionSource(std::vector<MocapClip> kicks);
  // With a slow walk too: `graph` built on `graph_clips` (same order), walks
  // start at `start_node`. Without a usable graph walk() returns false.
  MocapMotionSource(std::vector<MocapClip> kicks, MotionGraph graph, std::vector<MocapClip> graph_clips, int start_node);
  bool has_walk() const { return start_node_ >= 0; }

  std::size_t kick_count() const { return kicks_.size(); }
  // The clip a kick plays (a function of its contact time, so a kick keeps
  // its clip when later touches are merged into it); -1 with no clip.
  int clip_for(const ActionMotion& m) const;
  const MocapClip& clip(int i) const { return kicks_[static_cast<std::size_t>(i)].clip; }
  int contact_frame(int i) const { return kicks_[static_cast<std::size_t>(i)].contact; }

  bool kick(const ActionMotion& m, float tau, float heading, float root_x, float root_y,
            ActionSample& s) const override;
  // The graph walk (GraphSteerJob) played time-warped so that the clip's
  // ground speed is the wanted one (rate 0.5 to 2), retargeted; a foot is
  // planted while it is the lower one or within 3 cm of it.
  bool walk(WalkCursor& cursor, float speed, float turn_deg_s, float dt, WalkPose& out) const override;

 private:
  struct Kick {
    MocapClip clip;
    int contact = 0;
  };
  std::vector<Kick> kicks_;
  MotionGraph graph_;
  std::vector<MocapClip> graph_clips_;
  int start_node_ = -1;
};

}  // namespace mc::anim::mocap
