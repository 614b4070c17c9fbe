#include "viewer/interpolate.hpp"

#include <algorithm>
#include <cmath>

namespace mc::viewer {
namespace {
float lerp(float p, float q, float t) { return p + (q - p) * t; }
}  // namespace

float lerp_heading(float p, float q, float t) {
  float d = std::fmod(q - p, 360.0f);
  if (d >= 180.0f) d -= 360.0f;
  if (d < -180.0f) d += 360.0f;
  return p + d * t;
}

void blend_frames(const PoseFrame& a, const PoseFrame& b, float t, int dof_count, PoseFrame& out,
                  const anim::LegBlend* feet) {
  t = std::clamp(t, 0.0f, 1.0f);
  const PoseFrame& d = t >= 1.0f ? b : a;
  out.seq = d.seq;
  out.time = d.time;
  out.stoppage = d.stoppage;
  out.substep = d.substep;
  out.server_time_ms = d.server_time_ms;
  out.play_mode = d.play_mode;
  out.score_left = d.score_left;
  out.score_right = d.score_right;
  out.ball.x = lerp(a.ball.x, b.ball.x, t);
  out.ball.y = lerp(a.ball.y, b.ball.y, t);
  out.ball.z = lerp(a.ball.z, b.ball.z, t);
  const int n = std::clamp(dof_count, 0, kMaxDof);
  for (int i = 0; i < kMaxPlayers; ++i) {
    const PlayerPose& pa = a.players[i];
    // Slots are fixed (left 1..11, right 1..11); a different player in the
    // slot of b is not blended with a.
    const PlayerPose& pb =
        (b.players[i].side == pa.side && b.players[i].unum == pa.unum) ? b.players[i] : pa;
    PlayerPose& o = out.players[i];
    o.side = pa.side;
    o.unum = pa.unum;
    o.state = (t >= 1.0f ? pb : pa).state;
    const bool jump = std::hypot(pb.x - pa.x, pb.y - pa.y) > kTeleportMetres;
    const float tt = jump ? (t < 0.5f ? 0.0f : 1.0f) : t;
    o.x = lerp(pa.x, pb.x, tt);
    o.y = lerp(pa.y, pb.y, tt);
    o.z = lerp(pa.z, pb.z, tt);
    o.heading = lerp_heading(pa.heading, pb.heading, tt);
    for (int k = 0; k < n; ++k) o.angles[k] = lerp(pa.angles[k], pb.angles[k], tt);
    for (int k = n; k < kMaxDof; ++k) o.angles[k] = pa.angles[k];
  }
  if (feet != nullptr) feet->apply(a, b, t, out, kTeleportMetres);
}

}  // namespace mc::viewer
