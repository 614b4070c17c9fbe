#include "anim/joint_speed_limit.hpp"

#include <cmath>
#include <cstddef>

#include "anim/local_to_model_job.hpp"
#include "anim/player_animation.hpp"

namespace mc::anim {

void limit_joint_speed(const SkeletonDef& skel, const float* last, std::span<float> a, bool limited[kHumanJointCount],
                       int kicking_foot) {
  const std::size_t kick_thigh = kicking_foot == 0 ? kRThigh : kLThigh;
  std::size_t k = 0;
  for (std::size_t j = 0; j < skel.joints.size() && j < kHumanJointCount; ++j) {
    const JointDef& jd = skel.joints[j];
    const std::size_t n = jd.dofs.size();
    const bool kicking = kicking_foot >= 0 && j >= kick_thigh && j < kick_thigh + 3;  // thigh, shin, foot
    const bool knee = j == kRShin || j == kLShin;
    const float cap = kicking ? kMaxKickLegStepDeg
                      : knee  ? kMaxKneeStepDeg
                      : j >= kRThigh ? kMaxLegStepDeg
                                     : kMaxUpperStepDeg;
    limited[j] = false;
    float sum = 0;
    for (std::size_t d = 0; d < n; ++d) sum += std::fabs(a[k + d] - last[k + d]);
    if (sum > cap) {
      for (int pass = 0; pass < 3; ++pass) {
        const float ang = rotation_between(jd.dofs, last + k, &a[k]);
        if (ang <= cap) break;
        const float scale = (cap - 0.1f) / ang;
        for (std::size_t d = 0; d < n; ++d) a[k + d] = last[k + d] + (a[k + d] - last[k + d]) * scale;
        limited[j] = true;
      }
    }
    k += n;
  }
}

}  // namespace mc::anim
