#include "anim/mocap/reach_overlay.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <vector>

using namespace mc::anim::mocap;

namespace {

// A walker that goes 1.5 m/s straight ahead in a 30-frame cycle; at the end
// of each cycle it may instead turn 90 deg right or left on the spot (10
// frames): turning around costs about two thirds of a second.
const ReachModel& model() {
  static const ReachModel m = [] {
    MotionGraph g;
    g.nodes.resize(51);
    for (int i = 1; i <= 30; ++i) g.nodes[static_cast<std::size_t>(i)].fwd = 0.05f;
    for (int i = 31; i <= 40; ++i) g.nodes[static_cast<std::size_t>(i)].dyaw = 0.15707963f;
    for (int i = 41; i <= 50; ++i) g.nodes[static_cast<std::size_t>(i)].dyaw = -0.15707963f;
    std::vector<std::vector<std::uint32_t>> adj(51);
    for (std::uint32_t i = 0; i < 50; ++i) adj[i] = {i + 1};
    adj[30] = {1, 31, 41};
    adj[40] = {1};
    adj[50] = {1};
    g.first_edge.assign(1, 0);
    for (const auto& a : adj) {
      g.targets.insert(g.targets.end(), a.begin(), a.end());
      g.first_edge.push_back(static_cast<std::uint32_t>(g.targets.size()));
    }
    g.transition.assign(g.targets.size(), 0);
    CapabilityParams p;
    p.grid = MapGrid{40, 40, 0.5f, -10, -10};
    p.iterations = 5000;
    p.max_depth = 300;
    return make_reach_model(compute_capability_map(g, p), 30);
  }();
  return m;
}
ReachPlayer player(float x, float y, float heading, std::int8_t team, float speed = 1.5f) {
  ReachPlayer p;
  p.x = x; p.y = y; p.heading = heading; p.team = team; p.top_speed = speed; p.glide = 0;
  return p;
}

}  // namespace

TEST(ReachOverlay, ModelIsAsymmetricAndScalesWithSpeed) {
  const ReachModel& m = model();
  EXPECT_NEAR(m.reference_speed, 1.5f, 0.3f);
  const ReachPlayer p = player(0, 0, 0, 0);
  const float ahead = reach_time(m, p, 4, 0), behind = reach_time(m, p, -4, 0);
  EXPECT_GT(behind, ahead + 0.3f);
  // Far outside the map the far-field keeps the asymmetry.
  EXPECT_GT(reach_time(m, p, -40, 0), reach_time(m, p, 40, 0) + 0.3f);
  EXPECT_NEAR(reach_time(m, p, 40, 0), 40 / p.top_speed, 1.0f);
  // Twice the top speed: half the time.
  const ReachPlayer fast = player(0, 0, 0, 0, 3.0f);
  EXPECT_NEAR(reach_time(m, fast, 4, 0), ahead / 2, 1e-4);
  // Heading: facing +y (pi/2), the point (0, 4) is ahead.
  EXPECT_NEAR(reach_time(m, player(0, 0, 1.5707963f, 0), 0, 4), ahead, 0.1f);
}

TEST(ReachOverlay, EachSideOwnsItsHalfAndTheMiddleIsContested) {
  std::vector<ReachPlayer> players = {player(-10, 0, 0, 0), player(10, 0, 3.14159265f, 1)};
  ReachOverlayJob job;
  job.model = &model();
  job.players = players;
  job.field = MapGrid{21, 1, 2.0f, -21, -0.75f};  // one row, cell centres at x = -20, -18, ..., 20, y = 0.25
  std::vector<std::uint8_t> owner(21);
  std::vector<float> time(21);
  int ball = -2;
  float ball_t = 0;
  job.owner = owner;
  job.time = time;
  job.ball_player = &ball;
  job.ball_time = &ball_t;
  job.ball_x = 9.5f;  // at the right player's feet
  ASSERT_TRUE(job.Run());
  EXPECT_EQ(owner[job.field.index(-19.9f, 0)], static_cast<std::uint8_t>(ReachOwner::Left));
  EXPECT_EQ(owner[job.field.index(-4.1f, 0)], static_cast<std::uint8_t>(ReachOwner::Left));
  EXPECT_EQ(owner[job.field.index(0.1f, 0)], static_cast<std::uint8_t>(ReachOwner::Contested));
  EXPECT_EQ(owner[job.field.index(4.1f, 0)], static_cast<std::uint8_t>(ReachOwner::Right));
  // Behind the left player (x = -20) is further in time than ahead of it (x = 0).
  EXPECT_GT(time[job.field.index(-19.9f, 0)], 0.3f + reach_time(model(), players[0], -0.1f, 0) - 6.0f);
  EXPECT_EQ(ball, 1);
  EXPECT_LE(ball_t, 0.5f);
  // The ball rolling fast to the left player: he gets it first.
  job.ball_x = -6; job.ball_vx = -0.5f;
  ASSERT_TRUE(job.Run());
  EXPECT_EQ(ball, 0);
  // Absent players are ignored; nobody: no owner, no ball winner.
  players[0].team = -1;
  players[1].team = -1;
  ASSERT_TRUE(job.Run());
  EXPECT_EQ(owner[0], static_cast<std::uint8_t>(ReachOwner::None));
  EXPECT_EQ(ball, -1);
}

TEST(ReachOverlay, ValidateRefusesBadSpans) {
  std::vector<ReachPlayer> players(23, player(0, 0, 0, 0));
  std::vector<std::uint8_t> owner(10);
  int ball = 0;
  ReachOverlayJob job;
  job.model = &model();
  job.field = MapGrid{10, 1, 1, 0, 0};
  job.owner = owner;
  job.ball_player = &ball;
  job.players = std::span<const ReachPlayer>(players.data(), 22);
  EXPECT_TRUE(job.Validate());
  job.players = players;  // 23 players
  EXPECT_FALSE(job.Run());
  job.players = std::span<const ReachPlayer>(players.data(), 22);
  std::vector<std::uint8_t> small(9);
  job.owner = small;
  EXPECT_FALSE(job.Validate());
  job.owner = owner;
  job.ball_player = nullptr;
  EXPECT_FALSE(job.Validate());
}

TEST(ReachOverlay, PlayersFromAWorldState) {
  mc::WorldState w;
  mc::GameParams params;
  auto& p = w.players[0];
  p.side = mc::Side::Left; p.unum = 1; p.state = mc::state_bits::kStand;
  p.x = 5; p.y = -3; p.vx = 0.5; p.vy = 0; p.body = 90;
  w.players[12].side = mc::Side::Right;  // not standing: inactive
  std::array<ReachPlayer, mc::kMaxPlayers> out;
  reach_players(w, params, out);
  EXPECT_EQ(out[0].team, 0);
  EXPECT_FLOAT_EQ(out[0].x, 5);
  EXPECT_NEAR(out[0].heading, 1.5707963f, 1e-6);
  EXPECT_NEAR(out[0].vx, 5.0f, 1e-5);  // m/cycle -> m/s
  EXPECT_NEAR(out[0].top_speed, params.type(0).real_speed_max() * 10, 1e-4);
  EXPECT_NEAR(out[0].glide, 0.4f / 0.6f * 0.1f, 1e-5);
  EXPECT_EQ(out[12].team, -1);
  EXPECT_EQ(out[3].team, -1);
}
