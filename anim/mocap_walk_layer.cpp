#include "anim/mocap_walk_layer.hpp"

#include <algorithm>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/portable_math.hpp"

namespace mc::anim {

namespace {
constexpr float kWalkMinSpeed = 0.3f, kWalkMaxSpeed = 1.5f, kWalkFadeS = 0.25f;
}  // namespace

void mocap_walk(PlayerAnim& ctx, const PlayerFrameInput& in, float heading, std::span<float> a, float& pelvis_h,
                FootTarget feet[2], bool planted[2]) {
  const float speed = pm::hypot(in.move_dx, in.move_dy) / (2.0f * std::max(in.dt, 1e-3f));
  // Hysteresis on the speed band, so that a player near its edge does not
  // switch between the gaits every cycle.
  const bool on = ctx.walk_w > 0;
  const bool want = !in.reset && in.animate_locomotion && in.layer == nullptr &&
                    (in.action == Action::Walk || (on && in.action == Action::Run)) &&
                    speed > kWalkMinSpeed * (on ? 0.5f : 1.0f) && speed < kWalkMaxSpeed * (on ? 1.15f : 1.0f);
  ctx.walk_w = clampf(ctx.walk_w + (want ? 1.0f : -1.0f) * in.dt / kWalkFadeS, 0.0f, 1.0f);
  for (auto& n : ctx.walk_since_land)
    if (n < 255) ++n;
  if (ctx.walk_idle < 255) ++ctx.walk_idle;
  const BodyFrame body(in.x, in.y, heading);
  if (ctx.walk_w <= 0.99f && ctx.walk_idle < 20) {
    // While fading (and for a second after), locomotion steps; a foot of it landing sooner than the
    // cadence guard allows is kept in the air (lifted from where it is).
    bool take[2] = {false, false};
    float fx[2] = {0, 0}, fy[2] = {0, 0}, yaw[2] = {0, 0};
    const bool down[2] = {false, false};
    for (int i = 0; i < 2; ++i) {
      if (!planted[i] || ctx.last_planted[i] || ctx.walk_since_land[i] >= 9) continue;
      planted[i] = false;
      take[i] = true;
      body.to_field(feet[i].ankle_ms[0], feet[i].ankle_ms[2], fx[i], fy[i]);
      yaw[i] = wrap_deg(heading - feet[i].yaw_deg);
    }
    if (take[0] || take[1]) take_over_feet(ctx.loco, fx, fy, yaw, down, take);
  }
  if (ctx.walk_w <= 0 || in.reset) {
    ctx.walk.node = -1;
    ctx.walk_planted[0] = ctx.walk_planted[1] = false;
    ctx.walk_lockout[0] = ctx.walk_lockout[1] = false;
    ctx.walk_off[0][0] = ctx.walk_off[0][1] = ctx.walk_off[1][0] = ctx.walk_off[1][1] = 0;
    ctx.walk_w = 0;
    return;
  }
  WalkPose wp;
  const float turn = delta_deg(in.heading, heading) / std::max(in.dt, 1e-3f);
  if (!in.source->walk(ctx.walk, speed, turn, in.dt, wp)) {
    ctx.walk_w = 0;
    return;
  }
  const float w = ctx.walk_w;
  ctx.walk_idle = 0;
  bool take[2] = {false, false};
  float fx[2] = {0, 0}, fy[2] = {0, 0}, yaw[2] = {0, 0};
  // Hysteresis on the capture's contacts: a held foot lets go only when it
  // is 6 cm above the lower foot, a swinging one lands within 2 cm of it.
  const float low = std::min(wp.feet[0].ankle_ms[1], wp.feet[1].ankle_ms[1]);
  for (int i = 0; i < 2; ++i) {
    wp.planted[i] = wp.feet[i].ankle_ms[1] < low + (ctx.walk_planted[i] ? 0.06f : 0.02f);
    if (wp.feet[i].ankle_ms[1] > low + 0.06f) ctx.walk_lockout[i] = false;  // lifted: may plant again
    wp.planted[i] = wp.planted[i] && !ctx.walk_lockout[i];
    // Human cadence: a foot lands at most once per 0.45 s (4.4 steps/s).
    if (!ctx.walk_planted[i] && ctx.walk_since_land[i] < 9) wp.planted[i] = false;
  }
  for (int i = 0; i < 2; ++i) {
    FootTarget t = wp.feet[i];
    bool hold = w > 0.99f && wp.planted[i];
    // Taking over a foot that locomotion holds: hold it where it stands.
    if (hold && !ctx.walk_planted[i] && planted[i] && ctx.walk_since_land[i] >= 9) {
      body.to_field(feet[i].ankle_ms[0], feet[i].ankle_ms[2], ctx.walk_foot_x[i], ctx.walk_foot_y[i]);
      ctx.walk_planted[i] = true;
      ctx.walk_since_land[i] = 0;
    }
    if (hold && ctx.walk_planted[i]) {
      float hx = 0, hz = 0;
      body.to_body(ctx.walk_foot_x[i], ctx.walk_foot_y[i], hx, hz);  // where it landed
      // The capture's speed is not quite the 2D path's: the IK absorbs the
      // difference, and the swing that follows starts from the held spot.
      // Beyond 25 cm the leg lets go and waits for its next step.
      if (pm::hypot(hx - t.ankle_ms[0], hz - t.ankle_ms[2]) > 0.25f) {
        hold = false;
        wp.planted[i] = false;
        ctx.walk_lockout[i] = true;
      } else {
        ctx.walk_off[i][0] = hx - t.ankle_ms[0];
        ctx.walk_off[i][1] = hz - t.ankle_ms[2];
        t.ankle_ms[0] = hx;
        t.ankle_ms[2] = hz;
      }
    } else if (hold) {
      body.to_field(t.ankle_ms[0], t.ankle_ms[2], ctx.walk_foot_x[i], ctx.walk_foot_y[i]);  // landing now
    }
    if (!hold) {  // swinging: from where the held foot was towards the capture's path over 0.2 s
      const float k = std::max(0.0f, 1.0f - in.dt / 0.2f);
      ctx.walk_off[i][0] *= k;
      ctx.walk_off[i][1] *= k;
      t.ankle_ms[0] += ctx.walk_off[i][0];
      t.ankle_ms[2] += ctx.walk_off[i][1];
    }
    if (hold && !ctx.walk_planted[i]) {
      ctx.walk_since_land[i] = 0;
      ctx.walk_off[i][0] = ctx.walk_off[i][1] = 0;
    }
    ctx.walk_planted[i] = hold;
    // While fading, a foot locomotion holds stays where it is; swinging feet blend.
    const float fw = w > 0.99f ? 1.0f : (planted[i] ? 0.0f : w);
    for (int c = 0; c < 3; ++c) feet[i].ankle_ms[c] += (t.ankle_ms[c] - feet[i].ankle_ms[c]) * fw;
    feet[i].yaw_deg += (t.yaw_deg - feet[i].yaw_deg) * fw;
    feet[i].pitch_deg += (t.pitch_deg - feet[i].pitch_deg) * fw;
    if (w > 0.99f) planted[i] = hold;
    take[i] = w > 0.99f;
    body.to_field(feet[i].ankle_ms[0], feet[i].ankle_ms[2], fx[i], fy[i]);
    yaw[i] = wrap_deg(heading - feet[i].yaw_deg);
  }
  if (take[0] || take[1]) {
    take_over_feet(ctx.loco, fx, fy, yaw, planted, take);
    ctx.loco.pelvis_height = wp.pelvis_height;
  }
  pelvis_h += (wp.pelvis_height - pelvis_h) * w;
  a[dof::kTorso + 1] += (wp.torso_lean - a[dof::kTorso + 1]) * w;
  const int sh[2] = {dof::kRShoulder, dof::kLShoulder}, el[2] = {dof::kRElbow, dof::kLElbow};
  for (int i = 0; i < 2; ++i) {
    a[static_cast<std::size_t>(sh[i])] += (wp.shoulder[i] - a[static_cast<std::size_t>(sh[i])]) * w;
    a[static_cast<std::size_t>(el[i])] += (wp.elbow[i] - a[static_cast<std::size_t>(el[i])]) * w;
  }
}


}  // namespace mc::anim
