#include "proto/control_messages.hpp"

#include <gtest/gtest.h>

#include <limits>

namespace mc::proto {
namespace {

ControlMessage round_trip(const ControlMessage& m) {
  ControlMessage back;
  std::string error;
  EXPECT_TRUE(control_from_json(to_json(m), back, error)) << error << " in " << to_json(m);
  return back;
}

TEST(ControlMessages, KickRoundTrips) {
  KickEvent k{120, 60, Side::Right, 9, Foot::Left, 6025};
  const std::string text = to_json(ControlMessage{k});
  EXPECT_NE(text.find("\"type\":\"kick\""), std::string::npos);
  EXPECT_NE(text.find("\"foot\":\"left\""), std::string::npos);
  const auto back = std::get<KickEvent>(round_trip(k));
  EXPECT_EQ(back.seq, 120u);
  EXPECT_EQ(back.side, Side::Right);
  EXPECT_EQ(back.unum, 9);
  EXPECT_EQ(back.foot, Foot::Left);
  EXPECT_EQ(back.contact_time_ms, 6025u);
}

TEST(ControlMessages, EveryTypeRoundTrips) {
  const auto goal = std::get<GoalEvent>(round_trip(GoalEvent{10, 5, Side::Left, 2, 1}));
  EXPECT_EQ(goal.score_left, 2);
  EXPECT_EQ(goal.side, Side::Left);
  const auto pm = std::get<PlayModeEvent>(round_trip(PlayModeEvent{11, 5, PlayMode::KickOffR}));
  EXPECT_EQ(pm.mode, PlayMode::KickOffR);
  EXPECT_NE(to_json(ControlMessage{PlayModeEvent{11, 5, PlayMode::KickOffR}}).find("kick_off_r"), std::string::npos);
  const auto card = std::get<CardEvent>(round_trip(CardEvent{12, 6, Side::Right, 4, CardColor::Red}));
  EXPECT_EQ(card.card, CardColor::Red);
  const auto score = std::get<ScoreUpdate>(round_trip(ScoreUpdate{13, 6, 3, 4, 1, 0}));
  EXPECT_EQ(score.right, 4);
  EXPECT_EQ(score.pen_left, 1);
  const auto teams = std::get<TeamsUpdate>(round_trip(TeamsUpdate{0, {"A", "#ff0000", "#000000"}, {"B", "#00ff00", "#ffffff"}}));
  EXPECT_EQ(teams.right.name, "B");
  EXPECT_EQ(teams.left.color, "#ff0000");
  const auto feed = std::get<FeedStatus>(round_trip(FeedStatus{true, 99, 1700000000000ull, "no datagram for 3 s"}));
  EXPECT_TRUE(feed.lost);
  EXPECT_EQ(feed.detail, "no datagram for 3 s");
  EXPECT_FALSE(std::get<FeedStatus>(round_trip(FeedStatus{false, 100, 1, ""})).lost);
  StaminaUpdate st{200, 100, {}, {}};
  st.left.fill(8000);
  st.left[6] = 4123;
  st.right.fill(-1);
  st.right[0] = 7000;
  const auto stamina = std::get<StaminaUpdate>(round_trip(st));
  EXPECT_EQ(stamina.seq, 200u);
  EXPECT_EQ(stamina.left[6], 4123);
  EXPECT_EQ(stamina.right[0], 7000);
  EXPECT_EQ(stamina.right[10], -1);
}

// The stamina message is written without a JSON tree (it is most of a
// recording's messages); its text must be the tree's, byte for byte: the
// recording's binary form is checked by expanding it back to that text.
TEST(ControlMessages, StaminaTextIsTheTreesText) {
  const std::array<int, 11> ramp{-1, 0, 1, 9, 10, 99, 8000, 123456, 999999, 1000000, -1};
  const std::array<int, 11> odd{std::numeric_limits<int>::min(), std::numeric_limits<int>::max(), -42, 0, 0, 0, 0, 0, 0, 0, 7};
  for (const StaminaUpdate& e : {StaminaUpdate{0, 0, {}, {}}, StaminaUpdate{200, 100, ramp, odd},
                                 StaminaUpdate{std::numeric_limits<std::uint32_t>::max(), -3000, odd, ramp},
                                 StaminaUpdate{17, std::numeric_limits<int>::max(), ramp, ramp}}) {
    const ControlMessage m{e};
    EXPECT_EQ(to_json(m), control_to_json_value(m).dump());
  }
}

TEST(ControlMessages, StaminaNeedsElevenValuesInRange) {
  ControlMessage m;
  std::string error;
  const std::string eleven = "[1,2,3,4,5,6,7,8,9,10,11]";
  EXPECT_TRUE(control_from_json(R"({"type":"stamina","seq":1,"time":1,"left":)" + eleven + R"(,"right":)" + eleven + "}", m, error)) << error;
  EXPECT_FALSE(control_from_json(R"({"type":"stamina","seq":1,"time":1,"left":[1,2],"right":)" + eleven + "}", m, error));
  EXPECT_NE(error.find("11"), std::string::npos) << error;
  EXPECT_FALSE(control_from_json(R"({"type":"stamina","seq":1,"time":1,"left":[1,2,3,4,5,6,7,8,9,10,-7],"right":)" + eleven + "}", m, error));
  EXPECT_NE(error.find("out of range"), std::string::npos) << error;
  EXPECT_FALSE(control_from_json(R"({"type":"stamina","seq":1,"time":1,"left":"x","right":)" + eleven + "}", m, error));
  // A whole message, then a NUL and junk (nlohmann's parser stopped at the NUL).
  const std::string nul_junk = R"({"type":"stamina","seq":1,"time":1,"left":)" + eleven + R"(,"right":)" + eleven + "}" +
                               std::string(1, '\0') + "junk";
  EXPECT_FALSE(control_from_json(nul_junk, m, error));
  EXPECT_EQ(control_type(nul_junk, error), "");
  EXPECT_EQ(error, "control message is not a JSON object");
}

TEST(ControlMessages, ShiftFramesMovesSeqAndContactTimeTogether) {
  ControlMessage kick = KickEvent{100, 50, Side::Left, 9, Foot::Left, 100 * 50 + 25};
  shift_frames(kick, 40);
  const auto& k = std::get<KickEvent>(kick);
  EXPECT_EQ(k.seq, 140u);
  EXPECT_EQ(k.contact_time_ms, 140u * 50 + 25);  // still half-way after its frame
  ControlMessage goal = GoalEvent{300, 150, Side::Right, 0, 1};
  shift_frames(goal, -200);
  EXPECT_EQ(std::get<GoalEvent>(goal).seq, 100u);
  EXPECT_EQ(std::get<GoalEvent>(goal).time, 150);  // simulation time is not renumbered
}

TEST(ControlMessages, BadInputIsRefusedWithAClearError) {
  ControlMessage m;
  std::string error;
  EXPECT_FALSE(control_from_json("nope", m, error));
  EXPECT_NE(error.find("not a JSON object"), std::string::npos);
  EXPECT_FALSE(control_from_json(R"({"seq":1})", m, error));
  EXPECT_NE(error.find("no \"type\""), std::string::npos);
  EXPECT_FALSE(control_from_json(R"({"type":"teleport"})", m, error));
  EXPECT_NE(error.find("unknown control message type \"teleport\""), std::string::npos);
  EXPECT_FALSE(control_from_json(R"({"type":"kick","seq":1,"time":1,"side":"up","unum":3,"foot":"left","contact_time_ms":0})", m, error));
  EXPECT_NE(error.find("side"), std::string::npos) << error;
  EXPECT_FALSE(control_from_json(R"({"type":"kick","seq":1,"time":1,"side":"left","unum":30,"foot":"left","contact_time_ms":0})", m, error));
  EXPECT_FALSE(control_from_json(R"({"type":"play_mode","seq":1,"time":1,"mode":"dance"})", m, error));
  EXPECT_FALSE(control_from_json(R"({"type":"goal","seq":1,"time":1,"side":"left"})", m, error));
  EXPECT_NE(error.find("bad \"goal\" message"), std::string::npos) << error;
}

TEST(ControlMessages, TypeIsReadForRouting) {
  std::string error;
  EXPECT_EQ(control_type(R"({"type":"hello","protocol":{}})", error), "hello");
  EXPECT_EQ(control_type("[]", error), "");
  EXPECT_FALSE(error.empty());
}

}  // namespace
}  // namespace mc::proto
