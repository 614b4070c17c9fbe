// Transition blending (Kovar et al. 2002): when the motion jumps from frame i
// of one clip to frame j of another, the k frames i..i+k-1 and j..j+k-1 are
// blended with a sinusoid-like ease-in/ease-out weight, root positions lerped
// and joint rotations slerped, after placing the target motion on the source
// with the floor-plane alignment of frame_distance.hpp.
#pragma once

#include <vector>

#include "anim/mocap/frame_distance.hpp"
#include "anim/mocap/mocap_clip.hpp"

namespace mc::anim::mocap {

// Weight of the SOURCE motion at blend frame p in [0, k):
// alpha(p) = 2((p+1)/k)^3 - 3((p+1)/k)^2 + 1, falling smoothly from ~1 to 0.
float transition_alpha(int p, int k);

struct TransitionBlendJob {
  const MocapClip* from = nullptr;  // in: source clip
  int from_frame = 0;               // in: first blended frame of the source
  const MocapClip* to = nullptr;    // in: target clip, same skeleton
  int to_frame = 0;                 // in: first blended frame of the target
  int length = 10;                  // in: k, frames blended (both ranges must fit)
  PlanarAlign align;                // in: maps the target's floor frame onto the source's
  // out: length root positions and length * joints local rotations.
  glm::vec3* root_out = nullptr;
  glm::quat* local_out = nullptr;

  // False when a clip is missing, skeleton sizes differ, a range does not fit
  // or an output is missing.
  bool Validate() const;
  bool Run() const;
};

}  // namespace mc::anim::mocap
