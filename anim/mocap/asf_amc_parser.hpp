// Acclaim ASF (skeleton) and AMC (motion) text in memory -> MocapClip, on the
// internal skeleton of mocap_clip.hpp. CMU bone names are renamed to the
// cgspeed BVH names (lfemur -> LeftUpLeg, ...), so ASF/AMC clips and cgspeed
// BVH clips share one topology and one name set.
//
// ASF FK (CMU): C = Rz(az) Ry(ay) Rx(ax) from `axis`, M = Rz Ry Rx from the
// dof values, B_bone = B_parent C M C^T, tip = parent_tip + B_bone dir len.
// Internally each bone becomes a joint at its start with local = C M C^T and
// offset = the parent bone's dir * len; leaf bones get an end site at their tip.
#pragma once

#include <string>
#include <string_view>
#include <vector>

#include "anim/mocap/mocap_clip.hpp"

namespace mc::anim::mocap {

struct AsfBone {
  std::string name;            // cgspeed name when known, else the ASF name
  int parent = -1;             // index into AsfSkeleton::bones, -1 = root
  glm::vec3 direction{0};      // unit, world rest frame
  double length = 0;           // ASF units
  glm::quat axis{1, 0, 0, 0};  // C
  std::string dofs;            // e.g. "xyz", "xz" in file order
};

struct AsfSkeleton {
  double length_unit = 1;      // ":units length" (0.45 for CMU)
  std::string root_order;      // e.g. "TX TY TZ RX RY RZ" -> "xyzXYZ" (lower: translation)
  std::string root_axis_order = "XYZ";  // rotation order of the root's R dofs
  glm::quat root_axis{1, 0, 0, 0};      // C of the root, from `orientation`
  std::vector<AsfBone> bones;  // parents before children
};

struct AsfResult {
  bool ok = false;
  std::string error;
  AsfSkeleton skeleton;
};
AsfResult parse_asf(std::string_view text);

struct AmcOptions {
  double frame_time = 1.0 / 120;  // AMC carries no rate; CMU is 120 Hz (60 for a few subjects)
  int max_frames = 1'000'000;
};
struct AmcResult {
  bool ok = false;
  std::string error;
  MocapClip clip;
};
// `asf` gives the bones; lengths are converted with CMU's unit (metres =
// value * 0.0254 / length_unit).
AmcResult parse_amc(std::string_view text, const AsfSkeleton& asf, const AmcOptions& options = {});

// "lfemur" -> "LeftUpLeg" etc.; the name itself when not a CMU bone.
std::string cgspeed_name(const std::string& cmu_bone);

}  // namespace mc::anim::mocap
