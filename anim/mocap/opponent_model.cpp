#include "anim/mocap/opponent_model.hpp"

#include <cmath>

namespace mc::anim::mocap {

float cost_at(const CapabilityMap& map, const AgentPose& pose, float wx, float wy) {
  // World -> map frame: translate, then rotate by -heading.
  const float dx = wx - pose.x, dy = wy - pose.y;
  const float c = std::cos(pose.heading), s = std::sin(pose.heading);
  const int cell = map.grid.index(dx * c + dy * s, -dx * s + dy * c);
  return cell < 0 ? kUnreached : map.cost[static_cast<std::size_t>(cell)];
}

std::vector<float> place_map(const CapabilityMap& map, const AgentPose& pose, const MapGrid& world) {
  std::vector<float> out(static_cast<std::size_t>(world.cells()));
  for (int i = 0; i < world.cells(); ++i) out[static_cast<std::size_t>(i)] = cost_at(map, pose, world.center_x(i), world.center_y(i));
  return out;
}

std::vector<std::uint8_t> safe_cells(const std::vector<float>& own, const std::vector<float>& opp, float action_time,
                                     float margin) {
  std::vector<std::uint8_t> out(own.size(), 0);
  for (std::size_t i = 0; i < own.size() && i < opp.size(); ++i)
    out[i] = own[i] != kUnreached && opp[i] > own[i] + action_time + margin ? 1 : 0;
  return out;
}

int best_safe_cell(const std::vector<std::uint8_t>& safe, const std::function<float(int)>& score) {
  int best = -1;
  float best_score = 0;
  for (std::size_t i = 0; i < safe.size(); ++i) {
    if (!safe[i]) continue;
    const float sc = score(static_cast<int>(i));
    if (best < 0 || sc > best_score) { best = static_cast<int>(i); best_score = sc; }
  }
  return best;
}

}  // namespace mc::anim::mocap
