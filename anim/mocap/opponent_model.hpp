// Using capability maps at run time: a precomputed map placed at an agent's
// pose, and the paper's opponent model (its equation 3): the cells an agent
// reaches safely before its opponent are those where
//   Co > Cd + Ts + eps
// (opponent's cost, own cost, own action time, margin; all in frames), and
// among them the caller's score picks the best.
#pragma once

#include <cstdint>
#include <functional>
#include <vector>

#include "anim/mocap/capability_map.hpp"

namespace mc::anim::mocap {

// An agent's pose in a world frame: x, y in metres (y to the right of +x, as
// in rcssserver) and heading in radians from +x towards +y.
struct AgentPose {
  float x = 0, y = 0, heading = 0;
};

// Cost (frames) for an agent at `pose` to reach world point (wx, wy), read
// from its map (nearest cell); kUnreached outside the map or where unreached.
float cost_at(const CapabilityMap& map, const AgentPose& pose, float wx, float wy);

// The map placed at `pose`, sampled at every cell centre of `world`.
std::vector<float> place_map(const CapabilityMap& map, const AgentPose& pose, const MapGrid& world);

// 1 where opponent > own + action_time + margin (kUnreached for the opponent
// counts as infinitely late; unreached for us is never safe).
std::vector<std::uint8_t> safe_cells(const std::vector<float>& own, const std::vector<float>& opponent,
                                     float action_time, float margin);

// The safe cell with the highest score(cell); -1 when none is safe.
int best_safe_cell(const std::vector<std::uint8_t>& safe, const std::function<float(int cell)>& score);

}  // namespace mc::anim::mocap
