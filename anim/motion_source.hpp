// Captured motion for the animator's mocap mode (issue 9), behind a small
// interface so that anim/ stays pure and does not depend on anim/mocap: the
// caller (quality tool, server) loads the clips and hands the animator a
// shared, read-only source through AnimConfig::motion_source; without one
// the animator is the keyframe animator, byte for byte.
//
// Only kicks come from capture so far: the keyframe kick (kick_planner.hpp,
// action_motion.hpp) still plans the contact, the support foot and the blend
// weights; the source replaces the kicking foot's path, the pelvis height and
// the upper body's swing with a real kick bent so that the ankle meets the
// planned contact point at tau = 0.
#pragma once

#include "anim/action_motion.hpp"

namespace mc::anim {

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
};

}  // namespace mc::anim
