// The animator's events as the stream's control messages
// (proto/control_messages.hpp, SPEC.md section 5.2): a one-to-one mapping,
// so that the server forwards AnimEvents without knowing their fields.
#pragma once

#include "anim/anim_events.hpp"
#include "proto/control_messages.hpp"

namespace mc::anim {

// Kick -> KickEvent, Goal -> GoalEvent, PlayMode -> PlayModeEvent,
// Card -> CardEvent (a Card event with Card::None becomes a yellow card).
proto::ControlMessage to_control_message(const AnimEvent& e);

}  // namespace mc::anim
