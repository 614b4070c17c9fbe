// The reach overlay as a stream of "reach_map" control messages: every
// `every_states` world states (4 = 2.5 Hz at rcssserver's 10 Hz) it runs
// ReachOverlayJob on the state's players and ball and fills a
// proto::ReachMapUpdate. Pure and reusable per channel: it owns its buffers,
// so push() allocates nothing after the first call.
#pragma once

#include <array>
#include <memory>
#include <vector>

#include "anim/mocap/reach_overlay.hpp"
#include "proto/control_messages.hpp"

namespace mc::anim::mocap {

class ReachMapPublisher {
 public:
  // `model` must not be null. `field` is the grid sent (default: 2 m cells over
  // the pitch and its surroundings).
  explicit ReachMapPublisher(std::shared_ptr<const ReachModel> model, int every_states = 4,
                             MapGrid field = MapGrid{53, 34, 2.0f, -53.0f, -34.0f});

  // True (with `out` filled, seq left 0 for the caller to set) on every
  // `every_states`-th state, counting from the first; false otherwise.
  bool push(const WorldState& state, const GameParams& params, proto::ReachMapUpdate& out);

 private:
  std::shared_ptr<const ReachModel> model_;
  int every_;
  MapGrid field_;
  long count_ = 0;
  std::array<ReachPlayer, kMaxPlayers> players_{};
  std::vector<std::uint8_t> owner_;
};

}  // namespace mc::anim::mocap
