// Actions layered over locomotion: kick, tackle, goalie catch and dive. An
// ActionMotion is planned once per action (kick_planner.hpp) in field space,
// then sampled at any time around its contact instant.
#pragma once

#include <cstdint>

#include "anim/anim_events.hpp"

namespace mc::anim {

enum class MotionKind : std::uint8_t { Kick = 0, Tackle, Catch, Dive };

struct ActionMotion {
  MotionKind kind = MotionKind::Kick;
  Foot foot = Foot::Right;       // kicking foot; the leading leg of a tackle
  float ball_x = 0, ball_y = 0;  // field m: ball at contact
  float dir_x = 1, dir_y = 0;    // field unit vector: kick / tackle / dive direction
  float support_x = 0, support_y = 0;  // field m: support foot planted through contact
  float start_s = -0.15f;        // s from contact when the motion begins (<= 0)
  float follow_s = 0.25f;        // s after contact until the follow-through ends
  float end_s = 0.45f;           // s after contact when locomotion has taken over again
  float lunge_x = 0, lunge_y = 0;  // field m: root offset at contact (step-in), 0 at cycles
  std::uint64_t contact_pos = 0; // stream position of the cycle whose half-way frame is the contact
};

}  // namespace mc::anim
