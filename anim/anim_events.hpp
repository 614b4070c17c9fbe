// Events the animator reports beside its frames, for clients (kick sounds,
// score overlays). The proto stage defines their wire (JSON) form; this is
// the in-memory vocabulary.
//
// Every event carries the seq of the frame it belongs to: it is appended when
// that frame is appended, so events and frames stay in one order.
#pragma once

#include <cstdint>

#include "proto/world_state.hpp"

namespace mc::anim {

enum class AnimEventType : std::uint8_t {
  Kick = 0,      // a foot touches the ball: side, unum, foot, contact_time_ms
  Goal = 1,      // a goal was scored: side (scoring team), score_left/right
  PlayMode = 2,  // the play mode changed: play_mode
  Card = 3,      // a player got a card: side, unum, card
};

enum class Foot : std::uint8_t { Right = 0, Left = 1 };
enum class Card : std::uint8_t { None = 0, Yellow = 1, Red = 2 };

struct AnimEvent {
  AnimEventType type = AnimEventType::Kick;
  std::uint32_t seq = 0;        // frame the event belongs to (PoseFrame::seq)
  int time = 0;                 // simulation cycle of that frame
  Side side = Side::Neutral;
  std::uint8_t unum = 0;        // 1..11 for Kick and Card, 0 otherwise
  Foot foot = Foot::Right;      // Kick only
  // Kick only: contact instant in stream time, ms since frame 0
  // (= seq * 50 for a contact on a frame; contacts fall half-way between
  // simulation cycles, see kick_planner.hpp).
  std::uint64_t contact_time_ms = 0;
  PlayMode play_mode = PlayMode::Null;  // PlayMode: the new mode; others: mode of the frame
  std::uint8_t score_left = 0, score_right = 0;  // Goal: the score after it
  Card card = Card::None;       // Card only
};

}  // namespace mc::anim
