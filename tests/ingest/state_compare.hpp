// Test helper: the first difference between two world states, within
// tolerances that match each feed's quantisation. "" when they agree.
#pragma once

#include <cmath>
#include <sstream>
#include <string>

#include "proto/world_state.hpp"

namespace mc::ingest::testing {

struct Tolerance {
  double pos = 0;       // m (and m/cycle)
  double angle = 0;     // deg
  double stamina = 0;   // relative
  std::uint32_t state_mask = 0xffffffffu;
  bool velocities = true;  // v1 has none
  bool counters = true;    // JSON monitor shows have none
  bool details = true;     // view, stamina, focus, arm, attention (absent in v1)
  bool capacity = true;    // v2 has none
};

inline std::string first_difference(const WorldState& a, const WorldState& b, const Tolerance& t) {
  std::ostringstream d;
  auto near = [&](double x, double y, double tol) { return std::fabs(x - y) <= tol; };
  auto rel = [&](double x, double y) { return std::fabs(x - y) <= t.stamina * std::max(1.0, std::fabs(x)); };
  if (a.time != b.time) d << "time " << a.time << " vs " << b.time;
  else if (a.play_mode != b.play_mode)
    d << "play mode " << play_mode_name(a.play_mode) << " vs " << play_mode_name(b.play_mode);
  else if (a.left.name != b.left.name || a.right.name != b.right.name) d << "team names";
  else if (a.left.score != b.left.score || a.right.score != b.right.score) d << "score";
  else if (!near(a.ball.x, b.ball.x, t.pos) || !near(a.ball.y, b.ball.y, t.pos)) d << "ball position";
  else if (t.velocities && (!near(a.ball.vx, b.ball.vx, t.pos) || !near(a.ball.vy, b.ball.vy, t.pos)))
    d << "ball velocity";
  if (!d.str().empty()) return d.str() + " at time " + std::to_string(a.time);
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerState& p = a.players[static_cast<std::size_t>(i)];
    const PlayerState& q = b.players[static_cast<std::size_t>(i)];
    std::string what;
    if (p.side != q.side || p.unum != q.unum) what = "id";
    else if (p.type != q.type) what = "type";
    else if ((p.state & t.state_mask) != (q.state & t.state_mask)) what = "state";
    else if (!near(p.x, q.x, t.pos) || !near(p.y, q.y, t.pos)) what = "position";
    else if (t.velocities && (!near(p.vx, q.vx, t.pos) || !near(p.vy, q.vy, t.pos))) what = "velocity";
    else if (!near(p.body, q.body, t.angle) && !near(std::fabs(p.body - q.body), 360, t.angle)) what = "body";
    else if (t.details && !near(p.neck, q.neck, t.angle)) what = "neck";
    else if (t.details && (p.view_quality != q.view_quality || !near(p.view_width, q.view_width, t.angle)))
      what = "view";
    else if (t.details && (!rel(p.stamina, q.stamina) || !rel(p.effort, q.effort) || !rel(p.recovery, q.recovery)))
      what = "stamina";
    else if (t.capacity && p.capacity.has_value() != q.capacity.has_value()) what = "capacity presence";
    else if (t.capacity && p.capacity && !rel(*p.capacity, *q.capacity)) what = "capacity";
    else if (t.details && p.point.has_value() != q.point.has_value()) what = "arm";
    else if (t.details && p.point && (!near((*p.point)[0], (*q.point)[0], t.pos) || !near((*p.point)[1], (*q.point)[1], t.pos)))
      what = "arm point";
    else if (t.details && p.attention != q.attention) what = "attention";
    else if (t.counters && (p.counters.count != q.counters.count || p.counters.kick != q.counters.kick ||
                            p.counters.dash != q.counters.dash || p.counters.turn != q.counters.turn ||
                            p.counters.tackle != q.counters.tackle || p.counters.change_focus != q.counters.change_focus))
      what = "counters";
    if (!what.empty()) {
      d << "player " << i << " " << what << " at time " << a.time << " stoppage " << a.stoppage;
      return d.str();
    }
  }
  return {};
}

}  // namespace mc::ingest::testing
