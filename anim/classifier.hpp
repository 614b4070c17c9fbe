// Task-level commands from 2D data (Virtual RoboCup, section 1): for each
// player and cycle, what the player is doing, decided from that cycle's state,
// its neighbours and the state bits; then smoothed so that one noisy cycle
// does not flip the decision.
#pragma once

#include <cstdint>
#include <span>

#include "proto/game_params.hpp"
#include "proto/world_state.hpp"

namespace mc::anim {

enum class Action : std::uint8_t {
  Stand = 0, Walk, Run, Backpedal, SideStep, Turn,   // locomotion
  Kick, Tackle, Catch, Dive, Teleport, Disconnected,  // events and states
};
inline constexpr int kActionCount = 12;
const char* action_name(Action a);
inline bool is_locomotion(Action a) { return a <= Action::Turn; }

// One player's view of three consecutive cycles; `next` is null at the end
// of the stream, `prev` at its start.
struct ClassifyInput {
  const PlayerState* prev = nullptr;
  const PlayerState* cur = nullptr;
  const PlayerState* next = nullptr;
  const BallState* ball = nullptr;      // ball at `cur`'s cycle (dive vs catch)
  const PlayerType* type = nullptr;     // the player's heterogeneous type
};

// Thresholds, in rcssserver units (m/cycle, deg).
struct ClassifyParams {
  float stand_speed = 0.03f;      // below: stand or turn (0.3 m/s)
  float run_fraction = 0.25f;     // of the type's top speed: walk below, run above
  float turn_deg = 15.0f;         // body turn over two cycles that makes a standing player turn
  float teleport_m = 1.6f;        // displacement no dash can give in one cycle
  float dive_lateral_m = 0.7f;    // ball this far beside a catching goalie: dive
};

// Raw decision for the middle cycle. Cur must be set.
Action classify_raw(const ClassifyInput& in, const ClassifyParams& params = {});

// Smoothing: the decision for window[centre]. A locomotion decision that
// disagrees with equal neighbours on both sides takes theirs; event decisions
// (kick, tackle, catch, dive, teleport, disconnected) come from state bits and
// are kept. `window` holds raw decisions of consecutive cycles.
Action smooth_action(std::span<const Action> window, std::size_t centre);

}  // namespace mc::anim
