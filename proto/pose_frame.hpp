// One animation frame: the 3D pose of every player and the ball at one
// 20 Hz instant. anim produces it, the codec carries it, clients draw it.
#pragma once

#include <array>
#include <cstdint>

#include "proto/world_state.hpp"

namespace mc {

// Upper bound on a skeleton's degrees of freedom, so that a frame is a
// fixed-size value with no allocation per frame.
inline constexpr int kMaxDof = 64;

// Frames are produced at twice the simulation rate.
inline constexpr int kFramesPerCycle = 2;
inline constexpr int kFrameIntervalMs = 50;

struct PlayerPose {
  Side side = Side::Neutral;
  std::uint8_t unum = 0;
  std::uint32_t state = 0;      // the server's state bits for this cycle
  // Root (pelvis) position in field coordinates: x, y as in WorldState
  // (metres), z is the height above the grass (metres).
  float x = 0, y = 0, z = 0;
  // Body heading in field degrees (same convention as PlayerState::body).
  float heading = 0;
  // Joint angles in degrees, SkeletonDef order, dof_count() values used.
  std::array<float, kMaxDof> angles{};
};

struct BallPose {
  float x = 0, y = 0, z = 0;    // field coordinates, z up (metres)
};

struct PoseFrame {
  // Frame number in the stream: 2 * state index + substep. Clients detect a
  // gap when it does not grow by one.
  std::uint32_t seq = 0;
  int time = 0;                 // simulation cycle of the state this frame is at or after
  int stoppage = 0;             // WorldState::stoppage of that state
  std::uint8_t substep = 0;     // 0: exactly at the cycle, 1: half-way to the next
  std::uint64_t server_time_ms = 0;  // wall clock when the frame left the server (Unix ms)
  PlayMode play_mode = PlayMode::Null;
  std::uint8_t score_left = 0, score_right = 0;
  BallPose ball;
  std::array<PlayerPose, kMaxPlayers> players{};
};

}  // namespace mc
