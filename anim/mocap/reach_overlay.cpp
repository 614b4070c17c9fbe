#include "anim/mocap/reach_overlay.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "anim/mocap/opponent_model.hpp"

namespace mc::anim::mocap {

namespace {
// Bearing bin from the "diamond angle" (a monotonic stand-in for atan2 in
// [0, 4), no trigonometry): the bins are equal in diamond angle, which is all
// the table needs, since building and lookup use the same function.
int bearing_bin(float dx, float dy) {
  const float ax = std::fabs(dx), ay = std::fabs(dy), s = ax + ay;
  if (s <= 0) return 0;
  float d;
  if (dy >= 0) d = dx >= 0 ? dy / s : 1 + ax / s;
  else d = dx < 0 ? 2 + ay / s : 3 + dx / s;
  // Bin 0 is centred on straight ahead (half a bin each side).
  return static_cast<int>(d * (ReachModel::kBearings / 4) + 0.5f) % ReachModel::kBearings;
}
float median(std::vector<float>& v) {
  if (v.empty()) return 0;
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2), v.end());
  return v[v.size() / 2];
}
}  // namespace

ReachModel make_reach_model(CapabilityMap map, float hz) {
  ReachModel m;
  m.hz = hz;
  std::vector<float> ahead;
  for (int i = 0; i < map.grid.cells(); ++i) {
    const float c = map.cost[static_cast<std::size_t>(i)];
    const float x = map.grid.center_x(i), y = map.grid.center_y(i), d = std::hypot(x, y);
    if (c == kUnreached || d < 1.5f || std::fabs(std::atan2(y, x)) > 0.2f) continue;
    ahead.push_back(d / (c / hz));
  }
  // The 90th percentile: off-axis cells of the cone may need a turn.
  std::sort(ahead.begin(), ahead.end());
  m.reference_speed = ahead.empty() ? 1.0f : std::max(0.1f, ahead[ahead.size() * 9 / 10]);
  std::array<std::vector<float>, ReachModel::kBearings> extra;
  for (int i = 0; i < map.grid.cells(); ++i) {
    const float c = map.cost[static_cast<std::size_t>(i)];
    const float x = map.grid.center_x(i), y = map.grid.center_y(i), d = std::hypot(x, y);
    if (c == kUnreached || d < 1.5f) continue;
    extra[static_cast<std::size_t>(bearing_bin(x, y))].push_back(std::max(0.0f, c / hz - d / m.reference_speed));
  }
  float worst = 0;
  for (int b = 0; b < ReachModel::kBearings; ++b) {
    m.far_delay[static_cast<std::size_t>(b)] = median(extra[static_cast<std::size_t>(b)]);
    worst = std::max(worst, m.far_delay[static_cast<std::size_t>(b)]);
  }
  // Bearings the walks never covered get the worst delay seen.
  for (int b = 0; b < ReachModel::kBearings; ++b)
    if (extra[static_cast<std::size_t>(b)].empty()) m.far_delay[static_cast<std::size_t>(b)] = worst;
  m.map = std::move(map);
  return m;
}

namespace {
// A player's per-frame constants, so that one lookup is a few multiplies.
struct Prepared {
  float ox, oy, c, s, scale, glide;
  int team;
};
Prepared prepare(const ReachModel& m, const ReachPlayer& p) {
  return {p.x + p.vx * p.glide, p.y + p.vy * p.glide, std::cos(p.heading), std::sin(p.heading),
          m.reference_speed / std::max(0.1f, p.top_speed), p.glide, p.team};
}
float lookup(const ReachModel& m, const Prepared& p, float wx, float wy) {
  // Start where the current velocity carries the player, then the map frame.
  const float dx = wx - p.ox, dy = wy - p.oy;
  const float lx = dx * p.c + dy * p.s, ly = -dx * p.s + dy * p.c;
  const int cell = m.map.grid.index(lx, ly);
  float t;
  if (cell >= 0 && m.map.cost[static_cast<std::size_t>(cell)] != kUnreached) {
    t = m.map.cost[static_cast<std::size_t>(cell)] * (1.0f / m.hz);
  } else {
    t = std::sqrt(lx * lx + ly * ly) / m.reference_speed + m.far_delay[static_cast<std::size_t>(bearing_bin(lx, ly))];
  }
  return t * p.scale + p.glide;
}
}  // namespace

float reach_time(const ReachModel& m, const ReachPlayer& p, float wx, float wy) { return lookup(m, prepare(m, p), wx, wy); }

void reach_players(const WorldState& w, const GameParams& params, std::span<ReachPlayer, kMaxPlayers> out) {
  const float cycle = static_cast<float>(params.simulator_step_ms() / 1000.0);
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerState& ps = w.players[static_cast<std::size_t>(i)];
    ReachPlayer& r = out[static_cast<std::size_t>(i)];
    r = ReachPlayer();
    if (ps.side == Side::Neutral || !ps.active()) { r.team = -1; continue; }
    const PlayerType& type = params.type(ps.type);
    r.team = ps.side == Side::Left ? 0 : 1;
    r.x = static_cast<float>(ps.x);
    r.y = static_cast<float>(ps.y);
    r.heading = static_cast<float>(ps.body * std::numbers::pi / 180.0);
    r.vx = static_cast<float>(ps.vx / cycle);
    r.vy = static_cast<float>(ps.vy / cycle);
    r.top_speed = static_cast<float>(type.real_speed_max() / cycle);
    const double decay = std::clamp(type.player_decay, 0.0, 0.95);
    r.glide = static_cast<float>(decay / (1 - decay) * cycle);
  }
}

bool ReachOverlayJob::Validate() const {
  if (!model || model->map.cost.empty() || field.cells() <= 0 || !ball_player) return false;
  if (players.size() > static_cast<std::size_t>(kMaxPlayers)) return false;
  if (owner.size() != static_cast<std::size_t>(field.cells())) return false;
  if (!time.empty() && time.size() != owner.size()) return false;
  return ball_decay >= 0 && ball_decay < 1 && cycle > 0 && ball_horizon >= 0;
}

bool ReachOverlayJob::Run() const {
  if (!Validate()) return false;
  std::array<Prepared, kMaxPlayers> prep;
  std::array<int, kMaxPlayers> index;
  std::size_t n = 0;
  for (std::size_t j = 0; j < players.size(); ++j) {
    if (players[j].team != 0 && players[j].team != 1) continue;
    prep[n] = prepare(*model, players[j]);
    index[n++] = static_cast<int>(j);
  }
  for (int i = 0; i < field.cells(); ++i) {
    const float x = field.center_x(i), y = field.center_y(i);
    float best[2] = {kUnreached, kUnreached};
    for (std::size_t j = 0; j < n; ++j) {
      const float t = lookup(*model, prep[j], x, y);
      if (t < best[prep[j].team]) best[prep[j].team] = t;
    }
    ReachOwner o = ReachOwner::None;
    if (best[0] != kUnreached || best[1] != kUnreached)
      o = std::fabs(best[0] - best[1]) < contested_margin ? ReachOwner::Contested
          : best[0] < best[1]                             ? ReachOwner::Left
                                                          : ReachOwner::Right;
    owner[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(o);
    if (!time.empty()) time[static_cast<std::size_t>(i)] = std::min(best[0], best[1]);
  }
  // The ball: the first cycle k at which some player can be where the ball is.
  *ball_player = -1;
  float when = kUnreached;
  float bx = ball_x, by = ball_y, vx = ball_vx, vy = ball_vy;
  for (int k = 0; k <= ball_horizon && *ball_player < 0; ++k) {
    const float tk = static_cast<float>(k) * cycle;
    float first = kUnreached;
    for (std::size_t j = 0; j < n; ++j) {
      const float t = lookup(*model, prep[j], bx, by);
      if (t <= tk && t < first) { first = t; *ball_player = index[j]; when = tk; }
    }
    bx += vx; by += vy;
    vx *= ball_decay; vy *= ball_decay;
  }
  if (ball_time) *ball_time = when;
  return true;
}

}  // namespace mc::anim::mocap
