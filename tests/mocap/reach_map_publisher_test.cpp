#include "anim/mocap/reach_map_publisher.hpp"

#include <gtest/gtest.h>

#include "proto/control_messages.hpp"
#include "tests/mocap/synthetic_reach.hpp"

using namespace mc::anim::mocap;

namespace {

mc::WorldState two_players() {
  mc::WorldState w;
  w.time = 77;
  auto& l = w.players[0];
  l.side = mc::Side::Left; l.unum = 9; l.state = mc::state_bits::kStand; l.x = -20; l.body = 0;
  auto& r = w.players[mc::player_index(mc::Side::Right, 4)];
  r.side = mc::Side::Right; r.unum = 4; r.state = mc::state_bits::kStand; r.x = 20; r.body = 180;
  w.ball.x = -19;
  return w;
}

}  // namespace

TEST(ReachMapPublisher, EveryFourthStateAMessageThatRoundTrips) {
  ReachMapPublisher pub(test::straight_walker_reach_model(), 4);
  const mc::WorldState w = two_players();
  const mc::GameParams params;
  int sent = 0;
  mc::proto::ReachMapUpdate m;
  for (int i = 0; i < 12; ++i) sent += pub.push(w, params, m) ? 1 : 0;
  EXPECT_EQ(sent, 3);
  ASSERT_EQ(m.width * m.height, static_cast<int>(m.cells.size()));
  EXPECT_EQ(m.time, 77);
  // Left half is the left team's, right half the right team's.
  auto at = [&](float x, float y) {
    const int i = static_cast<int>((x - m.x0) / m.cell), j = static_cast<int>((y - m.y0) / m.cell);
    return m.cells[static_cast<std::size_t>(j * m.width + i)];
  };
  EXPECT_EQ(at(-40, 0), 'l');
  EXPECT_EQ(at(40, 0), 'r');
  EXPECT_EQ(m.ball_side, mc::Side::Left);
  EXPECT_EQ(m.ball_unum, 9);
  // JSON and back, run-length coded.
  m.seq = 1234;
  const std::string text = mc::proto::to_json(mc::proto::ControlMessage{m});
  EXPECT_LT(text.size(), m.cells.size());  // the run-length code is shorter than the grid
  mc::proto::ControlMessage back;
  std::string error;
  ASSERT_TRUE(mc::proto::control_from_json(text, back, error)) << error;
  const auto* r = std::get_if<mc::proto::ReachMapUpdate>(&back);
  ASSERT_NE(r, nullptr);
  EXPECT_EQ(r->cells, m.cells);
  EXPECT_EQ(r->seq, 1234u);
  EXPECT_EQ(r->ball_unum, 9);
  EXPECT_EQ(r->width, 53);
  mc::proto::shift_frames(back, 10);
  EXPECT_EQ(std::get<mc::proto::ReachMapUpdate>(back).seq, 1244u);
}

TEST(ReachMapPublisher, BadReachMapTextIsRefused) {
  mc::proto::ControlMessage out;
  std::string error;
  const std::string head = R"({"type":"reach_map","seq":1,"time":2,"grid":{"w":2,"h":2,"cell":1,"x0":0,"y0":0},"cells":")";
  EXPECT_TRUE(mc::proto::control_from_json(head + "l2r2\"}", out, error)) << error;
  for (const char* cells : {"l2r1", "l2r3", "x4", "l0l4", "l", "l99999999", "l4r", ""}) {
    EXPECT_FALSE(mc::proto::control_from_json(head + cells + "\"}", out, error)) << cells;
  }
  EXPECT_FALSE(mc::proto::control_from_json(
      R"({"type":"reach_map","seq":1,"time":2,"grid":{"w":100000,"h":2,"cell":1,"x0":0,"y0":0},"cells":"l2"})", out, error));
  EXPECT_FALSE(mc::proto::control_from_json(
      R"({"type":"reach_map","seq":1,"time":2,"grid":{"w":2,"h":2,"cell":-1,"x0":0,"y0":0},"cells":"l4"})", out, error));
}
