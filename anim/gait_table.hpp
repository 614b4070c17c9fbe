// The cyclic locomotion keyframe table and its sampling (Virtual RoboCup,
// section 4): keyframes annotated with their position gain, a posture index
// advanced by the distance covered, and inbetweening between the two nearest
// keyframes.
//
// One cycle is a step with the right leg followed by a step with the left
// leg. Like the paper's table, the reference cycle covers 4.10 m; a player's
// actual cycle length (stride) scales the gains. Phase 0 is the right foot's
// touch-down, phase 0.5 the left foot's.
//
// The keyframes hold the rhythmic channels of the whole body at unit
// amplitude; the feet themselves are placed on the grass by footsteps.hpp
// from the same phase, so that a planted foot does not slide.
#pragma once

#include <span>

namespace mc::anim {

inline constexpr float kReferenceCycleM = 4.10f;

// One keyframe; channels are unit amplitudes that locomotion scales by speed.
struct GaitKey {
  float gain_m;        // position gain since key 0 in the reference cycle (m), increasing
  float bob_walk;      // pelvis height, walking: -1 lowest (double support) .. +1 highest
  float bob_run;       // pelvis height, running: -1 lowest (mid-stance) .. +1 highest (flight)
  float pelvis_twist;  // pelvis yaw, +1 = right hip forward (turned left)
  float pelvis_roll;   // pelvis roll, +1 = swing side dropped
  float torso_twist;   // counter-rotation of the shoulders
  float r_arm, l_arm;  // shoulder flexion, +1 = swung forward
};

// The table: 20 keys, denser around touch-downs, left step mirroring the right.
std::span<const GaitKey> gait_keys();

// Channels inbetweened at one posture index (same units as GaitKey).
struct GaitSample {
  float bob_walk = 0, bob_run = 0, pelvis_twist = 0, pelvis_roll = 0, torso_twist = 0;
  float r_arm = 0, l_arm = 0;
};

// Posture index arithmetic. The index is a position in the reference cycle,
// in [0, kReferenceCycleM).
//   advance: add `distance_m` covered by a player whose actual cycle length
//   is `cycle_m`, wrapping around; a non-positive cycle leaves it unchanged.
float advance_posture(float posture_m, float distance_m, float cycle_m);
// Phase in [0, 1) of a posture index.
inline float posture_phase(float posture_m) { return posture_m / kReferenceCycleM; }

// Inbetweening: finds the keys f- and f+ around `posture_m` (cyclically) and
// blends them by proximity (ozz SamplingJob shape).
struct SampleGaitJob {
  std::span<const GaitKey> keys;  // in: a table as gait_keys() returns
  float posture_m = 0;            // in: posture index, wrapped into the cycle
  GaitSample* output = nullptr;   // out
  int* key_before = nullptr;      // out, optional: index of f-
  float* weight_after = nullptr;  // out, optional: weight of f+ in [0, 1)

  // False when the table has fewer than 2 keys, gains do not increase within
  // the reference cycle, or output is missing.
  bool Validate() const;
  bool Run() const;
};

}  // namespace mc::anim
