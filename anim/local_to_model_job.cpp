#include "anim/local_to_model_job.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <string>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/portable_math.hpp"
#include "anim/sincos_deg.hpp"

namespace mc::anim {
namespace {

int axis_index(char a) { return a == 'x' ? 0 : a == 'y' ? 1 : a == 'z' ? 2 : -1; }

constexpr float kDegToRad = 0.017453292519943295f;

// Four floats that the compiler treats as one vector (GCC's and Clang's
// vector extension; wasm and any target without vectors get the same
// arithmetic lane by lane): a column of a joint's rotation or transform.
typedef float Column __attribute__((vector_size(16)));
static_assert(sizeof(Column) == sizeof(glm::vec4));

// r * R_axis(angle) for each dof in turn, column by column: an elementary
// rotation mixes two columns of r and keeps the third. This is the hottest
// loop of the animation, so the columns are named, not indexed (they stay
// in registers), and are vectors of four floats (the fourth 0, GCC's and
// Clang's vector extension) so that a column is mixed in one vector
// operation. Each lane is the same product and sum as glm's, so the
// rotation is bit for bit the same. `sc(i, s, c)` gives dof i's sine and
// cosine.
template <typename SinCos>
glm::mat3 rotation_of(const std::string& dofs, SinCos sc) {
  Column c0 = {1, 0, 0, 0}, c1 = {0, 1, 0, 0}, c2 = {0, 0, 1, 0};
  auto mix = [](Column& p, Column& q, float s, float c) {
    const Column cp = p, cq = q;
    p = c * cp + s * cq;
    q = c * cq - s * cp;
  };
  const char* axes = dofs.data();
  for (std::size_t i = 0, n = dofs.size(); i < n; ++i) {
    float s = 0, c = 1;
    sc(i, s, c);
    if (axes[i] == 'x') mix(c1, c2, s, c);
    else if (axes[i] == 'y') mix(c2, c0, s, c);
    else mix(c0, c1, s, c);
  }
  return glm::mat3(c0[0], c0[1], c0[2], c1[0], c1[1], c1[2], c2[0], c2[1], c2[2]);
}

}  // namespace

glm::mat3 joint_rotation(const std::string& dofs, const float* deg) {
  return rotation_of(dofs, [deg](std::size_t i, float& s, float& c) { sincos_deg(deg[i], s, c); });
}

glm::mat3 joint_rotation(const std::string& dofs, const float* sin, const float* cos) {
  return rotation_of(dofs, [sin, cos](std::size_t i, float& s, float& c) {
    s = sin[i];
    c = cos[i];
  });
}

float rotation_between(const std::string& dofs, const float* a, const float* b) {
  const glm::mat3 ra = joint_rotation(dofs, a), rb = joint_rotation(dofs, b);
  float tr = 0;
  for (int i = 0; i < 3; ++i)
    for (int k = 0; k < 3; ++k) tr += ra[i][k] * rb[i][k];
  return pm::acos(clampf(0.5f * (tr - 1.0f), -1.0f, 1.0f)) / kDeg;
}

bool joint_angles(const std::string& dofs, const glm::mat3& r, float out_deg[3]) {
  if (dofs.size() != 3) return false;
  const int i = axis_index(dofs[0]), j = axis_index(dofs[1]), k = axis_index(dofs[2]);
  if (i < 0 || j < 0 || k < 0 || i == j || j == k || i == k) return false;
  // +1 for a cyclic order (xyz, yzx, zxy), -1 for the others.
  const float sign = (j - i + 3) % 3 == 1 ? 1.0f : -1.0f;
  auto at = [&](int row, int col) { return r[col][row]; };  // glm is column-major
  // asin by atan2: portable_math has no asin (anim's trigonometry must be
  // the same natively and in WebAssembly).
  const float sm = std::clamp(sign * at(i, k), -1.0f, 1.0f);
  const float mid = pm::atan2(sm, std::sqrt(std::max(0.0f, 1.0f - sm * sm)));
  const float first = pm::atan2(-sign * at(j, k), at(k, k));
  const float last = pm::atan2(-sign * at(i, j), at(i, i));
  out_deg[0] = first / kDegToRad;
  out_deg[1] = mid / kDegToRad;
  out_deg[2] = last / kDegToRad;
  return true;
}

bool LocalToModelJob::Validate() const {
  if (skeleton == nullptr) return false;
  const auto& joints = skeleton->joints;
  if (models.size() < joints.size()) return false;
  // The built-in skeleton is built once and never changes; its order and
  // dofs are checked by anim_human_skeleton_test. Checked here on every
  // pose, it was 1 % of the animation's instructions.
  if (skeleton == &human_skeleton()) return angles_deg.size() >= static_cast<std::size_t>(dof::kCount);
  // One pass (this runs before every pose): parents before children, and
  // the dofs counted against the angles.
  std::size_t dofs = 0;
  for (std::size_t i = 0; i < joints.size(); ++i) {
    if (joints[i].parent >= static_cast<int>(i) || (i > 0 && joints[i].parent < 0)) return false;
    dofs += joints[i].dofs.size();
  }
  return angles_deg.size() >= dofs;
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
    const glm::vec3 t(j.offset_ls[0], j.offset_ls[1], j.offset_ls[2]);
    if (j.parent < 0) {
      glm::mat4 local(r);
      local[3] = glm::vec4(t + root_ms, 1.0f);
      models[i] = local;
      continue;
    }
    // parent * [r | t], with the parent's and local's last rows (0 0 0 1)
    // not multiplied out: the same sums, in the same order, as glm's mat4
    // product, without its terms that are known to be zero. A column of
    // four floats in one vector operation, as in rotation_of; the last row
    // is then set to what it is.
    const glm::mat4& p = models[static_cast<std::size_t>(j.parent)];
    Column p0, p1, p2, p3;
    std::memcpy(&p0, &p[0], sizeof p0);
    std::memcpy(&p1, &p[1], sizeof p1);
    std::memcpy(&p2, &p[2], sizeof p2);
    std::memcpy(&p3, &p[3], sizeof p3);
    glm::mat4& out = models[i];
    for (int c = 0; c < 3; ++c) {
      Column col = p0 * r[c][0] + p1 * r[c][1] + p2 * r[c][2];
      col[3] = 0.0f;
      std::memcpy(&out[c], &col, sizeof col);
    }
    Column col = p0 * t[0] + p1 * t[1] + p2 * t[2] + p3;
    col[3] = 1.0f;
    std::memcpy(&out[3], &col, sizeof col);
  }
  return true;
}

}  // namespace mc::anim
