// Human walking and running by speed: how many steps a second, how long a
// foot stays on the ground, how far apart the feet land, whether there is a
// flight phase. The footstep planner (footsteps.hpp) takes its timing from
// here; the values and their sources are in anim/README.md ("Gait").
//
//   - Running (2.5 m/s and up): step length and cadence from Dorn, Schache &
//     Pandy 2012 (J Exp Biol 215:1944, corrected Fig. 2: up to about 7 m/s
//     speed comes from longer steps, above it from cadence), contact time
//     falling from about 0.3 s (jog) to about 0.1 s (sprint) as in Weyand et
//     al. 2000 (J Appl Physiol 89:1991), whose swing time stays near 0.35 s.
//   - Walking (below 2 m/s): cadence and step length as in Grieve & Gear 1966
//     (Ergonomics 9:379) and Murray, Drought & Kory 1964, a foot on the ground
//     for about 60 % of a stride (duty factor; 70 % in a shuffle), so both feet
//     share the ground and nothing flies.
//   - Walk to run near 2.2 m/s (Froude number 0.5; Thorstensson & Roberthson
//     1987 measured 1.9-2.2 m/s).
#pragma once

namespace mc::anim {

struct GaitTiming {
  float cadence = 0;      // steps per second (both feet together)
  float step_length = 0;  // m between successive touch-downs (of opposite feet)
  float duty = 0.6f;      // share of a stride (two steps) one foot is on the ground
  float stance_s = 0;     // s one foot is on the ground per step: 2 * duty / cadence
  float swing_s = 0;      // s one foot is in the air per stride: 2 / cadence - stance_s
  float run = 0;          // 0 walking (double support) .. 1 running (flight phase)
};

// Gait of a human moving at `speed_mps` (>= 0), with cadence capped at
// `cadence_cap` steps/s (the step grows instead). `stamina` in [0, 1]: a tired
// player takes steps up to 15 % shorter at a higher cadence.
GaitTiming human_gait(float speed_mps, float cadence_cap = 4.0f, float stamina = 1.0f);

// Step length (m) of the table at `speed_mps`, before any cadence cap:
// increasing in speed.
float gait_step_length(float speed_mps);

}  // namespace mc::anim
