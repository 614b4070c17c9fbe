#include "anim/event_messages.hpp"

namespace mc::anim {

proto::ControlMessage to_control_message(const AnimEvent& e) {
  switch (e.type) {
    case AnimEventType::Kick: {
      proto::KickEvent k;
      k.seq = e.seq;
      k.time = e.time;
      k.side = e.side;
      k.unum = e.unum;
      k.foot = e.foot == Foot::Left ? proto::Foot::Left : proto::Foot::Right;
      k.contact_time_ms = e.contact_time_ms;
      return k;
    }
    case AnimEventType::Goal: {
      proto::GoalEvent g;
      g.seq = e.seq;
      g.time = e.time;
      g.side = e.side;
      g.score_left = e.score_left;
      g.score_right = e.score_right;
      return g;
    }
    case AnimEventType::PlayMode: {
      proto::PlayModeEvent m;
      m.seq = e.seq;
      m.time = e.time;
      m.mode = e.play_mode;
      return m;
    }
    case AnimEventType::Card:
      break;
  }
  proto::CardEvent c;
  c.seq = e.seq;
  c.time = e.time;
  c.side = e.side;
  c.unum = e.unum;
  c.card = e.card == Card::Red ? proto::CardColor::Red : proto::CardColor::Yellow;
  return c;
}

}  // namespace mc::anim
