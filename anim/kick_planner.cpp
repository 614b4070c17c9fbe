#include "anim/kick_planner.hpp"

#include <algorithm>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

// A kick's backswing shrinks linearly with how far behind the hips its
// contact lies, to nothing at this distance (m); it keeps at least a quarter.
constexpr float kBackswingFadeM = 0.4f;

}  // namespace

bool is_successful_kick(const PlayerState* prev, const PlayerState& cur) {
  if ((cur.state & state_bits::kKick) == 0 || (cur.state & state_bits::kKickFault) != 0) return false;
  if (cur.counters.count == 0 || prev == nullptr || prev->counters.count == 0) return true;
  return cur.counters.kick > prev->counters.kick;
}

Foot choose_foot(float ball_lateral_m, float dir_lateral) {
  if (ball_lateral_m > 0.15f) return Foot::Right;
  if (ball_lateral_m < -0.15f) return Foot::Left;
  return dir_lateral <= 0 ? Foot::Right : Foot::Left;
}

ActionMotion plan_kick(const KickPlanInput& in) {
  ActionMotion m;
  m.kind = MotionKind::Kick;
  const BodyFrame body(in.root_x, in.root_y, in.heading);
  float dx = in.after_x - in.ball_x, dy = in.after_y - in.ball_y;
  const float dn = pm::hypot(dx, dy);
  if (dn > 1e-3f) { dx /= dn; dy /= dn; }
  else { dx = body.c; dy = body.s; }  // a stopped ball: kick where the body faces
  m.dir_x = dx; m.dir_y = dy;
  m.ball_x = in.ball_x; m.ball_y = in.ball_y;
  m.ball_radius = in.ball_radius;
  float bx, bz, dbx, dbz;
  body.to_body(in.ball_x, in.ball_y, bx, bz);
  body.dir_to_body(dx, dy, dbx, dbz);
  m.foot = choose_foot(bz, dbz);
  const float side = m.foot == Foot::Right ? 1.0f : -1.0f;

  // The sole turns towards the kick, up to 25 deg: with the pelvis twisted
  // into the kick, more would take the hip's yaw past its limit (and the
  // foot off the ball).
  const float kick_deg = pm::atan2(dy, dx) / kDeg;
  m.foot_yaw = wrap_deg(in.heading + clampf(delta_deg(kick_deg, in.heading), -25.0f, 25.0f));
  // The front of the foot (kStrikeLocal in the quality tool: 0.19 m ahead of
  // the ankle, 0.04 m below it), pitched 15 deg toes-down, meets the back of the ball.
  constexpr float kPitch = -15.0f * kDeg;
  const float fx = 0.19f * pm::cos(kPitch) + 0.04f * pm::sin(kPitch);
  const float fy = 0.19f * pm::sin(kPitch) - 0.04f * pm::cos(kPitch);
  const float ux = pm::cos(m.foot_yaw * kDeg), uy = pm::sin(m.foot_yaw * kDeg);
  const float sx = in.ball_x - dx * in.ball_radius, sy = in.ball_y - dy * in.ball_radius;
  m.contact_x = sx - ux * fx;
  m.contact_y = sy - uy * fx;
  m.contact_h = in.ball_radius - fy;

  // Support foot beside and a little behind the ball, on the other side, but
  // no further than the support hip reaches from the 2D position (the
  // step-in below only moves the root on the contact frame).
  float sbx = bx - 0.12f, sbz = bz - side * 0.25f;
  const float hz = -side * dims::kHipHalfWidth;
  const float sd = pm::hypot(sbx, sbz - hz);
  if (sd > 0.4f) { sbx *= 0.4f / sd; sbz = hz + (sbz - hz) * 0.4f / sd; }
  // Pulled in, it must still stay on its own side of the kicking foot.
  float cbx, cbz;
  body.to_body(m.contact_x, m.contact_y, cbx, cbz);
  if (side * (cbz - sbz) < 0.12f) sbz = cbz - side * 0.12f;
  // A contact behind the hips is reached back for, with less wind-up. Wound
  // up in full, a foot kicking a ball 0.6 m behind a backpedalling player
  // hung bent high behind him on the frame before the contact, and the
  // joint speed limit left it 8.3 cm short of the ball (issue 23).
  m.backswing = clampf(1.0f + cbx / kBackswingFadeM, 0.25f, 1.0f);
  body.to_field(sbx, sbz, m.support_x, m.support_y);

  // Step-in: move the root (on the contact frame only) until both hips are
  // within a comfortable horizontal reach of their feet.
  float ax, az, px, pz;
  body.to_body(m.contact_x, m.contact_y, ax, az);
  body.to_body(m.support_x, m.support_y, px, pz);
  float ox = 0, oz = 0;
  constexpr float kComfort = kComfortReach;
  for (int it = 0; it < 4; ++it) {
    const float kx = ax - ox, kz = az - (oz + side * dims::kHipHalfWidth);
    const float kd = pm::hypot(kx, kz);
    if (kd > kComfort) { ox += kx * (kd - kComfort) / kd; oz += kz * (kd - kComfort) / kd; }
    const float qx = px - ox, qz = pz - (oz - side * dims::kHipHalfWidth);
    const float qd = pm::hypot(qx, qz);
    if (qd > kComfort) { ox += qx * (qd - kComfort) / qd; oz += qz * (qd - kComfort) / qd; }
  }
  const float on = pm::hypot(ox, oz);
  if (on > kMaxStepIn) { ox *= kMaxStepIn / on; oz *= kMaxStepIn / on; }
  float lx, ly;
  body.to_field(ox, oz, lx, ly);
  m.lunge_x = lx - in.root_x;
  m.lunge_y = ly - in.root_y;
  // Pelvis as high as both legs allow at contact (down to a deep lunge).
  const float hk = pm::hypot(ax - ox, az - oz - side * dims::kHipHalfWidth);
  const float hs = pm::hypot(px - ox, pz - oz + side * dims::kHipHalfWidth);
  const float r2 = kPlanReach * kPlanReach;
  const float top_k = m.contact_h + std::sqrt(std::max(r2 - hk * hk, 0.09f)) + dims::kHipDrop;
  const float top_s = dims::kAnkleHeight + std::sqrt(std::max(r2 - hs * hs, 0.09f)) + dims::kHipDrop;
  m.pelvis_height = clampf(std::min(top_k, top_s), 0.62f, 0.93f);

  // Timing: preparation as long as the look-ahead allows (up to 0.3 s, the
  // measured swing start), and a stance on the support foot that the moving
  // 2D player can keep (0.4 m of travel).
  m.contact_time_s = in.contact_time_s;
  m.start_s = -std::clamp(in.prepare_s, 0.05f, 0.3f);
  m.end_s = clampf(0.4f / std::max(in.speed, 0.1f), 0.15f, 0.35f);
  m.follow_s = std::min(0.2f, m.end_s - 0.05f);
  return m;
}

bool merge_kick(ActionMotion& m, double contact_time_s, std::uint64_t pos, double max_gap_s) {
  if (m.kind != MotionKind::Kick) return false;
  const float rel = static_cast<float>(contact_time_s - m.contact_time_s);
  const float gap = rel - m.last_contact_s;
  if (gap <= 1e-4f || gap > max_gap_s + 1e-6) return false;
  m.follow_s += gap;
  m.end_s += gap;
  m.last_contact_s = rel;
  m.last_kick_pos = pos;
  return true;
}

}  // namespace mc::anim
