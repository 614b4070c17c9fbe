#include "anim/player_animation.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include "anim/body_frame.hpp"
#include "anim/drawn_leg_clearance.hpp"
#include "anim/exp2_remembered.hpp"
#include "anim/grid_rounding.hpp"
#include "anim/ground_contact.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/joint_limits.hpp"
#include "anim/joint_speed_limit.hpp"
#include "anim/kick_reach.hpp"
#include "anim/leg_pose_job.hpp"
#include "anim/limb_clearance.hpp"
#include "anim/local_to_model_job.hpp"
#include "anim/mocap_walk_layer.hpp"
#include "anim/portable_math.hpp"
#include "anim/swing_clearance.hpp"

namespace mc::anim {
namespace {

const std::string kYzx = "yzx", kZxy = "zxy", kZ = "z", kZx = "zx";
// Hip -> ankle at which a leg keeps a soft knee (the IK softens from 99.5 %).
constexpr float kLegReach = 0.985f * (dims::kThigh + dims::kShin);
constexpr float kMinPelvis = 0.62f;
// The pelvis rises at most this much per frame and sinks at most this much
// unless a leg needs it lower (then it sinks as far as that leg needs).
constexpr float kPelvisRise = 0.03f, kPelvisSink = 0.05f;
// An ankle is kept this far inside its dorsiflexion limit by raising the heel.
constexpr float kAnkleMargin = 3.0f;
constexpr float kAnkleDorsiflexion = 35.0f;  // the ankles' limit (human_skeleton)
// A kick's contact frame lies within this of its contact time (s): the
// kicking foot moves freely (no ankle travel limit) on that frame only.
constexpr float kContactFrameS = 0.02f;
// A kick's support foot held up to this far (m, and this high) from its spot
// as it plants is planted where it is.
constexpr float kSupportReanchorM = 0.4f;
// Turn-outs, each followed by a check of the clients' drawn travel, after
// the check held a leg back (below). On the two full games 3, 4 and 8
// retries all left them apart; each pair costs a separation and a check,
// on a few hundred frames a game. The fifth was a turn-out left unchecked
// until session 34.
constexpr int kDrawnTurnsApart = 5;
// How many times the legs are kept apart as the clients draw the frame,
// each followed by resting on the grass again.
constexpr int kDrawnApartTries = 5;

// Highest pelvis at which the ankle of `t` (body space) stays within reach of
// its hip, for a pelvis rotated by `pelvis` (pelvis joint on the body's Y axis).
float pelvis_limit(const glm::mat3& pelvis, const FootTarget& t, int side) {
  const glm::vec3 hip = pelvis * glm::vec3(0.0f, -dims::kHipDrop, side == 0 ? dims::kHipHalfWidth : -dims::kHipHalfWidth);
  const float dx = t.ankle_ms[0] - hip.x, dz = t.ankle_ms[2] - hip.z;
  const float h2 = kLegReach * kLegReach - dx * dx - dz * dz;
  return t.ankle_ms[1] - hip.y + (h2 > 0.0025f ? std::sqrt(h2) : 0.05f);
}

// The body-space ankle target of a planted foot with its current roll.
void planted_target(const FootState& f, const BodyFrame& body, FootTarget& t) {
  float ax, ay, ah;
  planted_ankle(f.x, f.y, f.yaw, f.pitch, ax, ay, ah);
  body.to_body(ax, ay, t.ankle_ms[0], t.ankle_ms[2]);
  t.ankle_ms[1] = ah;
  t.yaw_deg = -delta_deg(f.yaw, body.heading);
  t.pitch_deg = f.pitch;
}

}  // namespace

void animate_player(PlayerAnim& ctx, const PlayerFrameInput& in, const FootstepParams& fp,
                    const SkeletonDef& limits_from, PlayerPose& out, bool* planted) {
  const bool rest = !in.animate_locomotion || in.action == Action::Stand ||
                    in.action == Action::Turn || in.action == Action::Disconnected;
  // Rate-limited heading: zig-zags and pirouettes are softened further.
  float heading = in.heading;
  const float last_heading = ctx.heading;
  if (!in.reset)  // half-way each frame (a 0.1 s time constant), then rate-limited
    heading = wrap_deg(ctx.heading + clampf(0.5f * delta_deg(in.heading, ctx.heading), -kMaxTurnPerFrameDeg,
                                            kMaxTurnPerFrameDeg));
  ctx.heading = heading;
  const ActionSample* act = in.layer;
  const float w = act != nullptr ? act->weight : 0.0f;
  // Feet an action has taken whole are the action's this frame.
  for (int i = 0; i < 2; ++i)
    ctx.loco.feet[i].held = act != nullptr && w > 0 && act->feet && act->foot_weight[i] > 0.99f;

  FootstepInput fi;
  fi.x = in.x; fi.y = in.y; fi.heading = heading; fi.dt = in.dt;
  for (int k = 0; k < in.ahead_n && k < kPathAhead; ++k) {
    fi.ahead_x[k] = in.ahead_x[k];
    fi.ahead_y[k] = in.ahead_y[k];
  }
  fi.ahead_n = std::min(in.ahead_n, kPathAhead);
  fi.rest = rest;
  fi.stamina = in.stamina;
  fi.reset = in.reset || !in.animate_locomotion;
  FootstepOutput lo;
  step_footsteps(ctx.loco, fi, fp, lo);
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
  // Held a little away from the body: a hand swinging back passes outside
  // the thigh swinging forward.
  a[dof::kRShoulder + 1] = -13.0f - 7.0f * run;
  a[dof::kRElbow] = 12.0f + 75.0f * run * amp;
  a[dof::kLShoulder + 0] = g.l_arm * swing - 2.0f * lean;
  a[dof::kLShoulder + 1] = 13.0f + 7.0f * run;
  a[dof::kLElbow] = 12.0f + 75.0f * run * amp;

  // Head: the server's gaze (body + neck). The head turns by the neck angle,
  // plus the lag of the smoothed heading behind the server's body (up to 60
  // deg, so that a pirouette cannot wrap the head round); the pelvis, torso
  // and neck share the yaw. The joint speed limit below lets it follow at
  // a human head's speed.
  const float lag = clampf(delta_deg(in.body, heading), -60.0f, 60.0f);
  float head_yaw = -(in.neck + lag) - a[dof::kPelvis] - a[dof::kTorso];
  // The neck and the head turn together (0.4 and 0.6 of the yaw): the turn
  // is limited as a whole, so that the head's share keeps within the joint
  // speed limit. Limited joint by joint, the head alone was held back on a
  // sixth of all frames and the neck led it.
  if (!in.reset) {
    const float last = ctx.last_angles[dof::kNeck] + ctx.last_angles[dof::kHead];
    const float cap = (kMaxUpperStepDeg - 1.0f) / 0.6f;
    head_yaw = last + clampf(head_yaw - last, -cap, cap);
  }
  a[dof::kNeck + 0] = clampf(0.4f * head_yaw, -80.0f, 80.0f);
  a[dof::kHead + 0] = clampf(head_yaw - a[dof::kNeck + 0], -80.0f, 80.0f);
  a[dof::kNeck + 1] = 0.5f * lean;  // keep the eyes level against the lean
  a[dof::kHead + 1] = 0.3f * lean;

  float px = in.x, py = in.y, pelvis_h = lo.pelvis_height;
  FootTarget feet[2] = {lo.feet[0], lo.feet[1]};
  if (in.source != nullptr) mocap_walk(ctx, in, heading, a, pelvis_h, feet, lo.planted);
  // The upper body's locomotion targets, before the action layer (the
  // inertialization below looks at what the layer adds).
  std::array<float, dof::kRHip> layer{};
  for (int d = 0; d < dof::kRHip; ++d) layer[static_cast<std::size_t>(d)] = a[static_cast<std::size_t>(d)];
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
  for (int d = 0; d < dof::kRHip; ++d) {
    const auto k = static_cast<std::size_t>(d);
    layer[k] = a[k] - layer[k];
  }
  // Inertialization (Bollo 2016): where what the action layer adds jumps (an
  // action starts, ends or gives way to another), the jump is taken up by an
  // offset that decays. Locomotion's own motion (an arm swinging at a
  // sprint's cadence, the head turning to the gaze) is not a transition and
  // passes as it is: blending it too lagged and damped the arm swing and
  // shook the trunk (issue 23, recording size).
  if (in.reset) {
    ctx.blend_x.fill(0.0f);
    ctx.blend_v.fill(0.0f);
  } else {
    constexpr float kJumpDeg = 10.0f;
    // Critically damped decay, half-life 0.1 s (Holden's spring.h: y = 2 ln2
    // / half-life, and the exact step multiplies by exp(-y dt) =
    // 2^(-2 dt / half-life)).
    const float y = 13.862944f, e = exp2_remembered(-2.0f * in.dt / 0.1f);
    for (int d = 0; d < dof::kRHip; ++d) {
      const auto k = static_cast<std::size_t>(d);
      float& x = ctx.blend_x[k];
      float& v = ctx.blend_v[k];
      const float jump = layer[k] - ctx.last_layer[k];
      if (std::fabs(jump) > kJumpDeg) x -= jump;  // the output goes on from where it was
      const float j1 = v + x * y;
      x = e * (x + j1 * in.dt);
      v = e * (v - j1 * y * in.dt);
    }
  }
  for (int d = 0; d < dof::kRHip; ++d) {
    const auto k = static_cast<std::size_t>(d);
    ctx.last_layer[k] = layer[k];
    a[k] += ctx.blend_x[k];
  }
  const BodyFrame body(px, py, heading);
  if (act != nullptr && w > 0 && act->feet) {
    // The kick places both feet in field space; blend from the footsteps'.
    for (int i = 0; i < 2; ++i) {
      const float fw = act->foot_weight[i];
      if (fw <= 0) continue;
      float bx, bz;
      body.to_body(act->foot_x[i], act->foot_y[i], bx, bz);
      FootTarget& f = feet[i];
      f.ankle_ms[0] += (bx - f.ankle_ms[0]) * fw;
      f.ankle_ms[1] += (act->foot_h[i] - f.ankle_ms[1]) * fw;
      f.ankle_ms[2] += (bz - f.ankle_ms[2]) * fw;
      f.yaw_deg += (-delta_deg(act->foot_yaw[i], heading) - f.yaw_deg) * fw;
      f.pitch_deg += (act->foot_pitch[i] - f.pitch_deg) * fw;
      // A foot fully in the kick is the kick's (and the footsteps resume
      // from it); while blending in it is held only if both say so.
      const bool take = fw > 0.99f;
      lo.planted[i] = take ? act->planted[i] : lo.planted[i] && act->planted[i];
      if (take) {
        const float yaw = act->foot_yaw[i];
        if (act->planted[i]) {
          const float ux = pm::cos(yaw * kDeg), uy = pm::sin(yaw * kDeg);
          take_over_foot(ctx.loco, i, act->foot_x[i] + ux * 0.06f, act->foot_y[i] + uy * 0.06f, 0, yaw, 0, true);
        } else {
          take_over_foot(ctx.loco, i, act->foot_x[i], act->foot_y[i], act->foot_h[i], yaw, act->foot_pitch[i], false);
        }
      }
    }
  } else if (act != nullptr && w > 0.5f) {
    lo.planted[0] = lo.planted[1] = false;  // tackles, catches, dives: feet are not held
  }
  // A pitched sole rolls over its heel or toes rather than sink into the grass.
  for (FootTarget& f : feet) f.ankle_ms[1] = std::max(f.ankle_ms[1], min_ankle_height(f.pitch_deg));

  // The pelvis as low as the planted legs need: first a heel rises (a foot
  // behind the hip pushes off from its toes), then the pelvis sinks.
  const glm::mat3 pelvis_rot = joint_rotation(kYzx, &a[dof::kPelvis]);
  const bool own_feet = in.animate_locomotion && (act == nullptr || w <= 0 || act->feet || !act->whole_body);
  float limit = pelvis_h;
  for (int i = 0; i < 2 && own_feet; ++i) {
    FootState& f = ctx.loco.feet[i];
    // A foot in the air reaching down for the grass (footsteps: both feet
    // up while the body is too slow for a flight) brings the pelvis down as
    // a planted one does, but at the pelvis's own pace (kPelvisSink a
    // frame): out of the leg's reach, it hung 15-20 cm up (issue 23,
    // floating); dropped at once, the body bobbed and the planted feet of
    // the frames after moved more.
    if (lo.reaching[i] && !f.held && (act == nullptr || w <= 0)) {
      const float lim = pelvis_limit(pelvis_rot, feet[i], i);
      limit = std::min(limit, in.reset ? lim : std::max(lim, ctx.pelvis_height - kPelvisSink));
      continue;
    }
    if (!lo.planted[i] || !f.planted || f.held) continue;
    float lim = pelvis_limit(pelvis_rot, feet[i], i);
    for (int k = 0; k < 5 && lim < pelvis_h - 0.02f && f.pitch > -40.0f && feet[i].ankle_ms[0] < -0.05f; ++k) {
      f.pitch = std::max(-40.0f, std::min(f.pitch, 0.0f) - 8.0f);
      planted_target(f, body, feet[i]);
      lim = pelvis_limit(pelvis_rot, feet[i], i);
    }
    limit = std::min(limit, lim);
  }
  pelvis_h = std::min(pelvis_h, limit);
  if (own_feet) {  // a whole-body action (tackle, dive) sets its own height and rests on the grass
    if (!in.reset) pelvis_h = std::min(clampf(pelvis_h, ctx.pelvis_height - kPelvisSink, ctx.pelvis_height + kPelvisRise), limit);
    pelvis_h = std::max(pelvis_h, kMinPelvis);
  }

  LegPoseJob legs;
  legs.pelvis_height = pelvis_h;
  legs.feet[0] = feet[0];
  legs.feet[1] = feet[1];
  legs.angles = a;
  // The root's travel since the last frame (field m): how far a foot in the
  // air may travel with the body (swing_clear).
  const float root_step = ctx.ankles.valid ? pm::hypot(in.x - ctx.ankles.pelvis.x, in.y - ctx.ankles.pelvis.y) : 0.0f;
  // A foot in the air keeps off the grass as it travels (swing_clearance.hpp):
  // not a kick's foot up to its contact, nor under a whole-body action. After
  // the contact the kicking foot follows through and comes down beside a body
  // that runs on: left to the kick's keys, it came down low over the grass at
  // the body's speed (game 1 at 60 Hz, phase 0.5: 9 % of the 8-9 m/s band's
  // sliding, anim/README.md "A knee's own speed").
  if (own_feet && !in.reset && ctx.ankles.valid && (act == nullptr || !act->whole_body || w <= 0))
    for (int i = 0; i < 2; ++i) {
      const bool to_ball =
          act != nullptr && act->feet && w > 0 && act->kick_foot == i && act->to_contact_s > -kContactFrameS;
      if (lo.planted[i] || to_ball) continue;
      FootTarget& t = legs.feet[i];
      float fx, fy;
      body.to_field(t.ankle_ms[0], t.ankle_ms[2], fx, fy);
      const float travel = pm::hypot(fx - ctx.ankles.ankle[i].x, fy - ctx.ankles.ankle[i].y);
      const float clear = swing_clear(travel, root_step);
      if (may_skim(t.ankle_ms[1], travel, clear)) t.ankle_ms[1] += swing_lift(t.ankle_ms[1], t.pitch_deg, clear);
    }
  legs.Run();
  // An ankle that cannot bend as far as a flat planted sole needs: the heel rises.
  bool again = false;
  for (int i = 0; i < 2 && own_feet; ++i) {
    FootState& f = ctx.loco.feet[i];
    const float excess = legs.ankle_pitch_deg[i] - (kAnkleDorsiflexion - kAnkleMargin);
    if (!lo.planted[i] || !f.planted || f.held || excess <= 0) continue;
    f.pitch = std::max(-45.0f, std::min(f.pitch, 0.0f) - excess);
    planted_target(f, body, legs.feet[i]);
    again = true;
  }
  if (again) legs.Run();
  // No ankle jumps: a target further than an ankle moves in a frame is
  // pulled back, and a planted foot so pulled is not on its spot this frame.
  // The kicking foot is left free on its contact frame (touch_ball puts it
  // on the ball). Before it, it keeps within reach of its contact spot, so
  // that it gets there without a jump.
  const bool kicking = act != nullptr && act->feet && act->foot_weight[act->kick_foot] > 0;
  const bool striking = kicking && std::fabs(act->to_contact_s) < kContactFrameS;
  const bool skip[2] = {striking && act->kick_foot == 0, striking && act->kick_foot == 1};
  AnkleGoal goal[2];
  if (kicking && act->to_contact_s >= kContactFrameS) {
    AnkleGoal& g = goal[act->kick_foot];
    g.set = true;
    g.at = glm::vec3(act->contact_ankle_x, act->contact_ankle_y, act->contact_ankle_h);
    g.frames = std::max(1, static_cast<int>(std::lround(act->to_contact_s / in.dt)));
  }
  const bool travel_limited = !in.reset && (act == nullptr || !act->whole_body || w <= 0);
  if (travel_limited) {
    // A kick's support foot held short of its spot is on its way there, in
    // the air: at the grass's height it slid the rest of the way.
    bool lift[2] = {false, false};
    if (act != nullptr && act->feet && w > 0)
      for (int i = 0; i < 2; ++i) lift[i] = i != act->kick_foot && act->foot_weight[i] > 0;
    const int pulled = limit_ankle_travel(limits_from, body, ctx.ankles, skip, lift, goal, legs);
    // A planted foot pulled back (a sprinter's hip carried past it) lets go
    // of the grass next frame: planted again, it stepped twice on one
    // spot, 8 steps/s (issue 4's cadence, game 1 seq 10484).
    for (int i = 0; i < 2; ++i)
      if ((pulled & (1 << i)) != 0) {
        if (lo.planted[i]) ctx.loco.feet[i].release = true;
        lo.planted[i] = false;
      }
  }
  // The IK legs within their joint limits before they are kept apart: a
  // kick's follow-through asked a hip past its -40 deg, and clamped after
  // the check it brought the feet 2.5 cm inside each other (game 1 seq
  // 4065; at 20 Hz thighs / shins / feet too close 1/0/3 -> 0/0/1 and
  // 0/0/3 -> 0/0/1).
  clamp_legs_to_limits(limits_from, a);
  // Still too close with a leg planted: the planted knees turn out over the
  // same feet (and a leg in the air is turned out again).
  std::array<float, dof::kCount> unseparated;
  std::copy_n(a.begin(), dof::kCount, unseparated.begin());
  if (own_feet && separate_legs(a, pelvis_h, lo.planted)) {
    for (float out : {10.0f, 20.0f, 30.0f}) {
      for (int i = 0; i < 2; ++i) legs.feet[i].knee_out_deg = lo.planted[i] ? out : 0.0f;
      legs.Run();
      if (!separate_legs(a, pelvis_h, lo.planted)) break;
    }
  }
  // Turned out, a leg's ankle swings sideways: it still keeps within a
  // frame's travel (and kSeparationSlackM), giving up as little of the turn
  // as it must, from the legs as they were before it. Without it, 5 and 6 of
  // the two full games' ankle pops came from here.
  const bool separated = !std::equal(unseparated.begin() + dof::kRHip, unseparated.end(), a.begin() + dof::kRHip);
  if (travel_limited && !skip[0] && !skip[1] && separated)
    limit_ankle_travel(limits_from, body, pelvis_h, ctx.ankles, unseparated, a, kSeparationSlackM);
  // An ankle never rests against its limits: a joint held at its stop looks
  // locked (issue 23). In the air the sole only tilts a little further.
  for (int i = 0; i < 2; ++i) {
    const auto k = static_cast<std::size_t>(i == 0 ? dof::kRAnkle : dof::kLAnkle);
    a[k] = clampf(a[k], -58.0f, kAnkleDorsiflexion - 2.0f);
    a[k + 1] = clampf(a[k + 1], -28.0f, 28.0f);
  }
  if (act != nullptr && act->whole_body && w > 0) {  // the action's own leg pose over the IK legs
    for (int d = dof::kRHip; d < dof::kCount; ++d) {
      const auto k = static_cast<std::size_t>(d);
      a[k] += (act->angles[k] - a[k]) * w;
    }
    if (!in.reset) limit_ankle_travel(limits_from, body, pelvis_h, ctx.ankles, ctx.last_angles, a);
    // Blended with the IK legs, the action's leg pose (a tackle's folded
    // trailing leg) can pass through the other leg: the right leg turns out.
    if (!in.reset) {
      const bool in_air[2] = {false, false};
      separate_legs_again(limits_from, body, pelvis_h, ctx.last_angles, &ctx.ankles, in_air, a);
    }
  }
  // Nothing goes under the grass: a sole that the joint limits or the speed
  // limit left pitched into it turns level at the ankle, and what is still
  // under (a whole-body action's pose, given as angles, or a leg the speed
  // limit held short) lifts the body: it rests on the grass. Once before a
  // kick's contact is made (so it is made where the body is) and once after
  // the joint speed limit.
  // The ankles (body space) of the pose as rest_on_grass last left it: the
  // ankle travel limit's "last frame" (an ankle's own dofs do not move it).
  glm::vec3 rested_ankle[2];
  bool rested = false;
  const bool contact = act != nullptr && act->contact && act->feet && act->foot_weight[act->kick_foot] > 0;
  // The joints as rest_on_grass last posed them (body space): the last pose
  // of the legs, which round_legs_to_grid reads.
  std::array<glm::mat4, kHumanJointCount> m;
  auto rest_on_grass = [&](float leeway_deg) {
    const bool whole = act != nullptr && act->whole_body && w > 0;
    LocalToModelJob fk{&limits_from, std::span<const float>(a.data(), a.size()), glm::vec3(0, pelvis_h, 0), m};
    if (!whole) fk.joint_mask = kLegJoints;
    if (fk.Run()) {
      for (const auto& [joint, d] : {std::pair{kRFoot, dof::kRAnkle}, std::pair{kLFoot, dof::kLAnkle}}) {
        // Within the joint speed limit, and within `leeway_deg` of the pitch
        // it has now (after the limit, the ankle's turn must stay small).
        const float last = ctx.last_angles[static_cast<std::size_t>(d)];
        const float now = a[static_cast<std::size_t>(d)];
        // A foot in the air that travels turns towards level until its sole
        // is swing_clear() up, kSkimLevelDeg past its pitch at most: the
        // joint speed limit can leave a swing short and toes down, sole
        // skimming the grass (game 1 seq 7079, a dribbler's support foot
        // 2.6 cm up and 0.46 m from its spot).
        const int side = joint == kRFoot ? 0 : 1;
        float clear = 0, lee = leeway_deg;
        if (!whole && !in.reset && ctx.ankles.valid && !lo.planted[side] && !(contact && act->kick_foot == side)) {
          float fx, fy;
          body.to_field(m[joint][3].x, m[joint][3].z, fx, fy);
          const float travel = pm::hypot(fx - ctx.ankles.ankle[side].x, fy - ctx.ankles.ankle[side].y);
          if (travel > kSkimStepM) {
            clear = swing_clear(travel, root_step);
            lee = std::max(lee, kSkimLevelDeg);
          }
        }
        // Not against the ankle's stop either (it looks locked; 2 deg off it,
        // as the ankles are clamped above): taken there,
        // the ankles' time at a limit went from 0.9 / 0.7 % to 1.6 / 1.4 %.
        const float top = clear > 0 ? std::max(now, kAnkleDorsiflexion - 2.0f) : INFINITY;
        level_foot(limits_from, m, a, joint, d,
                   in.reset ? -INFINITY : std::max(last - kMaxLegStepDeg, now - lee),
                   in.reset ? INFINITY : std::min({last + kMaxLegStepDeg, now + lee, top}), clear);
      }
      const float lift = std::max(0.0f, -lowest_point_ms(limits_from, m, whole ? kAllJoints : kFeetJoints));
      pelvis_h += lift;
      rested_ankle[0] = glm::vec3(m[kRFoot][3]) + glm::vec3(0, lift, 0);
      rested_ankle[1] = glm::vec3(m[kLFoot][3]) + glm::vec3(0, lift, 0);
      rested = true;
    }
  };
  clamp_to_limits(limits_from, a);
  if (contact) rest_on_grass(180.0f);
  // A kick's contact: the kicking foot's box touches the ball (a few mm
  // off its surface, the margin of the stream's quantization), whatever the
  // leg's reach, the ankle's limits and the grass made of the planned spot.
  if (contact) {
    legs.pelvis_height = pelvis_h;
    for (int i = 0; i < 2; ++i) legs.feet[i] = feet[i];
    touch_ball(limits_from, body, pelvis_h, *act, act->kick_foot, legs, a);
  }
  if (act == nullptr || !act->whole_body)
    keep_hands_off_thighs(limits_from, a, in.reset ? std::span<const float>() : std::span<const float>(ctx.last_angles),
                          ctx.hands_near);
  // Joint speed limit (not across a teleport). Where it holds a planted leg
  // back, that foot lets go of the grass next frame rather than slide.
  bool limited[kHumanJointCount] = {};
  if (!in.reset) {
    limit_joint_speed(limits_from, ctx.last_angles.data(), a, limited, contact ? act->kick_foot : -1);
    for (int i = 0; i < 2; ++i) {
      const int j0 = i == 0 ? kRThigh : kLThigh;
      if (lo.planted[i] && (limited[j0] || limited[j0 + 1] || limited[j0 + 2])) ctx.loco.feet[i].release = true;
    }
    // A kicking leg the limit held short of the ball, or in it, meets it
    // with the hip (kick_reach.hpp): a knee bent 79 deg the frame before
    // left game 1 seq 10697's foot 6 cm short.
    if (contact) {
      const int j0 = act->kick_foot == 0 ? kRThigh : kLThigh;
      if (limited[j0] || limited[j0 + 1] || limited[j0 + 2]) {
        glm::vec3 ball(0.0f, act->ball_h, 0.0f);
        body.to_body(act->ball_x, act->ball_y, ball.x, ball.z);
        reach_ball_with_hip(limits_from, ctx.last_angles, pelvis_h, ball, act->ball_r, act->kick_foot, kContactGapM,
                            kMaxKickLegStepDeg, a);
      }
    }
    // The speed limit takes each joint part of the way back to the last
    // frame, which can bring the legs together again, and separate_legs
    // does not check its own last turn. (Only then: run on every frame, the
    // check cost 10 % of the animation's time.)
    bool leg_held = separated;
    for (int j = kRThigh; j <= kLFoot; ++j) leg_held = leg_held || limited[j];
    if (own_feet && !contact && leg_held)
      separate_legs_again(limits_from, body, pelvis_h, ctx.last_angles, travel_limited ? &ctx.ankles : nullptr,
                          lo.planted, a);
  }
  rest_on_grass(8.0f);
  // No ankle pops as the clients draw the frame either (the bounds above
  // hold a frame's chord only): 61 / 63 of the two full games' foot-frames
  // at 60 Hz -> 21 / 17. A planted foot is not moved. A kicking foot on its
  // last frame before contact is held back too since the contact reaches
  // the ball with the hip where the joint speed limit holds the knee
  // (kick_reach.hpp): before that, held back there, it reached the ball
  // 3.7 cm short (game 1 seq 11795), and those frames were the 21 / 18
  // pops left (now 1 / 1). A leg held back rests on the grass again.
  if (!in.reset && ctx.ankles.valid && rested) {
    const DrawnRoot from{ctx.ankles.pelvis.x, ctx.ankles.pelvis.y, ctx.ankles.pelvis.z, last_heading};
    bool keep[2], landing[2];
    glm::vec3 now_ankle[2];
    for (int i = 0; i < 2; ++i) {
      // A foot landing is held back too: one whose swing the joint speed
      // limit left short on the frame before reached its spot faster than
      // a pop (game 1 seq 11260, left 11, landing from 15 cm at 7.8 m/s:
      // 0.61 m a frame about the pelvis). Held, it is not planted on this
      // frame; the footsteps keep its spot, and it lands when it reaches it.
      landing[i] = lo.planted[i] && !ctx.last_planted[i];
      keep[i] = (lo.planted[i] && !landing[i]) || skip[i] || (contact && act->kick_foot == i);
      body.to_field(rested_ankle[i].x, rested_ankle[i].z, now_ankle[i].x, now_ankle[i].y);
      now_ankle[i].z = rested_ankle[i].y;
    }
    auto hold_drawn = [&] {
      const int held = limit_drawn_travel(limits_from, from, ctx.last_angles, ctx.ankles.ankle,
                                          DrawnRoot{px, py, pelvis_h, heading}, a, now_ankle, keep);
      for (int i = 0; i < 2; ++i)
        if (landing[i] && (held & (1 << i)) != 0) lo.planted[i] = false;
      return held != 0;
    };
    if (hold_drawn()) {
      // A leg held back may come back into the other one (game 2 seq 9484,
      // feet 3 mm too close): it is turned out again and checked again,
      // kDrawnTurnsApart times at most, until a check lets it be. Every
      // turn is checked: left at the last one, a foot passed the pop bound
      // (game 1 seq 8794, right 9: 0.61 m a frame at 60 Hz, session 34);
      // the drawn-leg check below keeps the legs apart in the blend.
      bool held = true;
      for (int k = 0; k < kDrawnTurnsApart && held && own_feet && !contact; ++k) {
        separate_legs_again(limits_from, body, pelvis_h, ctx.last_angles, &ctx.ankles, lo.planted, a);
        held = hold_drawn();
      }
      rest_on_grass(8.0f);
    }
  }
  // Nor do the legs pass through each other as the clients draw the frame
  // (drawn_leg_clearance.hpp), in a whole-body action (a tackle, a dive)
  // too: the clients blend its frames as any others (game 1 seq 5496, legs
  // through each other at 60 Hz on three of eight phases of the display).
  // Resting on the grass again may level a foot in the air into the other
  // one: then the step runs again.
  if (in.drawn_legs != nullptr && !in.reset && ctx.ankles.valid && rested && !contact) {
    for (int k = 0; k < kDrawnApartTries; ++k) {
      if (!keep_legs_apart_drawn(*in.drawn_legs, limits_from, in.grid, ctx.last_sent, ctx.last_angles,
                                 DrawnRoot{px, py, pelvis_h, heading}, lo.planted, a, k > 0))
        break;
      rest_on_grass(8.0f);
    }
  }
  for (int i = 0; i < 2; ++i)  // every touch-down counts for the mocap walk's cadence guard
    if (lo.planted[i] && !ctx.last_planted[i]) ctx.walk_since_land[i] = 0;
  ctx.last_planted[0] = lo.planted[0];
  ctx.last_planted[1] = lo.planted[1];
  ctx.pelvis_height = pelvis_h;
  if (rested) {
    for (int i = 0; i < 2; ++i) {
      body.to_field(rested_ankle[i].x, rested_ankle[i].z, ctx.ankles.ankle[i].x, ctx.ankles.ankle[i].y);
      ctx.ankles.ankle[i].z = rested_ankle[i].y;
    }
  } else {
    ankle_positions(limits_from, a, pelvis_h, body, ctx.ankles.ankle);
  }
  ctx.ankles.pelvis = glm::vec3(px, py, pelvis_h);
  ctx.ankles.valid = true;
  // A kick's support foot that the limits held short of its spot as it
  // plants stays where it came down: taken on to the spot on the next
  // frame, it slid there over the grass.
  if (act != nullptr && act->feet && act->support_lands && ctx.motion_active) {
    const int sup = 1 - act->kick_foot;
    const glm::vec3& at = ctx.ankles.ankle[sup];
    const float off = pm::hypot(at.x - act->foot_x[sup], at.y - act->foot_y[sup]);
    if (off > 0.01f && off < kSupportReanchorM && at.z < dims::kAnkleHeight + kSupportReanchorM) {
      ctx.motion.support_x = at.x;
      ctx.motion.support_y = at.y;
    }
  }
  for (int d = 0; d < dof::kCount; ++d) ctx.last_angles[static_cast<std::size_t>(d)] = a[static_cast<std::size_t>(d)];
  if (planted != nullptr) { planted[0] = lo.planted[0]; planted[1] = lo.planted[1]; }

  out.x = px;
  out.y = py;
  out.z = pelvis_h;
  out.heading = heading;
  // On the stream's grid, rounded so as not to move the ankles (the frames
  // the animation goes on from, ctx's, stay unrounded).
  if (in.grid != nullptr && rested)
    round_legs_to_grid(*in.grid, limits_from, m.data(), out, contact ? act->kick_foot : -1);
  ctx.last_sent = out;
}

}  // namespace mc::anim
