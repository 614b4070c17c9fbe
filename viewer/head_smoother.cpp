#include "viewer/head_smoother.hpp"

#include <algorithm>
#include <cmath>
#include <string>

namespace mc::viewer {

float limit_turn(float* cur, const float* target, const std::vector<std::vector<int>>& groups, double dt,
                 float max_deg_per_s, float tau) {
  if (!(dt > 0)) return 0.0f;
  const float ease = 1.0f - std::exp(-static_cast<float>(dt) / tau);
  const float budget = max_deg_per_s * static_cast<float>(dt);
  float f = ease;
  for (const auto& g : groups) {
    float sum = 0;
    for (int i : g) sum += target[i] - cur[i];
    if (std::fabs(sum) * ease > budget) f = std::min(f, budget / std::fabs(sum));
  }
  for (const auto& g : groups)
    for (int i : g) cur[i] += (target[i] - cur[i]) * f;
  return f;
}

HeadSmoother::HeadSmoother(const SkeletonDef& skeleton) {
  std::array<std::vector<int>, 3> by_axis;  // x, y, z
  int index = 0;
  for (const JointDef& j : skeleton.joints) {
    std::string name = j.name;
    std::transform(name.begin(), name.end(), name.begin(), [](unsigned char c) { return std::tolower(c); });
    const bool head = name.find("neck") != std::string::npos || name.find("head") != std::string::npos;
    for (char axis : j.dofs) {
      if (head && axis >= 'x' && axis <= 'z' && index < kMaxDof) by_axis[static_cast<std::size_t>(axis - 'x')].push_back(index);
      ++index;
    }
  }
  for (auto& g : by_axis)
    if (!g.empty()) {
      indices_.insert(indices_.end(), g.begin(), g.end());
      groups_.push_back(std::move(g));
    }
}

void HeadSmoother::apply(PoseFrame& frame, double dt) {
  for (std::size_t k = 0; k < frame.players.size(); ++k) {
    PlayerPose& p = frame.players[k];
    Drawn& d = drawn_[k];
    const bool jumped = !d.valid || !(dt < 0.5) || std::hypot(p.x - d.x, p.y - d.y) > 3.0f;
    d.x = p.x;
    d.y = p.y;
    if (jumped) {
      d.valid = true;
      for (int i : indices_) d.angles[static_cast<std::size_t>(i)] = p.angles[static_cast<std::size_t>(i)];
      continue;
    }
    limit_turn(d.angles.data(), p.angles.data(), groups_, dt);
    for (int i : indices_) p.angles[static_cast<std::size_t>(i)] = d.angles[static_cast<std::size_t>(i)];
  }
}

}  // namespace mc::viewer
