// BVH text (in memory) -> MocapClip. Handles what the CMU conversions do:
// per-joint rotation order from CHANNELS, CMU length units, "End Site",
// "Frames:<tab>598", "Frame Time: .0083333", CR/LF/CRLF mixed, trailing
// spaces, and cgspeed's synthetic first-frame T-pose (detected and dropped).
// Errors say "row:col: what" and never throw.
#pragma once

#include <string>
#include <string_view>

#include "anim/mocap/mocap_clip.hpp"

namespace mc::anim::mocap {

struct BvhOptions {
  double unit_to_metres = kCmuUnitToMetres;  // cgspeed BVH is in CMU units
  bool drop_cgspeed_tpose = true;            // drop frame 0 when it is the synthetic T-pose
  int max_joints = 256;                      // hostile-input bounds
  int max_frames = 1'000'000;
};

struct BvhResult {
  bool ok = false;
  std::string error;      // "row:col: message" when !ok
  MocapClip clip;
  bool dropped_tpose = false;
};

BvhResult parse_bvh(std::string_view text, const BvhOptions& options = {});

// Rotation from Euler angles (degrees) about the axes in `axes` ("ZYX" means
// R = Rz(a0) * Ry(a1) * Rx(a2): intrinsic, in the order listed).
glm::quat euler_to_quat(const char* axes, int count, const double* degrees);

}  // namespace mc::anim::mocap
