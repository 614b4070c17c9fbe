// The broadcast's reach overlay: per frame, which team gets to each cell of
// the pitch first, and who gets to the ball first, from every player's
// position, heading, speed and player type, using a capability map of human
// motion (capability_map.hpp) scaled to the player type's top speed.
//
// Runtime and pure: ReachModel is built once from a precomputed map; the job
// reads spans, writes caller-owned arrays and allocates nothing.
//
// Frames: field coordinates of rcssserver (metres, +y to the right of +x,
// angles from +x towards +y), times in seconds.
#pragma once

#include <array>
#include <cstdint>
#include <span>

#include "anim/mocap/capability_map.hpp"
#include "proto/game_params.hpp"
#include "proto/world_state.hpp"

namespace mc::anim::mocap {

// A capability map ready for lookups: the map in seconds, the human's speed it
// was made at, and for the far field (outside the map or cells no walk
// reached) the extra time by bearing that the map shows over straight-line
// motion (turning around costs more than going ahead).
struct ReachModel {
  CapabilityMap map;
  float hz = 30;                      // map frames per second
  float reference_speed = 1;          // m/s: the human's straight-ahead speed in the map
  static constexpr int kBearings = 32;
  std::array<float, kBearings> far_delay{};  // s, at reference speed, by bearing bin (0 centred on ahead, towards +y)
};

// Fits reference_speed (90th percentile of distance / time over the cells
// within 0.2 rad of straight ahead, beyond 1.5 m) and far_delay (per bearing,
// the median of time minus distance / speed over the reached cells beyond 1.5 m).
ReachModel make_reach_model(CapabilityMap map, float hz);

struct ReachPlayer {
  float x = 0, y = 0;       // m
  float heading = 0;        // rad
  float vx = 0, vy = 0;     // m/s
  float top_speed = 1.05f * 10;  // m/s, the player type's real top speed
  float glide = 0.667f;     // s of current velocity carried before the reaction (decay / (1 - decay) cycles)
  std::int8_t team = 0;     // 0 left, 1 right, -1 absent
};

// Seconds for `p` to reach (wx, wy).
float reach_time(const ReachModel& model, const ReachPlayer& p, float wx, float wy);

// Players of a world state (absent and inactive slots get team -1).
void reach_players(const WorldState& world, const GameParams& params, std::span<ReachPlayer, kMaxPlayers> out);

enum class ReachOwner : std::uint8_t { None = 0, Left = 1, Right = 2, Contested = 3 };

struct ReachOverlayJob {
  const ReachModel* model = nullptr;         // in
  std::span<const ReachPlayer> players;      // in
  MapGrid field{53, 34, 2.0f, -53.0f, -34.0f};  // in: the cells to colour (default: the pitch, 2 m)
  float contested_margin = 0.2f;             // in: s; closer than this is Contested
  float ball_x = 0, ball_y = 0;              // in: m
  float ball_vx = 0, ball_vy = 0;            // in: m per cycle
  float ball_decay = 0.94f;                  // in: per cycle
  float cycle = 0.1f;                        // in: s per cycle
  int ball_horizon = 50;                     // in: cycles of ball path searched

  std::span<std::uint8_t> owner;             // out: field.cells() ReachOwner values
  std::span<float> time;                     // out, optional: field.cells() winner's time (s)
  int* ball_player = nullptr;                // out: index into players of who reaches the ball first, -1 if none
  float* ball_time = nullptr;                // out, optional: when (s)

  // False when the model or outputs are missing or sized wrong, or there
  // are more than kMaxPlayers players.
  bool Validate() const;
  bool Run() const;
};

}  // namespace mc::anim::mocap
