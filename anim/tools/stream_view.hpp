// What a spectator receives of an animated game, decoded again: the quality
// tool measures this, never the animator's own bookkeeping (issue 23).
//
// The frames go through the wire format (proto::FrameEncoder with the
// server's keyframe interval, then proto::FrameDecoder), the skeleton through
// the hello's JSON, and the animator's events through their control
// messages' JSON. So every figure is of the quantized values a client draws
// (angles to 0.99 deg, positions to 1 cm), posed on the hello's skeleton,
// with the kicks a client is told about.
//
// Drawn frames: the page and the native viewer draw at the display's rate
// and blend two 20 Hz frames linearly (web/src/model/interp.js,
// viewer/interpolate.cpp); blend_like_clients() is that blend, so that the
// same metrics can be taken at the drawing rate; the clients then rest each
// pose on the grass (anim::rest_on_grass). With a LegBlend it also takes
// the clients' step for the feet (anim/leg_blend.hpp) after the blend.
#pragma once

#include <string>
#include <vector>

#include "anim/anim_events.hpp"
#include "anim/leg_blend.hpp"
#include "proto/control_messages.hpp"
#include "proto/game_params.hpp"
#include "proto/pose_frame.hpp"
#include "proto/skeleton.hpp"

namespace mc::anim::tools {

struct StreamView {
  SkeletonDef skeleton;               // the hello's, parsed back from its JSON
  double ball_radius = 0.085;         // m, the hello's field.ball_radius
  std::vector<PoseFrame> frames;      // decoded, in stream order
  std::vector<proto::KickEvent> kicks;  // the "kick" control messages, parsed back
  std::size_t encoded_bytes = 0;      // the frames' size on the wire (headers included)
};

// Encodes and decodes `frames` (the animator's output, in stream order) and
// `events` as the server sends them, with the hello of `skeleton` and
// `params`. False with `error` when anything fails to decode.
bool view_stream(const SkeletonDef& skeleton, const GameParams& params, const std::vector<PoseFrame>& frames,
                 const std::vector<AnimEvent>& events, StreamView& out, std::string& error);

// The clients' blend of two consecutive frames at t in [0, 1): positions and
// angles linearly, the heading the short way round, a player whose root
// jumps more than 5 m held at `a` up to t = 0.5 and at `b` after
// (interp.js's teleport rule); seq, time and state from `a`. Then `legs`,
// when given, re-aims the planted legs (null: the clients' blend).
void blend_like_clients(const PoseFrame& a, const PoseFrame& b, float t, int dof_count, PoseFrame& out,
                        const LegBlend* legs);

}  // namespace mc::anim::tools
