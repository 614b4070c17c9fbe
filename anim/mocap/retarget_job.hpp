// Retargets a mocap frame onto the broadcast skeleton (anim/human_skeleton):
// the legs through the feet (ankle targets and sole orientation, scaled by leg
// length, solved by anim's LegPoseJob), the torso lean and the arm swing from
// the mocap segment directions. Optionally bends a kick so that the kicking
// ankle meets a target at the contact frame: the offset is added with a smooth
// bump (1 at contact, 0 at +-half_width frames) and solved by the same IK.
//
// Spaces: the mocap frame is read in its own body frame (origin under the
// hips, facing from the hips, as motion_graph.hpp); the output is
// human_skeleton() body space (Y up, facing +X, +Z right). The pelvis is
// lowered where the broadcast skeleton's straight leg would not reach a
// planted foot. The root position on the pitch is not produced: the broadcast
// places the player.
#pragma once

#include <span>

#include "anim/mocap/mocap_clip.hpp"

namespace mc::anim::mocap {

struct MocapRetargetJob {
  const MocapClip* clip = nullptr;  // in: cgspeed joint names (sets A and C)
  float frame = 0;                  // in: frame of the clip, fractional (lerp between frames)

  int kick_foot = -1;               // in: -1 none, 0 right, 1 left
  float contact_frame = 0;          // in: frame of ball contact
  float ankle_target[3] = {0, 0, 0};  // in: kicking ankle at contact, human body space (m)
  float half_width = 9;             // in: frames over which the correction fades out

  std::span<float> angles;          // out: human_skeleton() dofs (degrees)
  float* pelvis_height = nullptr;   // out: m above the grass
  bool reached = true;              // out: false when an ankle target was out of reach
  float* ankle_targets = nullptr;   // out, optional: 6 floats, the ankle targets given to the IK
                                    // (right x y z, left x y z; x/z from the pelvis, y above the grass)

  // False when the clip lacks the named joints, the frame is outside the
  // clip, or the outputs are missing.
  bool Validate() const;
  bool Run();
};

// A clip's contact frame: where the kicking foot's toe is fastest (the data's
// README: peak toe speed at ball contact). `right` picks RightToeBase_end.
int kick_contact_frame(const MocapClip& clip, bool right);

// Scale from this clip's legs to the broadcast skeleton's (ankle drop 0.92 m).
float leg_scale(const MocapClip& clip);

}  // namespace mc::anim::mocap
