#include "anim/joint_limits.hpp"

#include <array>
#include <cstddef>

#include "anim/human_skeleton.hpp"

namespace mc::anim {
namespace {

// True when v was out of [lo, hi] and is now at the nearer end.
bool clamp_one(float& v, float lo, float hi) {
  if (v < lo) {
    v = lo;
    return true;
  }
  if (v > hi) {
    v = hi;
    return true;
  }
  return false;
}

// The built-in skeleton's limits, one (min, max) per dof, made once:
// walking the joints' dof strings for them on every call was 1.5 % of the
// animation's instructions (the skeleton is built once and never changes).
const std::array<std::array<float, 2>, dof::kCount>& human_limits() {
  static const auto table = [] {
    std::array<std::array<float, 2>, dof::kCount> t{};
    std::size_t n = 0;
    for (const JointDef& j : human_skeleton().joints)
      for (std::size_t d = 0; d < j.dofs.size(); ++d) t[n++] = {j.limits[d][0], j.limits[d][1]};
    return t;
  }();
  return table;
}

}  // namespace

int clamp_to_limits(const SkeletonDef& skeleton, std::span<float> angles) {
  int out = 0;
  if (&skeleton == &human_skeleton() && angles.size() >= static_cast<std::size_t>(dof::kCount)) {
    const auto& limits = human_limits();
    for (std::size_t k = 0; k < limits.size(); ++k) out += clamp_one(angles[k], limits[k][0], limits[k][1]);
    return out;
  }
  std::size_t k = 0;
  for (const JointDef& j : skeleton.joints)
    for (std::size_t d = 0; d < j.dofs.size() && k < angles.size(); ++d, ++k)
      out += clamp_one(angles[k], j.limits[d][0], j.limits[d][1]);
  return out;
}

void clamp_legs_to_limits(const SkeletonDef& skeleton, std::span<float> angles) {
  std::size_t k = dof::kRHip;
  for (std::size_t j = kRThigh; j <= kLFoot; ++j) {
    const JointDef& jd = skeleton.joints[j];
    for (std::size_t d = 0; d < jd.dofs.size(); ++d, ++k) clamp_one(angles[k], jd.limits[d][0], jd.limits[d][1]);
  }
}

}  // namespace mc::anim
