#include "anim/player_animation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/leg_pose_job.hpp"
#include "anim/local_to_model_job.hpp"

namespace mc::anim {

int clamp_to_limits(const SkeletonDef& skeleton, std::span<float> angles) {
  int out = 0;
  std::size_t k = 0;
  for (const JointDef& j : skeleton.joints) {
    for (std::size_t d = 0; d < j.dofs.size() && k < angles.size(); ++d, ++k) {
      const float lo = j.limits[d][0], hi = j.limits[d][1];
      if (angles[k] < lo) { angles[k] = lo; ++out; }
      else if (angles[k] > hi) { angles[k] = hi; ++out; }
    }
  }
  return out;
}

namespace {

// Mocap mode: a player walking slowly forwards takes legs and body from the
// source's captured walk, cross-faded with the keyframe gait over 0.25 s;
// a foot the capture plants is held where it landed (no slide) and handed
// to locomotion, which resumes from it.
constexpr float kWalkMinSpeed = 0.3f, kWalkMaxSpeed = 1.5f, kWalkFadeS = 0.25f;

void mocap_walk(PlayerAnim& ctx, const PlayerFrameInput& in, float heading, std::span<float> a, float& pelvis_h,
                FootTarget feet[2], bool planted[2]) {
  const float speed = std::hypot(in.move_dx, in.move_dy) / (2.0f * std::max(in.dt, 1e-3f));
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
      if (std::hypot(hx - t.ankle_ms[0], hz - t.ankle_ms[2]) > 0.25f) {
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

}  // namespace

void animate_player(PlayerAnim& ctx, const PlayerFrameInput& in, const LocomotionParams& lp,
                    const SkeletonDef& limits_from, PlayerPose& out, bool* planted) {
  const bool rest = !in.animate_locomotion || in.action == Action::Stand ||
                    in.action == Action::Turn || in.action == Action::Disconnected;
  // Rate-limited heading: zig-zags and pirouettes are softened further.
  float heading = in.heading;
  if (!in.reset)  // half-way each frame (a 0.1 s time constant), then rate-limited
    heading = wrap_deg(ctx.heading + clampf(0.5f * delta_deg(in.heading, ctx.heading), -kMaxTurnPerFrameDeg,
                                            kMaxTurnPerFrameDeg));
  ctx.heading = heading;
  LocomotionInput li;
  li.x = in.x; li.y = in.y; li.heading = heading; li.dt = in.dt;
  li.move_dx = in.move_dx; li.move_dy = in.move_dy;
  li.rest = rest;
  li.stamina = in.stamina;
  li.reset = in.reset || !in.animate_locomotion;
  LocomotionOutput lo;
  step_locomotion(ctx.loco, li, lp, lo);
  if (!in.animate_locomotion) lo.planted[0] = lo.planted[1] = false;  // gliding: no foot is held
  ctx.action = in.action;

  std::span<float> a(out.angles.data(), static_cast<std::size_t>(dof::kCount));
  std::fill(out.angles.begin(), out.angles.end(), 0.0f);
  const GaitSample& g = lo.sample;
  const float amp = lo.amplitude, run = lo.run;
  const float fresh = clampf(in.stamina, 0.0f, 1.0f);
  // A tired player runs more upright (less forward lean).
  const float lean = (2.0f + 9.0f * run) * amp * (0.45f + 0.55f * fresh);
  const float back = in.action == Action::Backpedal ? 1.0f : 0.0f;

  a[dof::kPelvis + 0] = g.pelvis_twist * (4.0f + 4.0f * run) * amp;
  a[dof::kPelvis + 1] = -0.4f * lean + 4.0f * back;
  a[dof::kPelvis + 2] = g.pelvis_roll * 3.0f * amp;
  a[dof::kTorso + 0] = g.torso_twist * (5.0f + 7.0f * run) * amp - a[dof::kPelvis + 0];
  a[dof::kTorso + 1] = -0.6f * lean + 6.0f * back;
  a[dof::kTorso + 2] = -a[dof::kPelvis + 2];

  // Arms swing against the legs; elbows bend more as the player runs.
  const float swing = (12.0f + 38.0f * run) * amp;
  a[dof::kRShoulder + 0] = g.r_arm * swing - 2.0f * lean;
  a[dof::kRShoulder + 1] = -8.0f - 6.0f * run;
  a[dof::kRElbow] = 12.0f + 75.0f * run * amp;
  a[dof::kLShoulder + 0] = g.l_arm * swing - 2.0f * lean;
  a[dof::kLShoulder + 1] = 8.0f + 6.0f * run;
  a[dof::kLElbow] = 12.0f + 75.0f * run * amp;

  // Head: the server's gaze (body + neck). The head turns by the neck angle
  // exactly, plus the lag of the smoothed heading behind the server's body
  // (up to 60 deg, so that a pirouette cannot wrap the head round); the
  // pelvis, torso and neck share the yaw.
  const float lag = clampf(delta_deg(in.body, heading), -60.0f, 60.0f);
  const float head_yaw = -(in.neck + lag) - a[dof::kPelvis] - a[dof::kTorso];
  a[dof::kNeck + 0] = clampf(0.4f * head_yaw, -80.0f, 80.0f);
  a[dof::kHead + 0] = clampf(head_yaw - a[dof::kNeck + 0], -80.0f, 80.0f);
  a[dof::kNeck + 1] = 0.5f * lean;  // keep the eyes level against the lean
  a[dof::kHead + 1] = 0.3f * lean;

  float px = in.x, py = in.y, pelvis_h = lo.pelvis_height;
  FootTarget feet[2] = {lo.feet[0], lo.feet[1]};
  if (in.source != nullptr) mocap_walk(ctx, in, heading, a, pelvis_h, feet, lo.planted);
  const ActionSample* act = in.layer;
  const float w = act != nullptr ? act->weight : 0.0f;
  if (act != nullptr && w > 0) {
    px += act->root_dx;
    py += act->root_dy;
    pelvis_h += (act->pelvis_height - pelvis_h) * w;
    const int upper = dof::kRHip;  // pelvis, torso, arms; legs after IK below
    for (int d = 0; d < upper; ++d) {
      if (d >= dof::kNeck && d < dof::kRShoulder && !act->whole_body) continue;  // the head keeps the gaze
      a[static_cast<std::size_t>(d)] += (act->angles[static_cast<std::size_t>(d)] - a[static_cast<std::size_t>(d)]) * w;
    }
  }
  if (act != nullptr && w > 0 && act->feet) {
    // The kick places both feet in field space; blend from locomotion's.
    const BodyFrame body(px, py, heading);
    bool take[2] = {false, false};
    for (int i = 0; i < 2; ++i) {
      const float fw = act->foot_weight[i];
      float bx, bz;
      body.to_body(act->foot_x[i], act->foot_y[i], bx, bz);
      FootTarget& f = feet[i];
      f.ankle_ms[0] += (bx - f.ankle_ms[0]) * fw;
      f.ankle_ms[1] += (act->foot_h[i] - f.ankle_ms[1]) * fw;
      f.ankle_ms[2] += (bz - f.ankle_ms[2]) * fw;
      f.yaw_deg += (-delta_deg(act->foot_yaw[i], heading) - f.yaw_deg) * fw;
      f.pitch_deg += (act->foot_pitch[i] - f.pitch_deg) * fw;
      // A foot fully in the kick is the kick's (and locomotion resumes from
      // it); while blending in it is held only if both say so.
      take[i] = fw > 0.99f;
      lo.planted[i] = take[i] ? act->planted[i] : (fw > 0.01f ? lo.planted[i] && act->planted[i] : lo.planted[i]);
    }
    if (take[0] || take[1]) {
      const float yaw[2] = {act->foot_yaw[0], act->foot_yaw[1]};
      take_over_feet(ctx.loco, act->foot_x, act->foot_y, yaw, act->planted, take);
      if (w > 0.99f) ctx.loco.pelvis_height = pelvis_h;
    }
  } else if (act != nullptr && w > 0.5f) {
    lo.planted[0] = lo.planted[1] = false;  // tackles, catches, dives: feet are not held
  }
  // A pitched sole rolls over its heel or toes rather than sink into the grass.
  for (FootTarget& f : feet) f.ankle_ms[1] = std::max(f.ankle_ms[1], min_ankle_height(f.pitch_deg));
  LegPoseJob legs;
  legs.pelvis_height = pelvis_h;
  legs.feet[0] = feet[0];
  legs.feet[1] = feet[1];
  legs.angles = a;
  legs.Run();
  if (act != nullptr && act->whole_body && w > 0) {  // the action's own leg pose over the IK legs
    for (int d = dof::kRHip; d < dof::kCount; ++d) {
      const auto k = static_cast<std::size_t>(d);
      a[k] += (act->angles[k] - a[k]) * w;
    }
  }
  // Joint speed limit, except on teleports and in actions (whose motions are
  // fast on purpose) and for the neck and head yaw (which follow the server's
  // neck angle, turned up to 180 deg per cycle).
  const bool free = in.reset || w > 0 || ctx.was_in_action;
  // Where the limit holds a planted leg back, that foot lets go of the
  // grass (it is lifted from where the limit left it) rather than slide.
  bool released[2] = {false, false};
  for (int d = 0; d < dof::kCount && !free; ++d) {
    if (d == dof::kNeck || d == dof::kHead) continue;
    const auto k = static_cast<std::size_t>(d);
    const float limited = ctx.last_angles[k] + clampf(a[k] - ctx.last_angles[k], -kMaxJointStepDeg, kMaxJointStepDeg);
    if (std::fabs(limited - a[k]) > 0.01f && d >= dof::kRHip) released[d >= dof::kLHip ? 1 : 0] = true;
    a[k] = limited;
  }
  ctx.was_in_action = w > 0;
  // A walk foot the speed limit holds back stays held: the leg catches up
  // within a frame or two (the capture's knee straightens fast at heel strike).
  for (int i = 0; i < 2; ++i)
    if (ctx.walk_planted[i] && ctx.walk_w > 0.99f) released[i] = false;
  clamp_to_limits(limits_from, a);
  // Nothing goes under the grass: a sole that the joint limits or the speed
  // limit left pitched into it turns level at the ankle, and what is still
  // under (a whole-body action's pose, given as angles, or a leg the speed
  // limit held short) lifts the body: it rests on the grass.
  {
    // Outside whole-body actions only the feet can reach the grass: the
    // legs alone are posed (a third of the work).
    const bool whole = act != nullptr && act->whole_body && w > 0;
    std::array<glm::mat4, kHumanJointCount> m;
    LocalToModelJob fk{&limits_from, std::span<const float>(a.data(), a.size()), glm::vec3(0, pelvis_h, 0), m};
    if (!whole) fk.joint_mask = kLegJoints;
    if (fk.Run()) {
      for (const auto& [joint, d] : {std::pair{kRFoot, dof::kRAnkle}, std::pair{kLFoot, dof::kLAnkle}}) {
        const float last = ctx.last_angles[static_cast<std::size_t>(d)];
        level_foot(limits_from, m, a, joint, d, free ? -INFINITY : last - kMaxJointStepDeg,
                   free ? INFINITY : last + kMaxJointStepDeg);
      }
      pelvis_h += std::max(0.0f, -lowest_point_ms(limits_from, m, whole ? kAllJoints : kFeetJoints));
    }
  }
  // A foot touching down where the speed limit let it reach (not quite its
  // target) is held there, so that its stance does not start with a slide;
  // a released foot swings off from where it is.
  if (!free && (lo.planted[0] || lo.planted[1])) {
    std::array<glm::mat4, kHumanJointCount> m;
    LocalToModelJob fk{&limits_from, std::span<const float>(a.data(), a.size()), glm::vec3(0, pelvis_h, 0), m};
    if (fk.Run()) {
      const BodyFrame body(px, py, heading);
      const int foot_joint[2] = {kRFoot, kLFoot};
      for (int i = 0; i < 2; ++i) {
        if (!lo.planted[i]) continue;
        const bool landing = !ctx.last_planted[i];
        if (!landing && !released[i]) continue;
        const glm::vec4& ankle = m[static_cast<std::size_t>(foot_joint[i])][3];
        FootState& f = ctx.loco.feet[i];
        body.to_field(ankle.x, ankle.z, f.x, f.y);
        if (released[i] && !landing) {
          f.release = true;
          lo.planted[i] = false;
        }
      }
    }
  }
  for (int i = 0; i < 2; ++i)  // every touch-down counts for the mocap walk's cadence guard
    if (lo.planted[i] && !ctx.last_planted[i]) ctx.walk_since_land[i] = 0;
  ctx.last_planted[0] = lo.planted[0];
  ctx.last_planted[1] = lo.planted[1];
  for (int d = 0; d < dof::kCount; ++d) ctx.last_angles[static_cast<std::size_t>(d)] = a[static_cast<std::size_t>(d)];
  if (planted != nullptr) { planted[0] = lo.planted[0]; planted[1] = lo.planted[1]; }

  out.x = px;
  out.y = py;
  out.z = pelvis_h;
  out.heading = heading;
}

}  // namespace mc::anim
