// One internal skeleton and clip type for every mocap format we read (BVH,
// ASF/AMC), and the offline operations on clips: forward kinematics,
// resampling, dropping cgspeed's synthetic T-pose, retargeting offsets.
//
// Skeleton convention (BVH's, which ASF/AMC is converted to): a joint sits at
// the START of its bone, the rest orientation of every joint is the identity
// (world axes), and a joint's offset is its position in its parent's frame at
// rest. Parents come before children. Units: metres; Y is up; the cgspeed
// T-pose faces +Z, so the body's left is +X.
//   R_ms(j) = R_ms(parent) * local(j),   p_ms(j) = p_ms(parent) + R_ms(parent) * offset(j)
// and the root: R_ms(0) = local(0), p_ms(0) = root_position.
// End sites are joints with no data of their own (local rotation identity).
#pragma once

#include <string>
#include <vector>

#include <glm/gtc/quaternion.hpp>
#include <glm/vec3.hpp>

namespace mc::anim::mocap {

// CMU's length unit is 1/0.45 inch: metres = value * 0.0254 / 0.45.
inline constexpr double kCmuUnitToMetres = 0.0254 / 0.45;

struct MocapSkeleton {
  std::vector<std::string> names;   // end sites are "<parent>_end"
  std::vector<int> parents;         // -1 for the root
  std::vector<glm::vec3> offsets;   // m, in the parent's frame
  std::vector<bool> end_site;       // true: no rotation data

  int size() const { return static_cast<int>(names.size()); }
  int find(const std::string& name) const;
};

struct MocapClip {
  std::string name;
  MocapSkeleton skeleton;
  double frame_time = 1.0 / 120;    // s
  int frames = 0;
  std::vector<glm::vec3> root_position;  // m, one per frame
  std::vector<glm::quat> local;          // frames * joints, row-major by frame

  const glm::quat* pose(int frame) const { return local.data() + static_cast<std::size_t>(frame) * skeleton.names.size(); }
  glm::quat* pose(int frame) { return local.data() + static_cast<std::size_t>(frame) * skeleton.names.size(); }
};

// Model-space joint positions of one frame (m), `out` resized to the joint count.
void forward_kinematics(const MocapClip& clip, int frame, std::vector<glm::vec3>& out);

// cgspeed prepends a synthetic T-pose: root rotation zero and every rotation
// channel a small whole number of degrees (-21, 21, -16, 11, -8, 8). `degrees`
// are the frame's rotation channel values in file order.
bool looks_like_cgspeed_tpose(const std::vector<double>& rotation_degrees);

// Removes the first `count` frames.
void drop_frames(MocapClip& clip, int count);

// The clip resampled at `hz` (root lerp, rotation slerp), from t = 0 to the
// last whole sample inside the clip.
MocapClip resample(const MocapClip& clip, double hz);

// Replaces each joint's offset by the offset of the same-named joint in
// `canonical` (joints without a match keep theirs) and scales the root
// trajectory by the ratio of leg lengths, so that clips of subjects of
// different sizes give comparable joint positions. Returns the joints matched.
int retarget_offsets(MocapClip& clip, const MocapSkeleton& canonical);

// Ground-plane facing of a frame from the hip joints: the horizontal
// direction perpendicular to left-hip minus right-hip (x, z), unit length.
// `left_hip`/`right_hip` are joint indices; positions from forward_kinematics.
glm::vec2 facing_xz(const std::vector<glm::vec3>& positions, int left_hip, int right_hip);

}  // namespace mc::anim::mocap
