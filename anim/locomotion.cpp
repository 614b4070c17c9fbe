#include "anim/locomotion.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"

namespace mc::anim {
namespace {

// Usable leg reach hip -> ankle: a little short of straight so that IK keeps
// a soft knee and pelvis twist never pushes a planted foot out of reach.
constexpr float kReach = 0.965f * (dims::kThigh + dims::kShin);
constexpr float kStandPelvis = 0.975f;
constexpr float kRestTolerance = 0.07f;  // m from the resting spot that counts as "under the hip"
constexpr float kRestYawTolerance = 30;  // deg

// Side of each foot: +1 right (+Z), -1 left.
constexpr float kSide[2] = {1.0f, -1.0f};

float phase_of_foot(float phase, int foot) {
  float p = phase - (foot == 0 ? 0.0f : 0.5f);
  if (p < 0) p += 1.0f;
  return p;
}

// Highest pelvis that keeps an ankle (body space) within reach of its hip.
float pelvis_limit(const float ankle[3], int foot) {
  const float dz = ankle[2] - kSide[foot] * dims::kHipHalfWidth;
  const float horiz2 = ankle[0] * ankle[0] + dz * dz;
  const float v2 = kReach * kReach - horiz2;
  const float v = v2 > 0.04f ? std::sqrt(v2) : 0.2f;
  return ankle[1] + v + dims::kHipDrop;
}

void place_at_rest(LocomotionState& s, const BodyFrame& body, int foot) {
  FootState& f = s.feet[foot];
  body.to_field(0.0f, kSide[foot] * 0.11f, f.x, f.y);
  f.from_x = f.x; f.from_y = f.y;
  f.yaw = f.from_yaw = body.heading;
  f.planted = true; f.lift = 0; f.progress = 0;
}

}  // namespace

float human_step_length(float v) {
  // Speed (m/s) -> step length (m): walking mocap, Dorn et al. 2012, Salo et al. 2011.
  static constexpr std::array<float, 9> kV{0.0f, 1.0f, 1.5f, 2.0f, 3.5f, 5.2f, 7.0f, 8.95f, 11.0f};
  static constexpr std::array<float, 9> kL{0.30f, 0.55f, 0.72f, 0.85f, 1.25f, 1.65f, 1.95f, 2.05f, 2.50f};
  if (v <= kV[0]) return kL[0];
  for (std::size_t i = 1; i < kV.size(); ++i)
    if (v <= kV[i]) return kL[i - 1] + (kL[i] - kL[i - 1]) * (v - kV[i - 1]) / (kV[i] - kV[i - 1]);
  return kL.back() * v / kV.back();
}

void step_locomotion(LocomotionState& s, const LocomotionInput& in, const LocomotionParams& prm,
                     LocomotionOutput& out) {
  const BodyFrame body(in.x, in.y, in.heading);
  if (!s.initialized || in.reset) {
    s.initialized = true;
    s.x = in.x; s.y = in.y; s.heading = in.heading;
    s.speed = 0;
    s.pelvis_height = kStandPelvis;
    place_at_rest(s, body, 0);
    place_at_rest(s, body, 1);
  }
  const float dt = in.dt > 1e-4f ? in.dt : 0.05f;
  const float ds = std::hypot(in.x - s.x, in.y - s.y);
  // Turning on the spot counts as distance: the feet must step round.
  const float dturn = std::fabs(delta_deg(in.heading, s.heading)) * kDeg * 0.25f;
  const float v_inst = ds / dt;
  s.speed += (v_inst - s.speed) * (1.0f - std::exp2(-dt / prm.speed_halflife_s));

  // Stride from the smoothed speed, shortened by fatigue, and never so short
  // that this frame's advance would exceed the cadence cap.
  const float stride_factor = 0.85f + 0.15f * clampf(in.stamina, 0.0f, 1.0f);
  float cycle = 2.0f * human_step_length(s.speed) * stride_factor;
  cycle = std::max(cycle, 2.0f * (ds + dturn) / (prm.cadence_cap * dt));
  s.cycle_m = cycle;
  const float beta = clampf(prm.max_stance_travel / cycle, 0.18f, 0.62f);  // stance fraction
  const float run = clampf((s.speed - 2.2f) / 2.5f, 0.0f, 1.0f);
  const float moving = in.rest ? 0.0f : clampf(s.speed / 0.6f, 0.0f, 1.0f);

  // Are both feet already resting under the hips?
  bool settled = true;
  for (int i = 0; i < 2; ++i) {
    const FootState& f = s.feet[i];
    float bx, bz;
    body.to_body(f.x, f.y, bx, bz);
    if (!f.planted || std::hypot(bx, bz - kSide[i] * 0.11f) > kRestTolerance ||
        std::fabs(delta_deg(f.yaw, in.heading)) > kRestYawTolerance)
      settled = false;
  }
  float dphase = (ds + dturn) / cycle;
  if (in.rest || s.speed < 0.3f) {
    if (settled && ds < 0.02f) dphase = 0;
    else dphase = std::max(dphase, prm.settle_cadence * dt * 0.5f);
  }
  const float phase0 = posture_phase(s.posture_m);
  s.posture_m = advance_posture(s.posture_m, dphase * kReferenceCycleM, kReferenceCycleM);

  // Direction of travel for the landing spots.
  float ux = in.move_dx, uy = in.move_dy;
  const float un = std::hypot(ux, uy);
  if (un > 1e-3f) { ux /= un; uy /= un; } else { ux = uy = 0; }

  for (int i = 0; i < 2; ++i) {
    FootState& f = s.feet[i];
    const float psi0 = phase_of_foot(phase0, i);
    float bx, bz;
    body.to_body(f.x, f.y, bx, bz);
    const bool too_far = f.planted && std::hypot(bx, bz - kSide[i] * dims::kHipHalfWidth) > 0.55f;
    const bool scheduled = psi0 < beta && psi0 + dphase >= beta;
    if (f.planted && dphase > 0 && (scheduled || too_far)) {
      f.planted = false;
      f.from_x = f.x; f.from_y = f.y; f.from_yaw = f.yaw;
      f.progress = scheduled ? (psi0 + dphase - beta) / (1.0f - beta) : 0.0f;
    } else if (!f.planted) {
      f.progress += dphase / (1.0f - beta);
    }
    if (f.planted) continue;
    const float p = std::min(f.progress, 1.0f);
    // Landing spot: where the hip will be at touch-down, plus half a stance ahead.
    const float travel = (1.0f - p) * (1.0f - beta) * cycle * moving;
    const float ahead = 0.5f * beta * cycle * moving;
    float tx, ty;
    body.to_field(0.0f, kSide[i] * prm.foot_spacing, tx, ty);
    tx += ux * (travel + ahead);
    ty += uy * (travel + ahead);
    // Legs never cross: keep the landing spot on this foot's side of the other foot.
    const FootState& o = s.feet[1 - i];
    float obx, obz, tbx, tbz;
    body.to_body(o.x, o.y, obx, obz);
    body.to_body(tx, ty, tbx, tbz);
    if (kSide[i] * (tbz - obz) < 0.14f) {
      tbz = obz + kSide[i] * 0.14f;
      body.to_field(tbx, tbz, tx, ty);
    }
    const float w = smoothstep(p);
    f.x = f.from_x + (tx - f.from_x) * w;
    f.y = f.from_y + (ty - f.from_y) * w;
    f.yaw = lerp_deg(f.from_yaw, in.heading, w);
    f.lift = (0.07f + 0.12f * run) * std::sin(kPi * p) * std::max(moving, 0.5f);
    if (f.progress >= 1.0f) {
      f.planted = true;
      f.lift = 0;
      f.progress = 0;
      ++s.steps;
    }
  }

  // Rhythmic channels and pelvis height.
  SampleGaitJob sample{gait_keys(), s.posture_m, &out.sample, nullptr, nullptr};
  sample.Run();
  const float amp = clampf(s.speed / 1.5f, 0.0f, 1.0f) * (in.rest ? 0.3f : 1.0f);
  float pelvis = kStandPelvis - 0.06f * run * stride_factor - 0.02f * amp +
                 amp * (0.012f * (1.0f - run) * out.sample.bob_walk + 0.03f * run * out.sample.bob_run);
  for (int i = 0; i < 2; ++i) {
    const FootState& f = s.feet[i];
    FootTarget& t = out.feet[i];
    body.to_body(f.x, f.y, t.ankle_ms[0], t.ankle_ms[2]);
    t.ankle_ms[1] = dims::kAnkleHeight + f.lift;
    t.yaw_deg = -delta_deg(f.yaw, in.heading);
    t.pitch_deg = f.planted ? 0.0f : 12.0f * std::sin(2.0f * kPi * std::min(f.progress, 1.0f)) * run;
    out.planted[i] = f.planted;
    pelvis = std::min(pelvis, pelvis_limit(t.ankle_ms, i));
  }
  s.pelvis_height = std::max(pelvis, 0.62f);
  out.pelvis_height = s.pelvis_height;
  out.run = run;
  out.amplitude = amp;
  s.x = in.x; s.y = in.y; s.heading = in.heading;
}

}  // namespace mc::anim
