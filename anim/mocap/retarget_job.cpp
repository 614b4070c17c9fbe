#include "anim/mocap/retarget_job.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

#include <glm/geometric.hpp>

#include "anim/human_skeleton.hpp"
#include "anim/leg_pose_job.hpp"

namespace mc::anim::mocap {

namespace {

constexpr float kDeg = 180.0f / std::numbers::pi_v<float>;

struct Names {
  int hips, lhip, rhip, lfoot, rfoot, ltoe, rtoe, spine, rarm, rfore, rhand, larm, lfore, lhand;
};
Names names(const MocapSkeleton& s) {
  return {s.find("Hips"), s.find("LeftUpLeg"), s.find("RightUpLeg"), s.find("LeftFoot"), s.find("RightFoot"),
          s.find("LeftToeBase"), s.find("RightToeBase"), s.find("Spine1"), s.find("RightArm"), s.find("RightForeArm"),
          s.find("RightHand"), s.find("LeftArm"), s.find("LeftForeArm"), s.find("LeftHand")};
}
bool complete(const Names& n) {
  for (int v : {n.hips, n.lhip, n.rhip, n.lfoot, n.rfoot, n.ltoe, n.rtoe, n.spine, n.rarm, n.rfore, n.rhand, n.larm, n.lfore, n.lhand})
    if (v < 0) return false;
  return true;
}

// Positions at a fractional frame (joint positions lerped).
void positions_at(const MocapClip& c, float frame, std::vector<glm::vec3>& out) {
  const int a = std::clamp(static_cast<int>(std::floor(frame)), 0, c.frames - 1);
  const int b = std::min(a + 1, c.frames - 1);
  const float t = std::clamp(frame - static_cast<float>(a), 0.0f, 1.0f);
  std::vector<glm::vec3> pb;
  forward_kinematics(c, a, out);
  if (t <= 0 || b == a) return;
  forward_kinematics(c, b, pb);
  for (std::size_t i = 0; i < out.size(); ++i) out[i] = glm::mix(out[i], pb[i], t);
}

// Body frame of a pose: origin on the floor under the hips, facing from the hips.
struct Body {
  glm::vec3 origin;
  glm::vec2 fwd, right;
  glm::vec3 to_body(const glm::vec3& p) const {  // -> (x forward, y up, z right)
    const glm::vec3 d = p - origin;
    return {d.x * fwd.x + d.z * fwd.y, d.y, d.x * right.x + d.z * right.y};
  }
  glm::vec3 dir(const glm::vec3& v) const { return {v.x * fwd.x + v.z * fwd.y, v.y, v.x * right.x + v.z * right.y}; }
};
Body body_of(const std::vector<glm::vec3>& p, const Names& n) {
  Body b;
  const glm::vec2 f = facing_xz(p, n.lhip, n.rhip);
  b.fwd = f;
  b.right = glm::vec2(-f.y, f.x);
  b.origin = glm::vec3(p[static_cast<std::size_t>(n.hips)].x, 0, p[static_cast<std::size_t>(n.hips)].z);
  return b;
}

float smooth_bump(float d, float half) {
  const float u = std::fabs(d) / std::max(half, 1e-3f);
  if (u >= 1) return 0;
  return 0.5f * (1 + std::cos(std::numbers::pi_v<float> * u));
}

}  // namespace

float leg_scale(const MocapClip& clip) {
  const auto& s = clip.skeleton;
  float drop = 0;
  for (int j = s.find("RightFoot"); j > 0; j = s.parents[static_cast<std::size_t>(j)]) drop -= s.offsets[static_cast<std::size_t>(j)].y;
  return drop > 0.3f ? (dims::kHipDrop + dims::kThigh + dims::kShin) / drop : 1.0f;
}

int kick_contact_frame(const MocapClip& clip, bool right) {
  const int toe = clip.skeleton.find(right ? "RightToeBase_end" : "LeftToeBase_end");
  if (toe < 0 || clip.frames < 2) return 0;
  std::vector<glm::vec3> a, b;
  float best = -1;
  int at = 0;
  for (int f = 1; f < clip.frames; ++f) {
    forward_kinematics(clip, f - 1, a);
    forward_kinematics(clip, f, b);
    const float v = glm::length(b[static_cast<std::size_t>(toe)] - a[static_cast<std::size_t>(toe)]);
    if (v > best) { best = v; at = f; }
  }
  return at;
}

bool MocapRetargetJob::Validate() const {
  if (!clip || !pelvis_height || angles.size() < static_cast<std::size_t>(dof::kCount)) return false;
  if (!(frame >= 0 && frame <= static_cast<float>(clip->frames - 1))) return false;
  return complete(names(clip->skeleton)) && kick_foot >= -1 && kick_foot <= 1;
}

bool MocapRetargetJob::Run() {
  if (!Validate()) return false;
  const Names n = names(clip->skeleton);
  std::vector<glm::vec3> p;
  positions_at(*clip, frame, p);
  const Body body = body_of(p, n);
  const float k = leg_scale(*clip);
  auto at = [&](int j) { return body.to_body(p[static_cast<std::size_t>(j)]) * k; };
  std::fill(angles.begin(), angles.end(), 0.0f);
  const glm::vec3 hips = at(n.hips);
  *pelvis_height = hips.y;
  // Torso lean: the spine's direction in the sagittal plane (+ leans back).
  const glm::vec3 spine = at(n.spine) - hips;
  angles[dof::kTorso + 1] = std::atan2(-spine.x, spine.y) * kDeg;
  // Arms: shoulder flexion from the upper arm, elbow from the forearm.
  for (int side = 0; side < 2; ++side) {
    const int arm = side == 0 ? n.rarm : n.larm, fore = side == 0 ? n.rfore : n.lfore, hand = side == 0 ? n.rhand : n.lhand;
    const glm::vec3 u = glm::normalize(at(fore) - at(arm)), l = glm::normalize(at(hand) - at(fore));
    const int sh = side == 0 ? dof::kRShoulder : dof::kLShoulder, el = side == 0 ? dof::kRElbow : dof::kLElbow;
    angles[static_cast<std::size_t>(sh)] = std::atan2(u.x, -u.y) * kDeg - angles[dof::kTorso + 1];
    angles[static_cast<std::size_t>(el)] = std::acos(std::clamp(glm::dot(u, l), -1.0f, 1.0f)) * kDeg;
  }
  // Feet: ankle positions relative to the pelvis on the grass, sole from foot -> toe.
  LegPoseJob legs;
  legs.pelvis_height = hips.y;
  legs.angles = angles;
  for (int side = 0; side < 2; ++side) {
    const int foot = side == 0 ? n.rfoot : n.lfoot, toe = side == 0 ? n.rtoe : n.ltoe;
    glm::vec3 ankle = at(foot);
    ankle.x -= hips.x;
    ankle.z -= hips.z;
    if (side == kick_foot) {
      // Where this ankle is at contact in the clip, vs. where it must be.
      std::vector<glm::vec3> pc;
      positions_at(*clip, contact_frame, pc);
      const Body bc = body_of(pc, n);
      glm::vec3 c = bc.to_body(pc[static_cast<std::size_t>(foot)]) * k;
      const glm::vec3 hc = bc.to_body(pc[static_cast<std::size_t>(n.hips)]) * k;
      c.x -= hc.x;
      c.z -= hc.z;
      const glm::vec3 want(ankle_target[0], ankle_target[1], ankle_target[2]);
      ankle += (want - c) * smooth_bump(frame - contact_frame, half_width);
    }
    const glm::vec3 v = body.dir(p[static_cast<std::size_t>(toe)] - p[static_cast<std::size_t>(foot)]);
    const glm::vec3 rest = clip->skeleton.offsets[static_cast<std::size_t>(toe)];
    const float rest_pitch = std::atan2(rest.y, std::hypot(rest.x, rest.z));
    FootTarget& f = legs.feet[side];
    f.ankle_ms[0] = ankle.x;
    f.ankle_ms[1] = ankle.y;
    f.ankle_ms[2] = ankle.z;
    f.yaw_deg = std::atan2(-v.z, v.x) * kDeg;
    f.pitch_deg = (std::atan2(v.y, std::hypot(v.x, v.z)) - rest_pitch) * kDeg;
  }
  // The broadcast skeleton's legs are not the subject's: lower the pelvis
  // where a straight leg could not reach its ankle target, so that planted
  // feet stay planted (the IK softens the last half percent of the reach).
  const float reach = 0.99f * 0.995f * (dims::kThigh + dims::kShin);
  for (int side = 0; side < 2; ++side) {
    const FootTarget& f = legs.feet[side];
    const float dz = f.ankle_ms[2] - (side == 0 ? dims::kHipHalfWidth : -dims::kHipHalfWidth);
    const float h2 = f.ankle_ms[0] * f.ankle_ms[0] + dz * dz;
    if (h2 < reach * reach) legs.pelvis_height = std::min(legs.pelvis_height, f.ankle_ms[1] + dims::kHipDrop + std::sqrt(reach * reach - h2));
  }
  *pelvis_height = legs.pelvis_height;
  if (ankle_targets != nullptr)
    for (int side = 0; side < 2; ++side)
      for (int c = 0; c < 3; ++c) ankle_targets[3 * side + c] = legs.feet[side].ankle_ms[c];
  legs.Run();
  reached = legs.reached[0] && legs.reached[1];
  return true;
}

}  // namespace mc::anim::mocap
