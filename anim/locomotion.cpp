#include "anim/locomotion.hpp"

#include <algorithm>
#include <array>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/portable_math.hpp"

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

void take_over_feet(LocomotionState& s, const float x[2], const float y[2], const float yaw[2],
                    const bool planted[2], const bool take[2]) {
  for (int i = 0; i < 2; ++i) {
    if (!take[i]) continue;
    FootState& f = s.feet[i];
    f.x = f.from_x = x[i];
    f.y = f.from_y = y[i];
    BodyFrame(s.x, s.y, s.heading).to_body(f.x, f.y, f.rel_x, f.rel_z);
    f.yaw = f.from_yaw = yaw[i];
    f.lift = 0;
    if (planted[i] && !f.planted) { f.planted_frames = 0; f.stance_phase = 0; }
    f.planted = planted[i];
    f.progress = planted[i] ? 0.0f : 0.5f;
  }
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
    // Ready to step off, right foot first.
    s.feet[0].stance_phase = 1.0f;
    s.feet[1].stance_phase = 0.5f;
    s.feet[0].planted_frames = s.feet[1].planted_frames = 100;
  }
  const float dt = in.dt > 1e-4f ? in.dt : 0.05f;
  const float ds = pm::hypot(in.x - s.x, in.y - s.y);
  // Turning on the spot counts as distance: the feet must step round.
  const float dturn = std::fabs(delta_deg(in.heading, s.heading)) * kDeg * 0.25f;
  const float v_inst = ds / dt;
  s.speed += (v_inst - s.speed) * (1.0f - pm::exp2(-dt / prm.speed_halflife_s));

  // Stride from the smoothed speed, shortened by fatigue, and never so short
  // that this frame's advance would exceed the cadence cap.
  const float stride_factor = 0.85f + 0.15f * clampf(in.stamina, 0.0f, 1.0f);
  float cycle = 2.0f * human_step_length(s.speed) * stride_factor;
  cycle = std::max(cycle, 2.0f * (ds + dturn) / (prm.cadence_cap * dt));
  s.cycle_m = cycle;
  // Stance fraction. Above ~4 m/s a planted leg would sweep more than the
  // joint speed limit per frame (v * dt / leg length), so the foot stays
  // down for one frame only: a touch-and-go, as a sprinter's 0.1 s contact
  // looks at 20 frames per second.
  const bool one_frame = ds > prm.one_frame_stance_m;
  const float travel = one_frame ? ds * 0.98f : prm.max_stance_travel;
  const float beta = clampf(travel / cycle, 0.02f, 0.62f);
  const float run = clampf((s.speed - 2.2f) / 2.5f, 0.0f, 1.0f);
  const float moving = in.rest ? 0.0f : clampf(s.speed / 0.6f, 0.0f, 1.0f);

  // Are both feet already resting under the hips?
  bool settled = true;
  for (int i = 0; i < 2; ++i) {
    const FootState& f = s.feet[i];
    float bx, bz;
    body.to_body(f.x, f.y, bx, bz);
    if (!f.planted || pm::hypot(bx, bz - kSide[i] * 0.11f) > kRestTolerance ||
        std::fabs(delta_deg(f.yaw, in.heading)) > kRestYawTolerance)
      settled = false;
  }
  float dphase = (ds + dturn) / cycle;
  if (in.rest || s.speed < 0.3f) {
    if (settled && ds < 0.02f) dphase = 0;
    else dphase = std::max(dphase, prm.settle_cadence * dt * 0.5f);
  }
  // The posture index follows the distance; a touch-down off its keyframe
  // pulls it back into step gradually (a few frames), so that the rhythmic
  // channels stay continuous.
  const float corr = dphase > 0 ? clampf(0.25f * s.phase_error, -0.03f, 0.03f) : 0.0f;
  s.phase_error -= corr;
  s.posture_m = advance_posture(s.posture_m, (dphase - corr) * kReferenceCycleM, kReferenceCycleM);

  // Direction of travel for the landing spots.
  float ux = in.move_dx, uy = in.move_dy;
  const float un = pm::hypot(ux, uy);
  if (un > 1e-3f) { ux /= un; uy /= un; } else { ux = uy = 0; }

  // Lift-off: a foot's own stance lasts a fraction beta of the cycle (so each
  // foot steps once per cycle and the cadence cap holds), and the feet
  // alternate: walking waits for the other foot to be down, running for it
  // to be half-way through its swing. A foot left too far behind or twisted
  // past what the hip can turn steps early, but not in the first frames after
  // its touch-down.
  bool wants[2] = {false, false};
  float eager[2] = {0, 0};
  for (int i = 0; i < 2; ++i) {
    const FootState& f = s.feet[i];
    const FootState& o = s.feet[1 - i];
    if (f.planted && f.release) {
      wants[i] = true;
      eager[i] = 2.0f;
      continue;
    }
    if (!f.planted || dphase <= 0) continue;
    float bx, bz;
    body.to_body(f.x, f.y, bx, bz);
    const bool at_rest = pm::hypot(bx, bz - kSide[i] * 0.11f) <= kRestTolerance &&
                         std::fabs(delta_deg(f.yaw, in.heading)) <= kRestYawTolerance;
    if (moving == 0 && at_rest) continue;
    const bool too_far = f.planted_frames >= 2 && pm::hypot(bx, bz - kSide[i] * dims::kHipHalfWidth) > 0.55f;
    const bool twisted = f.planted_frames >= 2 && std::fabs(delta_deg(f.yaw, in.heading)) > 50.0f;
    const bool due = f.stance_phase + dphase >= beta || twisted;
    const bool other_ok = o.planted || (beta < 0.5f && (o.progress >= 0.4f || one_frame));
    // A foot being dragged goes even if the other is in the air (a flight
    // phase, as in sprinting).
    if ((due && other_ok) || too_far) {
      wants[i] = true;
      eager[i] = f.stance_phase + (too_far ? 1.0f : 0.0f);
    }
  }
  // Both planted and both due: the longer stance goes first, the other waits.
  if (wants[0] && wants[1] && s.feet[0].planted && s.feet[1].planted && !s.feet[0].release && !s.feet[1].release)
    wants[eager[0] >= eager[1] ? 1 : 0] = false;

  for (int i = 0; i < 2; ++i) {
    FootState& f = s.feet[i];
    ++f.since_landing;
    f.release = false;
    if (wants[i]) {
      f.planted = false;
      f.from_x = f.x; f.from_y = f.y; f.from_yaw = f.yaw;
      f.progress = std::max(0.0f, f.stance_phase + dphase - beta) / (1.0f - beta);
      f.progress = std::min(f.progress, 0.3f);
      body.to_body(f.x, f.y, f.rel_x, f.rel_z);
    } else if (!f.planted) {
      // Two feet in the air close together in their swings drift apart: the
      // one behind slows, so that running steps alternate.
      const FootState& o = s.feet[1 - i];
      const bool crowded = !o.planted && o.progress > f.progress && o.progress - f.progress < 0.45f;
      f.progress += dphase / (1.0f - beta) * (crowded ? 0.5f : 1.0f);
    }
    if (f.planted) {
      ++f.planted_frames;
      f.stance_phase += dphase;
      continue;
    }
    const float p = std::min(f.progress, 1.0f);
    // The swing is planned relative to the moving body: from where the foot
    // left the grass (body space, at lift-off) to half a stance ahead of the
    // hip, along the direction of travel. So the foot passes under the body
    // mid-swing, whatever the 2D player does meanwhile.
    float ubx, ubz;
    body.dir_to_body(ux, uy, ubx, ubz);
    const float ahead = 0.5f * beta * cycle * moving;
    float tbx = ubx * ahead, tbz = kSide[i] * prm.foot_spacing + ubz * ahead;
    // Legs never cross: keep the landing spot on this foot's side of the other foot.
    const FootState& o = s.feet[1 - i];
    float obx, obz;
    body.to_body(o.x, o.y, obx, obz);
    if (kSide[i] * (tbz - obz) < 0.14f) tbz = obz + kSide[i] * 0.14f;
    // Within a comfortable reach of the hip.
    const float hz = kSide[i] * dims::kHipHalfWidth;
    const float off = pm::hypot(tbx, tbz - hz);
    if (off > 0.5f) {
      tbx *= 0.5f / off;
      tbz = hz + (tbz - hz) * 0.5f / off;
    }
    const float w = smoothstep(p);
    float rx = f.rel_x + (tbx - f.rel_x) * w;
    const float rz = f.rel_z + (tbz - f.rel_z) * w;
    if (run > 0) {
      // Running: the heel first rises behind the body, then the knee drives
      // the foot forward to its spot.
      const float back = std::min(f.rel_x, -0.3f);
      const float run_x = p < 0.3f ? f.rel_x + (back - f.rel_x) * smoothstep(p / 0.3f)
                                   : back + (tbx - back) * smoothstep((p - 0.3f) / 0.7f);
      rx += (run_x - rx) * run;
    }
    body.to_field(rx, rz, f.x, f.y);
    f.yaw = lerp_deg(f.from_yaw, in.heading, w);
    f.lift = (0.07f + 0.2f * run) * pm::sin(kPi * p) * std::max(moving, 0.5f);
    // Touch-down, unless this foot landed too recently for a human cadence:
    // then it hovers a frame longer just above its spot.
    const int min_frames = static_cast<int>(std::ceil(2.0f / (prm.hard_cadence_cap * dt) - 1e-3f));
    if (f.progress >= 1.0f && f.since_landing < min_frames) {
      f.progress = 0.97f;
      f.lift = std::max(f.lift, 0.01f);
    }
    if (f.progress >= 1.0f) {
      f.planted = true;
      f.since_landing = 0;
      f.planted_frames = 0;
      f.stance_phase = 0;
      // Touch-down of the right foot is phase 0, of the left 0.5.
      float e = posture_phase(s.posture_m) - (i == 0 ? 0.0f : 0.5f);
      e -= std::floor(e + 0.5f);
      s.phase_error = e;
      f.lift = 0;
      f.progress = 0;
      ++s.steps;
    }
  }

  // Rhythmic channels and pelvis height.
  SampleGaitJob sample{gait_keys(), s.posture_m, &out.sample, nullptr, nullptr};
  sample.Run();
  const float amp = clampf(s.speed / 1.5f, 0.0f, 1.0f) * (in.rest ? 0.3f : 1.0f);
  float pelvis = kStandPelvis - 0.03f * run * stride_factor - 0.02f * amp +
                 amp * (0.012f * (1.0f - run) * out.sample.bob_walk + 0.03f * run * out.sample.bob_run);
  for (int i = 0; i < 2; ++i) {
    const FootState& f = s.feet[i];
    FootTarget& t = out.feet[i];
    body.to_body(f.x, f.y, t.ankle_ms[0], t.ankle_ms[2]);
    t.ankle_ms[1] = dims::kAnkleHeight + f.lift;
    t.yaw_deg = -delta_deg(f.yaw, in.heading);
    t.pitch_deg = f.planted ? 0.0f : 12.0f * pm::sin(2.0f * kPi * std::min(f.progress, 1.0f)) * run;
    out.planted[i] = f.planted;
    // Only planted feet hold the pelvis down; a swinging foot may tuck.
    if (f.planted) pelvis = std::min(pelvis, pelvis_limit(t.ankle_ms, i));
  }
  // The pelvis moves at most 1.5 cm per frame, so the
  // knees never snap; the rare foot it leaves out of reach is clamped by IK.
  pelvis = clampf(pelvis, s.pelvis_height - 0.015f, s.pelvis_height + 0.015f);
  s.pelvis_height = std::max(pelvis, 0.62f);
  out.pelvis_height = s.pelvis_height;
  out.run = run;
  out.amplitude = amp;
  s.x = in.x; s.y = in.y; s.heading = in.heading;
}

}  // namespace mc::anim
