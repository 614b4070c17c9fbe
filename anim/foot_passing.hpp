// A foot in the air passes the other foot on its own side (issue 23: legs
// through each other). The footsteps (footsteps.cpp) move a swinging
// ankle a share of the way to its landing spot each frame; this takes that
// move and keeps the foot a sole's width to its own side of the other one
// wherever the two are side by side: where it ends, and on its way there
// past a foot that stood on the grass as the frame began (the clients'
// blend starts from it). A foot left crossed by a fast turn uncrosses
// where it is, a pass length off, and passes on the next frame. Field
// space; no I/O.
#pragma once

#include "anim/body_frame.hpp"

namespace mc::anim {

// m along the body within which two feet are side by side.
inline constexpr float kPassLength = 0.32f;

struct PassingStep {
  float side = 1;               // the swinging foot's side: +1 right (+Z), -1 left
  float from_x = 0, from_y = 0; // its ankle at the frame's start (field m)
  float other_x = 0, other_y = 0;  // the other ankle now (field m)
  bool other_stood = false;     // the other foot stood on the grass as the frame began...
  float stood_x = 0, stood_y = 0;  // ...there (its ankle, field m)
  float min_gap = 0.17f;        // m sideways the two ankles keep when side by side
  float root_dx = 0, root_dy = 0;  // the root's move this frame (field m)
  float past_hip = 0.55f;       // m a frame the ankle may move relative to the root
};

// `x`, `y`: where the swing takes the ankle this frame (field m), moved in
// place so that it passes on its own side, and still no faster past the
// hip than `past_hip`. `body`: this frame's root and heading.
void pass_other_foot(const BodyFrame& body, const PassingStep& step, float& x, float& y);

}  // namespace mc::anim
