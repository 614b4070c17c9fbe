// Captured motion for the animator's mocap mode (issue 9), behind a small
// interface so that anim/ stays pure and does not depend on anim/mocap: the
// caller (quality tool, server) loads the clips and hands the animator a
// shared, read-only source through AnimConfig::motion_source; without one
// the animator is the keyframe animator, byte for byte.
//
// Kicks: the keyframe kick (kick_planner.hpp,
// action_motion.hpp) still plans the contact, the support foot and the blend
// weights; the source replaces the kicking foot's path, the pelvis height and
// the upper body's swing with a real kick bent so that the ankle meets the
// planned contact point at tau = 0.
//
// Slow walking: a source with a walk (walk()) drives the legs, pelvis, torso
// lean and arms of a player walking forwards below 1.5 m/s, cross-faded with
// the keyframe gait; the animator (player_animation.cpp) holds the feet the
// capture plants where they landed and guards the cadence. Running, side
// steps, backpedalling and standing turns stay keyframed.
#pragma once

#include "anim/action_motion.hpp"
#include "anim/leg_pose_job.hpp"

namespace mc::anim {

// Where one player is in a captured walk: kept by the animator per player,
// read and advanced only by the source. node < 0: start afresh.
struct WalkCursor {
  int node = -1;
  float frac = 0;  // fraction of the way to the next frame
};

// One frame of a captured walk in body space (x forward, y up, z right,
// x/z from the pelvis; human_skeleton() conventions).
struct WalkPose {
  FootTarget feet[2];             // [0] right, [1] left
  bool planted[2] = {false, false};  // the foot bears weight (the animator holds it on the grass)
  float pelvis_height = 0.9f;
  float torso_lean = 0;           // deg, the torso's sagittal dof
  float shoulder[2] = {0, 0};     // deg, flexion, [0] right
  float elbow[2] = {0, 0};        // deg
};

class MotionSource {
 public:
  virtual ~MotionSource() = default;

  // `s` is the keyframe sample of kick `m` at `tau` (s from contact) for a
  // player at 2D root (root_x, root_y) with body heading `heading` (field
  // deg): the arguments sample_action() got. Rewrites the kicking foot's
  // ankle target, the pelvis height and the torso lean and arm swing of `s`;
  // keeps its weights and the support foot. At tau = 0 the kicking ankle
  // target is (m.contact_x, m.contact_y, m.contact_h). Returns false and
  // leaves `s` alone when it has no capture for `m` (not a kick, no clip).
  // Must be safe to call from several animators at once (const, no state).
  virtual bool kick(const ActionMotion& m, float tau, float heading, float root_x, float root_y,
                    ActionSample& s) const = 0;

  // Slow walk: advances `cursor` by `dt` seconds towards a ground speed
  // (m/s along the facing) and turn rate (deg/s, + to the right) and writes
  // the frame. False (nothing written) when the source has no walk.
  virtual bool walk(WalkCursor& cursor, float speed, float turn_deg_s, float dt, WalkPose& out) const {
    (void)cursor, (void)speed, (void)turn_deg_s, (void)dt, (void)out;
    return false;
  }
};

}  // namespace mc::anim
