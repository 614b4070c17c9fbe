// Fast whole-state copy used where a record is parsed into a scratch state
// and only handed out when it parsed completely (so a bad record never
// leaves the caller's state half-written).
#pragma once

#include <memory>
#include <type_traits>

#include "proto/world_state.hpp"

namespace mc::ingest {

// PlayerState's copy *assignment* is memberwise (std::pair inside an
// optional), but its copy construction and destruction are trivial, so
// re-constructing in place copies the bytes in one go.
static_assert(std::is_trivially_copy_constructible_v<PlayerState> &&
              std::is_trivially_destructible_v<PlayerState>);

inline void copy_state(const WorldState& from, WorldState& to) {
  to.index = from.index;
  to.time = from.time;
  to.stoppage = from.stoppage;
  to.play_mode = from.play_mode;
  to.left = from.left;
  to.right = from.right;
  to.ball = from.ball;
  for (std::size_t i = 0; i < from.players.size(); ++i) {
    std::destroy_at(&to.players[i]);
    std::construct_at(&to.players[i], from.players[i]);
  }
}

}  // namespace mc::ingest
