#include "anim/action_motion.hpp"

#include <algorithm>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/portable_math.hpp"

namespace mc::anim {
namespace {

// One keyframe of the kicking ankle, relative to the contact spot: `along`
// metres along the kick direction, `up` metres above the contact height.
struct KickKey { float tau, along, up, pitch; };

void sample_kick_foot(const ActionMotion& m, float tau, float& along, float& up, float& pitch) {
  // Backswing (hip extension, knee flexion), contact, follow-through, landing.
  const float f = std::max(m.follow_s, 0.12f);
  const KickKey keys[] = {
      {m.start_s, -0.15f, 0.06f, -10},
      {std::min(-0.06f, m.start_s + 0.05f), -0.42f * m.backswing, 0.22f * m.backswing, -30},
      {0.0f, 0.0f, 0.0f, -15},
      {0.10f, 0.42f, 0.28f, -10},
      {f, 0.55f, 0.14f, -5},
      {std::max(m.end_s, f + 0.05f), 0.45f, -(m.contact_h - dims::kAnkleHeight), 0},
  };
  constexpr int n = sizeof keys / sizeof keys[0];
  if (tau <= keys[0].tau) { along = keys[0].along; up = keys[0].up; pitch = keys[0].pitch; return; }
  for (int i = 1; i < n; ++i) {
    if (tau <= keys[i].tau) {
      const float span = std::max(keys[i].tau - keys[i - 1].tau, 1e-3f);
      const float w = smoothstep((tau - keys[i - 1].tau) / span);
      along = keys[i - 1].along + (keys[i].along - keys[i - 1].along) * w;
      up = keys[i - 1].up + (keys[i].up - keys[i - 1].up) * w;
      pitch = keys[i - 1].pitch + (keys[i].pitch - keys[i - 1].pitch) * w;
      return;
    }
  }
  along = keys[n - 1].along; up = keys[n - 1].up; pitch = keys[n - 1].pitch;
}

// Ramps in over `in_s` from the start and out over `out_s` before the end.
float envelope(const ActionMotion& m, float tau, float in_s, float out_s) {
  if (tau < m.start_s || tau > m.end_s) return 0;
  return std::min(smoothstep((tau - m.start_s) / in_s), smoothstep((m.end_s - tau) / out_s));
}

// Sideways gap (m) between the support foot and the kicking foot's landing.
constexpr float kLandingClearance = 0.24f;
// The least sideways gap while the foot follows through.
constexpr float kFollowClearance = 0.16f;

void kick(const ActionMotion& m, float tau, float heading, float root_x, float root_y, ActionSample& s) {
  s.feet = true;
  // Ramp in over at most 0.1 s, and fully in by contact whatever the look-ahead.
  s.weight = smoothstep((tau - m.start_s) / std::min(0.1f, std::max(-m.start_s, 0.01f)));
  const int k = m.foot == Foot::Right ? 0 : 1;
  const int sup = 1 - k;
  float along, up, pitch;
  sample_kick_foot(m, tau, along, up, pitch);
  s.foot_x[k] = m.contact_x + m.dir_x * along;
  s.foot_y[k] = m.contact_y + m.dir_y * along;
  // After the follow-through the foot comes down beside the body, wherever
  // the 2D player has gone meanwhile.
  if (tau > m.follow_s) {
    const float side_k = k == 0 ? 1.0f : -1.0f;
    const BodyFrame body(root_x, root_y, heading);
    // Beside the body, and on its own side of a support foot that is still
    // planted where the kick left it (the body may have drifted over it):
    // the shins must not cross.
    float lz = side_k * 0.12f;
    if (pm::hypot(m.support_x - root_x, m.support_y - root_y) <= 0.45f) {
      float sbx, sbz;
      body.to_body(m.support_x, m.support_y, sbx, sbz);
      if (side_k * (lz - sbz) < kLandingClearance) lz = sbz + side_k * kLandingClearance;
    }
    float lx, ly;
    body.to_field(0.05f, lz, lx, ly);
    const float w = smoothstep((tau - m.follow_s) / std::max(m.end_s - m.follow_s, 0.05f));
    s.foot_x[k] += (lx - s.foot_x[k]) * w;
    s.foot_y[k] += (ly - s.foot_y[k]) * w;
  }
  // After contact the body may turn away while the foot follows through
  // along the kick: the foot is kept on its own side of a support foot that
  // is still planted, eased in over 0.1 s (the contact stays where it was).
  if (tau > 0 && pm::hypot(m.support_x - root_x, m.support_y - root_y) <= 0.45f) {
    const float side_k = k == 0 ? 1.0f : -1.0f;
    const BodyFrame body(root_x, root_y, heading);
    float fbx, fbz, sbx, sbz;
    body.to_body(s.foot_x[k], s.foot_y[k], fbx, fbz);
    body.to_body(m.support_x, m.support_y, sbx, sbz);
    const float need = sbz + side_k * kFollowClearance;
    if (side_k * (fbz - need) < 0) {
      fbz += (need - fbz) * smoothstep(tau / 0.1f);
      body.to_field(fbx, fbz, s.foot_x[k], s.foot_y[k]);
    }
  }
  s.foot_h[k] = std::max(m.contact_h + up, dims::kAnkleHeight);
  s.foot_yaw[k] = m.foot_yaw;
  s.foot_pitch[k] = pitch;
  s.planted[k] = tau >= m.end_s - 1e-4f;
  s.foot_weight[k] = s.weight;
  s.kick_foot = k;
  s.to_contact_s = -tau;
  s.contact_ankle_x = m.contact_x;  // the keyframes' contact: along 0, up 0
  s.contact_ankle_y = m.contact_y;
  s.contact_ankle_h = std::max(m.contact_h, dims::kAnkleHeight);
  // The support foot is down beside the ball from just before contact; it
  // leaves locomotion for its spot only in the 0.1 s before it plants (a long
  // look-ahead does not pin it to a spot the running body has not reached).
  const float plant_at = std::max(-0.05f, m.start_s);
  const float reach_from = std::max(m.start_s, plant_at - 0.1f);
  const float sw = tau >= plant_at ? 1.0f : smoothstep((tau - reach_from) / std::max(plant_at - reach_from, 0.01f));
  s.foot_weight[sup] = std::min(sw, s.weight > 0 ? 1.0f : 0.0f);
  s.foot_x[sup] = m.support_x;
  s.foot_y[sup] = m.support_y;
  s.foot_h[sup] = dims::kAnkleHeight + (tau < plant_at ? 0.08f * pm::sin(kPi * sw) : 0.0f);
  s.foot_yaw[sup] = heading;
  s.foot_pitch[sup] = 0;
  s.planted[sup] = tau >= plant_at - 1e-4f;
  s.support_lands = s.planted[sup] && tau < plant_at + 0.05f - 1e-4f;
  // After contact, once the 2D player has run on past the support foot's
  // reach, locomotion takes that foot back (it steps off, it is not dragged).
  if (tau > 0 && pm::hypot(m.support_x - root_x, m.support_y - root_y) > 0.45f) {
    s.planted[sup] = false;
    s.foot_weight[sup] = 0;
  }
  // Step-in: the root reaches towards the ball on the contact frame only, so
  // that it still lies on the 2D position at every cycle.
  if (std::fabs(tau) < 0.02f) {
    s.root_dx = m.lunge_x;
    s.root_dy = m.lunge_y;
    s.contact = true;
    s.ball_x = m.ball_x;
    s.ball_y = m.ball_y;
    s.ball_h = m.ball_radius;
    s.ball_r = m.ball_radius;
  }
  const float near = 1.0f - smoothstep(std::fabs(tau) / 0.2f);
  s.pelvis_height = 0.95f + (m.pelvis_height - 0.95f) * near;
  // Upper body: lean over the ball, the arm opposite the kicking leg forward.
  const float side = k == 0 ? 1.0f : -1.0f;
  auto& a = s.angles;
  a[dof::kPelvis + 0] = -side * 12.0f * near;
  a[dof::kPelvis + 1] = -6.0f * near;
  a[dof::kTorso + 0] = side * 8.0f * near;
  a[dof::kTorso + 1] = -14.0f * near;
  const int kick_arm = k == 0 ? dof::kRShoulder : dof::kLShoulder;
  const int other_arm = k == 0 ? dof::kLShoulder : dof::kRShoulder;
  a[kick_arm + 0] = -25.0f;
  a[kick_arm + 1] = -side * 35.0f;
  a[other_arm + 0] = 45.0f;
  a[other_arm + 1] = side * 50.0f;
  a[dof::kRElbow] = 30.0f;
  a[dof::kLElbow] = 30.0f;
}

void tackle(const ActionMotion& m, float tau, ActionSample& s) {
  s.whole_body = true;
  s.weight = envelope(m, tau, 0.15f, 0.3f);
  s.pelvis_height = 0.95f + (0.30f - 0.95f) * s.weight;
  const bool right = m.foot == Foot::Right;
  auto& a = s.angles;
  a[dof::kPelvis + 1] = 30;   // lean back into the slide
  a[dof::kTorso + 1] = -15;
  a[dof::kRShoulder + 0] = 25; a[dof::kRShoulder + 1] = -60; a[dof::kRElbow] = 25;
  a[dof::kLShoulder + 0] = 25; a[dof::kLShoulder + 1] = 60; a[dof::kLElbow] = 25;
  const int lead_hip = right ? dof::kRHip : dof::kLHip, trail_hip = right ? dof::kLHip : dof::kRHip;
  const int lead_knee = right ? dof::kRKnee : dof::kLKnee, trail_knee = right ? dof::kLKnee : dof::kRKnee;
  const int lead_ankle = right ? dof::kRAnkle : dof::kLAnkle;
  // The leading leg slides along the grass; the other is folded under it.
  a[lead_hip] = 58; a[lead_knee] = -5; a[lead_ankle] = -20;
  a[trail_hip] = 45; a[trail_hip + 1] = right ? 25.0f : -25.0f; a[trail_knee] = -150;
}

// A catch is the upper body's: the arms take the ball in and the trunk
// bends over it while the legs stay locomotion's, on their footsteps, with
// the pelvis lowered into a crouch. A goalkeeper often catches on the run
// or sets off with the ball at once; given as a whole-body crouch, the
// legs glided with the body for the catch's 0.5 s (game 1 seq 1486-1491,
// a goalkeeper at 6-10 m/s with both feet on the grass).
void catch_ball(const ActionMotion& m, float tau, ActionSample& s) {
  s.weight = envelope(m, tau, 0.12f, 0.25f);
  s.pelvis_height = 0.95f + (0.84f - 0.95f) * s.weight;
  auto& a = s.angles;
  a[dof::kPelvis + 1] = -12;
  a[dof::kTorso + 1] = -10;
  a[dof::kRShoulder + 0] = 95; a[dof::kRShoulder + 1] = 8; a[dof::kRElbow] = 35;
  a[dof::kLShoulder + 0] = 95; a[dof::kLShoulder + 1] = -8; a[dof::kLElbow] = 35;
}

void dive(const ActionMotion& m, float tau, ActionSample& s) {
  s.whole_body = true;
  s.weight = envelope(m, tau, 0.15f, 0.35f);
  s.pelvis_height = 0.95f + (0.42f - 0.95f) * s.weight;
  auto& a = s.angles;
  a[dof::kPelvis + 2] = 75.0f * m.side;  // roll towards the ball's side
  a[dof::kTorso + 2] = 10.0f * m.side;
  a[dof::kRShoulder + 0] = 160; a[dof::kRShoulder + 1] = m.side > 0 ? -30.0f : 0.0f; a[dof::kRElbow] = 10;
  a[dof::kLShoulder + 0] = 160; a[dof::kLShoulder + 1] = m.side > 0 ? 0.0f : 30.0f; a[dof::kLElbow] = 10;
  a[dof::kRHip] = 15; a[dof::kLHip] = 5;
  a[dof::kRKnee] = -20; a[dof::kLKnee] = -35;
}

}  // namespace

ActionSample sample_action(const ActionMotion& m, float tau, float heading, float root_x, float root_y) {
  ActionSample s;
  if (tau < m.start_s - 1e-4f || tau > m.end_s + 1e-4f) return s;
  switch (m.kind) {
    case MotionKind::Kick: kick(m, tau, heading, root_x, root_y, s); break;
    case MotionKind::Tackle: tackle(m, tau, s); break;
    case MotionKind::Catch: catch_ball(m, tau, s); break;
    case MotionKind::Dive: dive(m, tau, s); break;
  }
  return s;
}

}  // namespace mc::anim
