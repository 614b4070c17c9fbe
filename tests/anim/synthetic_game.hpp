// Builds small synthetic 2D games for the anim tests: every player active,
// parked on a grid, and helpers to script one player's motion.
#pragma once

#include <vector>

#include "anim/animator.hpp"
#include "anim/human_skeleton.hpp"
#include "proto/world_state.hpp"

namespace mc::anim::testing {

inline WorldState base_state(std::uint64_t index) {
  WorldState s;
  s.index = index;
  s.time = static_cast<int>(index) + 1;
  s.play_mode = PlayMode::PlayOn;
  for (int side = 0; side < 2; ++side) {
    for (int u = 1; u <= kPlayersPerSide; ++u) {
      PlayerState& p = s.players[static_cast<std::size_t>(player_index(side == 0 ? Side::Left : Side::Right, u))];
      p.side = side == 0 ? Side::Left : Side::Right;
      p.unum = static_cast<std::uint8_t>(u);
      p.state = state_bits::kStand;
      p.x = (side == 0 ? -1 : 1) * (5.0 + 3.0 * u);
      p.y = -20.0 + 4.0 * u;
      p.body = side == 0 ? 0 : 180;
      p.stamina = 8000;
    }
  }
  return s;
}

// A game of `n` cycles in which left player 1 runs along +x at `speed` m/cycle
// from cycle `start` on, facing its direction of travel.
inline std::vector<WorldState> run_game(int n, double speed, int start = 5) {
  std::vector<WorldState> g;
  double x = -30;
  for (int i = 0; i < n; ++i) {
    WorldState s = base_state(static_cast<std::uint64_t>(i));
    if (i >= start) x += speed;
    PlayerState& p = s.players[0];
    p.x = x;
    p.y = 0;
    p.vx = i >= start ? speed : 0;
    g.push_back(s);
  }
  return g;
}

// A whole game animated at once: frames, per-frame info and events.
struct AnimatedGame {
  std::vector<PoseFrame> frames;
  std::vector<FrameInfo> infos;
  std::vector<AnimEvent> events;
};
inline AnimatedGame animate_game(const std::vector<WorldState>& game, const AnimConfig& cfg = {}) {
  AnimatedGame r;
  Animator a(human_skeleton(), GameParams{}, cfg);
  a.set_frame_info_sink(&r.infos);
  for (const WorldState& s : game) a.push(s, r.frames, &r.events);
  a.finish(r.frames, &r.events);
  return r;
}

}  // namespace mc::anim::testing
