// Test and benchmark support: a 36-dof humanoid skeleton like the one anim
// builds, and a gait synthesizer that turns 2D world states (from a real
// log) into plausible 20 Hz pose frames when mc::anim is not linked.
#pragma once

#include <vector>

#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"
#include "proto/world_state.hpp"

namespace mc::proto::testing {

SkeletonDef humanoid_skeleton();

// Deterministic frames: `count` frames of a small scripted game (players
// jog in circles, some stand, two are inactive, the ball flies).
std::vector<PoseFrame> scripted_frames(const SkeletonDef& skeleton, int count, unsigned seed = 1);

// Turns consecutive world states into pose frames, two per state (the
// second half-way to the next state), with a gait driven by distance run.
class GaitSynth {
 public:
  explicit GaitSynth(const SkeletonDef& skeleton);
  // Appends the frames for `state` (interpolating towards `next`).
  void add(const WorldState& state, const WorldState& next, std::vector<PoseFrame>& out);

 private:
  void pose_player(const PlayerState& a, const PlayerState& b, double t, int slot, const BallState& ball,
                   PlayerPose& out);
  SkeletonDef skeleton_;
  double phase_[kMaxPlayers] = {};
  std::uint32_t seq_ = 0;
};

}  // namespace mc::proto::testing
