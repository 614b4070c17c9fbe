#include "anim/mocap/transition_blend.hpp"

namespace mc::anim::mocap {

float transition_alpha(int p, int k) {
  if (k <= 0) return 0;
  const float t = static_cast<float>(p + 1) / static_cast<float>(k);
  return 2 * t * t * t - 3 * t * t + 1;
}

bool TransitionBlendJob::Validate() const {
  if (!from || !to || !root_out || !local_out || length < 1) return false;
  if (from->skeleton.size() != to->skeleton.size()) return false;
  return from_frame >= 0 && to_frame >= 0 && from_frame + length <= from->frames && to_frame + length <= to->frames;
}

bool TransitionBlendJob::Run() const {
  if (!Validate()) return false;
  const auto nj = static_cast<std::size_t>(from->skeleton.size());
  const glm::quat yaw = glm::angleAxis(align.theta, glm::vec3(0, 1, 0));
  for (int p = 0; p < length; ++p) {
    const float a = transition_alpha(p, length);
    const auto fa = static_cast<std::size_t>(from_frame + p), fb = static_cast<std::size_t>(to_frame + p);
    root_out[p] = glm::mix(align.apply(to->root_position[fb]), from->root_position[fa], a);
    const glm::quat* qa = from->pose(from_frame + p);
    const glm::quat* qb = to->pose(to_frame + p);
    glm::quat* out = local_out + static_cast<std::size_t>(p) * nj;
    for (std::size_t j = 0; j < nj; ++j) {
      const glm::quat b = j == 0 ? yaw * qb[j] : qb[j];  // the root turns with the alignment
      out[j] = glm::slerp(b, qa[j], a);
    }
  }
  return true;
}

}  // namespace mc::anim::mocap
