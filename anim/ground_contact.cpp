#include "anim/ground_contact.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>

#include <glm/vec4.hpp>

#include "anim/human_skeleton.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/portable_math.hpp"
#include "anim/sincos_deg.hpp"

namespace mc::anim {

float segment_lowest_ms(const Segment& seg, const glm::mat4& m) {
  // Height is the model matrix's Y row applied to a local point; its lowest
  // over a box is the centre's less each half extent times |its Y weight|
  // (a sphere's: the centre's less the radius, rotations keep it a sphere).
  const float cy = m[0][1] * seg.center[0] + m[1][1] * seg.center[1] + m[2][1] * seg.center[2] + m[3][1];
  if (seg.shape == SegmentShape::Sphere) return cy - seg.size[0];
  return cy - 0.5f * (std::fabs(m[0][1]) * seg.size[0] + std::fabs(m[1][1]) * seg.size[1] +
                      std::fabs(m[2][1]) * seg.size[2]);
}

float lowest_point_ms(const SkeletonDef& skeleton, std::span<const glm::mat4> models, std::uint32_t mask) {
  float lowest = INFINITY;
  const std::size_t n = std::min(skeleton.joints.size(), models.size());
  for (std::size_t j = 0; j < n; ++j)
    if (j >= 32 || (mask & (1u << j)) != 0) lowest = std::min(lowest, segment_lowest_ms(skeleton.joints[j].segment, models[j]));
  return lowest;
}

float rest_on_grass(const SkeletonDef& skeleton, PlayerPose& pose, float tolerance_m) {
  if (skeleton.joints.empty()) return 0;
  // One transform per joint; the small array covers the human skeleton and
  // any hello's of up to 32 joints without allocating.
  std::array<glm::mat4, 32> small;
  std::vector<glm::mat4> large;
  std::span<glm::mat4> models(small.data(), small.size());
  if (skeleton.joints.size() > small.size()) {
    large.resize(skeleton.joints.size());
    models = std::span<glm::mat4>(large);
  } else {
    models = models.first(skeleton.joints.size());
  }
  const auto dofs = static_cast<std::size_t>(std::clamp(skeleton.dof_count(), 0, kMaxDof));
  // The root at the pose's height; its own rest offset is not added
  // (proto/SPEC.md 4.1), which LocalToModelJob would.
  const auto& off = skeleton.joints[0].offset_ls;
  const glm::vec3 root(-off[0], pose.z - off[1], -off[2]);
  LocalToModelJob fk{&skeleton, std::span<const float>(pose.angles.data(), dofs), root, models};
  if (!fk.Run()) return 0;
  const float lift = std::max(0.0f, -lowest_point_ms(skeleton, models) - tolerance_m);
  pose.z += lift;
  return lift;
}

void rest_on_grass(const SkeletonDef& skeleton, PoseFrame& frame) {
  for (PlayerPose& p : frame.players)
    if (p.side != Side::Neutral) rest_on_grass(skeleton, p);
}

float level_foot(const SkeletonDef& skeleton, std::span<glm::mat4> models, std::span<float> angles, int foot,
                 int ankle_dof, float lo_deg, float hi_deg, float clear_m) {
  const JointDef& j = skeleton.joints[static_cast<std::size_t>(foot)];
  const glm::mat4& parent = models[static_cast<std::size_t>(j.parent)];
  float* a = &angles[static_cast<std::size_t>(ankle_dof)];
  auto model_at = [&](float pitch) {
    float deg[3] = {pitch, j.dofs.size() > 1 ? a[1] : 0.0f, j.dofs.size() > 2 ? a[2] : 0.0f};
    glm::mat4 local(joint_rotation(j.dofs, deg));
    local[3] = glm::vec4(j.offset_ls[0], j.offset_ls[1], j.offset_ls[2], 1.0f);
    return parent * local;
  };
  glm::mat4& m = models[static_cast<std::size_t>(foot)];
  float best = segment_lowest_ms(j.segment, m);
  const float enough = clear_m - 1e-4f;  // less float rounding (a sole lying on the grass)
  if (best >= enough) return best;
  // Level is where the sole's forward axis, parent rotation * Rz(pitch) *
  // +X, has no height: tan(pitch) = -P[0][1] / P[1][1]. Between the start
  // and level (within the bounds) the lowest corner rises; bisect for the
  // smallest turn that clears, or stop at level when even level does not.
  const glm::mat4 pt = [&] {
    glm::mat4 t(1.0f);
    t[3] = glm::vec4(j.offset_ls[0], j.offset_ls[1], j.offset_ls[2], 1.0f);
    return parent * t;
  }();
  const float level = pm::atan2(-pt[0][1], pt[1][1]) * (180.0f / 3.14159265f);
  const float lo = std::max(j.limits[0][0], lo_deg), hi = std::min(j.limits[0][1], hi_deg);
  float best_pitch = std::clamp(level, lo, hi);
  best = segment_lowest_ms(j.segment, model_at(best_pitch));
  if (best >= enough) {
    float out = a[0];
    // To 1/64 of the turn: 10 halvings cost 1 % more of the animation's
    // time and moved no figure.
    for (int k = 0; k < 6; ++k) {
      const float mid = 0.5f * (best_pitch + out);
      const float low = segment_lowest_ms(j.segment, model_at(mid));
      if (low >= enough) { best_pitch = mid; best = low; }
      else out = mid;
    }
  }
  a[0] = best_pitch;
  m = model_at(best_pitch);
  return best;
}

float min_ankle_height(float pitch_deg) {
  float s = 0, c = 1;
  sincos_deg(pitch_deg, s, c);
  // Sole corners in the foot's frame: (forward, down) = (kFootFront, -h), (-kFootBack, -h).
  const float toe = dims::kFootFront * s - dims::kAnkleHeight * c;
  const float heel = -dims::kFootBack * s - dims::kAnkleHeight * c;
  return -std::min(toe, heel);
}

}  // namespace mc::anim
