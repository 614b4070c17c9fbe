#include "anim/event_messages.hpp"

#include <variant>

#include <gtest/gtest.h>

namespace mc::anim {
namespace {

TEST(EventMessages, KickKeepsFootAndContactTime) {
  AnimEvent e;
  e.type = AnimEventType::Kick;
  e.seq = 1203;
  e.time = 601;
  e.side = Side::Right;
  e.unum = 9;
  e.foot = Foot::Left;
  e.contact_time_ms = 60150;
  const proto::ControlMessage m = to_control_message(e);
  ASSERT_TRUE(std::holds_alternative<proto::KickEvent>(m));
  const auto& k = std::get<proto::KickEvent>(m);
  EXPECT_EQ(k.seq, 1203u);
  EXPECT_EQ(k.time, 601);
  EXPECT_EQ(k.side, Side::Right);
  EXPECT_EQ(k.unum, 9);
  EXPECT_EQ(k.foot, proto::Foot::Left);
  EXPECT_EQ(k.contact_time_ms, 60150u);
}

TEST(EventMessages, GoalPlayModeAndCard) {
  AnimEvent e;
  e.type = AnimEventType::Goal;
  e.side = Side::Left;
  e.score_left = 2;
  e.score_right = 1;
  const auto g = std::get<proto::GoalEvent>(to_control_message(e));
  EXPECT_EQ(g.side, Side::Left);
  EXPECT_EQ(g.score_left, 2);
  e.type = AnimEventType::PlayMode;
  e.play_mode = PlayMode::CornerKickR;
  EXPECT_EQ(std::get<proto::PlayModeEvent>(to_control_message(e)).mode, PlayMode::CornerKickR);
  e.type = AnimEventType::Card;
  e.card = Card::Red;
  e.unum = 4;
  const auto c = std::get<proto::CardEvent>(to_control_message(e));
  EXPECT_EQ(c.card, proto::CardColor::Red);
  EXPECT_EQ(c.unum, 4);
}

}  // namespace
}  // namespace mc::anim
