#include "anim/local_to_model_job.hpp"

#include <cmath>

#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

constexpr float kDegToRad = 0.017453292519943295f;

}  // namespace

glm::mat3 joint_rotation(const std::string& dofs, const float* deg) {
  // r * R_axis(angle), column by column: an elementary rotation mixes two
  // columns of r and keeps the third.
  glm::mat3 r(1.0f);
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    const float a = deg[i] * kDegToRad;
    float s = 0, c = 1;
    pm::sincos(a, s, c);
    int p = 0, q = 1;  // z: columns 0 and 1
    if (dofs[i] == 'x') { p = 1; q = 2; }
    else if (dofs[i] == 'y') { p = 2; q = 0; }
    const glm::vec3 cp = r[p], cq = r[q];
    r[p] = c * cp + s * cq;
    r[q] = c * cq - s * cp;
  }
  return r;
}

bool LocalToModelJob::Validate() const {
  if (skeleton == nullptr) return false;
  const auto& joints = skeleton->joints;
  if (models.size() < joints.size()) return false;
  if (angles_deg.size() < static_cast<std::size_t>(skeleton->dof_count())) return false;
  for (std::size_t i = 0; i < joints.size(); ++i)
    if (joints[i].parent >= static_cast<int>(i) || (i > 0 && joints[i].parent < 0)) return false;
  return true;
}

bool LocalToModelJob::Run() const {
  if (!Validate()) return false;
  const auto& joints = skeleton->joints;
  const float* a = angles_deg.data();
  for (std::size_t i = 0; i < joints.size(); ++i) {
    const JointDef& j = joints[i];
    const float* ja = a;
    a += j.dofs.size();
    if (i < 32 && (joint_mask & (1u << i)) == 0) continue;
    const glm::mat3 r = joint_rotation(j.dofs, ja);
    glm::mat4 local(r);
    local[3] = glm::vec4(j.offset_ls[0], j.offset_ls[1], j.offset_ls[2], 1.0f);
    if (j.parent < 0) {
      local[3] += glm::vec4(root_ms, 0.0f);
      models[i] = local;
    } else {
      models[i] = models[static_cast<std::size_t>(j.parent)] * local;
    }
  }
  return true;
}

}  // namespace mc::anim
