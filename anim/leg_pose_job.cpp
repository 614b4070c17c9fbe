#include "anim/leg_pose_job.hpp"

#include <algorithm>
#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/portable_math.hpp"
#include "anim/two_bone_ik_job.hpp"

namespace mc::anim {
namespace {

const std::string kYzx = "yzx", kZxy = "zxy", kZ = "z", kYz = "yz";

// Wanted sole orientation in body space: yaw about Y, then pitch about Z.
glm::mat3 sole_rotation(float yaw_deg, float pitch_deg) {
  const float a[2] = {yaw_deg, pitch_deg};
  return joint_rotation(kYz, a);
}

}  // namespace

bool LegPoseJob::Validate() const { return angles.size() >= static_cast<std::size_t>(dof::kCount); }

bool LegPoseJob::Run() {
  if (!Validate()) return false;
  const glm::mat3 pelvis = joint_rotation(kYzx, &angles[dof::kPelvis]);
  const glm::mat3 pelvis_inv = glm::transpose(pelvis);
  const glm::vec3 pelvis_pos(0.0f, pelvis_height, 0.0f);
  // Both legs stage by stage (the IK, then each ankle's two angles), each
  // leg's arithmetic as if it were solved alone: a leg is a long chain of
  // dependent trigonometry, and the two side by side keep the processor
  // busy where one leaves it waiting (issue 23: LegPoseJob and the IK were
  // 14 % of the animation's time, most of it waiting).
  TwoBoneIKJob ik[2];
  for (int side = 0; side < 2; ++side) {
    const FootTarget& f = feet[side];
    const int hip = side == 0 ? dof::kRHip : dof::kLHip;
    const int knee = side == 0 ? dof::kRKnee : dof::kLKnee;
    const glm::vec3 hip_ls(0.0f, -dims::kHipDrop, side == 0 ? dims::kHipHalfWidth : -dims::kHipHalfWidth);
    const glm::vec3 target_ls =
        pelvis_inv * (glm::vec3(f.ankle_ms[0], f.ankle_ms[1], f.ankle_ms[2]) - pelvis_pos) - hip_ls;
    // Knee direction: the sole's yaw relative to the pelvis, within the hip's twist range.
    const float pelvis_yaw = angles[dof::kPelvis];
    // (Past a quarter turn the knee direction is ambiguous: the twist fades
    // to zero at a half turn instead of flipping sides.)
    const float rel = wrap_deg(f.yaw_deg - pelvis_yaw);
    const float fade = std::fabs(rel) > 90.0f ? (180.0f - std::fabs(rel)) / 90.0f : 1.0f;
    // (+ twist turns the knee towards -Z, the body's left: outward is - for
    // the right leg and + for the left.)
    const float twist = clampf(rel, -40.0f, 40.0f) * fade + (side == 0 ? -f.knee_out_deg : f.knee_out_deg);
    TwoBoneIKJob& j = ik[side];
    j.upper_length = dims::kThigh;
    j.lower_length = dims::kShin;
    j.target[0] = target_ls.x;
    j.target[1] = target_ls.y;
    j.target[2] = target_ls.z;
    j.hinge_sign = -1;
    j.twist_deg = twist;
    j.start_zxy = &angles[hip];
    j.hinge_z = &angles[knee];
    j.reached = &reached[side];
  }
  bool ran[2];
  run_both(ik[0], ik[1], ran);
  // Ankle: the rotation left between the shin and the wanted sole, as Z then X.
  glm::mat3 local[2];
  float az[2];
  for (int side = 0; side < 2; ++side) {
    const FootTarget& f = feet[side];
    const int hip = side == 0 ? dof::kRHip : dof::kLHip;
    const int knee = side == 0 ? dof::kRKnee : dof::kLKnee;
    const glm::mat3 shin = pelvis * joint_rotation(kZxy, &angles[hip]) * joint_rotation(kZ, &angles[knee]);
    local[side] = glm::transpose(shin) * sole_rotation(f.yaw_deg, f.pitch_deg);
    const glm::vec3 fwd = local[side][0];  // where the sole's +X points, in shin space
    // Pitch of the sole's forward axis out of the shin's XZ plane: continuous
    // even when the hip cannot turn the knee as far as the sole is turned.
    az[side] = pm::atan2(fwd.y, pm::hypot(fwd.x, fwd.z)) / kDeg;
  }
  for (int side = 0; side < 2; ++side) {
    const int ankle = side == 0 ? dof::kRAnkle : dof::kLAnkle;
    const float rz[1] = {-az[side]};
    const glm::vec3 right = joint_rotation(kZ, rz) * local[side][2];  // sole's +Z after undoing az
    const float ax = pm::atan2(-right.y, right.z) / kDeg;
    angles[ankle] = clampf(az[side], -60.0f, 35.0f);
    ankle_pitch_deg[side] = az[side];
    angles[ankle + 1] = clampf(ax, -30.0f, 30.0f);
  }
  return true;
}

}  // namespace mc::anim
