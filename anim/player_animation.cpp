#include "anim/player_animation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/leg_pose_job.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/mocap_walk_layer.hpp"

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
