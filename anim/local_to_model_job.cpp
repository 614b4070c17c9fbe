#include "anim/local_to_model_job.hpp"

#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>

#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

constexpr float kDegToRad = 0.017453292519943295f;

// sin and cos of one joint angle (degrees), remembered. One frame of one
// player poses the same angles many times over (the legs' solver, the
// hands' clearance, the grass check, the speed limit all run forward
// kinematics on them), and pm::sincos is most of a joint's rotation. A
// small direct-mapped table per thread, keyed by the angle's bits: a hit
// gives exactly what the computation would, so the frames do not change.
// (Zeroed entries hold +0 degrees, whose sine and cosine are 0 and 1.)
void sincos_deg(float deg, float& s, float& c) {
  struct Entry {
    std::uint32_t bits = 0;
    float s = 0, c = 1;
  };
  constexpr unsigned kBits = 10;
  thread_local std::array<Entry, 1u << kBits> table{};
  std::uint32_t bits = 0;
  std::memcpy(&bits, &deg, sizeof bits);
  Entry& e = table[(bits * 2654435761u) >> (32 - kBits)];
  if (e.bits != bits) {
    e.bits = bits;
    pm::sincos(deg * kDegToRad, e.s, e.c);
  }
  s = e.s;
  c = e.c;
}

}  // namespace

glm::mat3 joint_rotation(const std::string& dofs, const float* deg) {
  // r * R_axis(angle), column by column: an elementary rotation mixes two
  // columns of r and keeps the third.
  glm::mat3 r(1.0f);
  for (std::size_t i = 0; i < dofs.size(); ++i) {
    float s = 0, c = 1;
    sincos_deg(deg[i], s, c);
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
