// Places both feet: ankle targets in body space -> hip, knee and ankle angles
// of human_skeleton(), by closed-form two-bone IK (two_bone_ik_job.hpp) and
// an ankle that keeps the sole at the wanted orientation.
//
// Requires the pelvis dofs (yaw, pitch, roll) and the pelvis height to be
// chosen already: the hips move with the pelvis.
#pragma once

#include <span>

namespace mc::anim {

struct FootTarget {
  float ankle_ms[3] = {0, 0, 0};  // ankle joint, body (model) space, m; [1] is height
  float yaw_deg = 0;              // sole yaw in body space (+ = toes turned left)
  float pitch_deg = 0;            // sole pitch (+ = toes up)
  // The knee turned outward by this much more (deg of hip twist) for the
  // same ankle: planted legs whose thighs come too close (issue 23).
  float knee_out_deg = 0;
};

struct LegPoseJob {
  float pelvis_height = 1.0f;    // in: pelvis joint height above the grass (m)
  FootTarget feet[2];            // in: [0] right, [1] left
  std::span<float> angles;       // in/out: pelvis dofs read, leg dofs written (deg)
  bool reached[2] = {true, true};  // out: false when a target was clamped to reach
  // out: the ankle pitch the wanted sole needs (deg, before the ankle's
  // limits clamp it): above 35 the sole cannot lie as wanted.
  float ankle_pitch_deg[2] = {0, 0};

  // False when `angles` is shorter than the human skeleton's dof count.
  bool Validate() const;
  bool Run();
};

}  // namespace mc::anim
