#include "anim/footsteps.hpp"

#include <algorithm>
#include <cmath>

#include "anim/body_frame.hpp"
#include "anim/exp2_remembered.hpp"
#include "anim/foot_passing.hpp"
#include "anim/human_skeleton.hpp"
#include "anim/portable_math.hpp"
#include "anim/segment_distance.hpp"
#include "anim/sincos_deg.hpp"

namespace mc::anim {
namespace {

constexpr float kSide[2] = {1.0f, -1.0f};  // +1 right (+Z), -1 left
// The sole (bottom of the foot's box): centre ahead of the ankle, half length.
constexpr float kSoleCentre = 0.5f * (dims::kFootFront - dims::kFootBack);  // 0.06
constexpr float kSoleHalf = 0.5f * (dims::kFootFront + dims::kFootBack);    // 0.13
constexpr float kSettleSwingS = 0.32f;  // s, a settling step's swing
constexpr float kSwingPastHipM = 0.55f;  // m a frame, a swinging ankle relative to the root (11 m/s)
// The same on the frame a foot lands, below kLandingBoundBelow m/s: it also
// comes down 0.1-0.2 m on that frame, and the clients' blend of its angles
// carries it fastest mid-frame. Landing steps of 0.48 m past the hip read
// 0.62 m a frame at 60 Hz (game 1 seq 1058, right 9: an ankle pop).
// Sprinters keep the full bound: held to 0.45 m their feet landed short
// and slid (game 2's 9+ m/s band 0.47 -> 0.55 m/s at 60 Hz).
constexpr float kLandingPastHipM = 0.45f;
constexpr float kLandingBoundBelow = 8.0f;
constexpr float kApproachSlope = 0.4f;  // m up per m still to travel, coming down
// m between two soles' centre lines when one lands: the boxes are 0.10 m
// wide (the quality tool's feet too close: nearer than 0.05 m).
constexpr float kSolesApartM = 0.11f;
constexpr float kMaxHeelRise = -35.0f;  // deg, the most a planted foot rolls up on its toes
// Above this gait speed (m/s) a foot stays on the grass until the hip is
// out of its reach, not a frame before. Lifting it a frame early cut a
// sprinter's stance to one frame (0.05 s, half of Weyand et al.'s 0.1 s),
// and the clients, blending from a foot on the grass to one in the air,
// drew it sliding as it left: the 9+ m/s band's grounded foot was 3.9 m/s
// at 60 Hz. Below 7.5 m/s the later lift also cut the 4-6 m/s bands'
// sliding by a sixth, but left the swinging thigh passing through the
// planted one in the blend 7 times as often (anim/README.md).
constexpr float kLeaveLateSpeed = 7.5f;

float wrap01(float p) { return p - std::floor(p); }

// How near (m) the centre lines of two soles come, each sole given by its
// centre and its yaw (deg) in one plane: feet at different yaws (a turn)
// can cross at a toe or a heel with their centres far enough apart.
float soles_apart(float ax, float ay, float ayaw, float bx, float by, float byaw) {
  const glm::vec3 da(pm::cos(ayaw * kDeg) * kSoleHalf, 0.0f, pm::sin(ayaw * kDeg) * kSoleHalf);
  const glm::vec3 db(pm::cos(byaw * kDeg) * kSoleHalf, 0.0f, pm::sin(byaw * kDeg) * kSoleHalf);
  const glm::vec3 a(ax, 0.0f, ay), b(bx, 0.0f, by);
  return segment_distance(a - da, a + da, b - db, b + db);
}

// Where the root is `t` seconds from now along the path ahead (then
// straight on at the last known velocity, for at most 0.6 s more).
void root_at(const FootstepInput& in, float t, float& x, float& y) {
  const float dt = in.dt > 1e-4f ? in.dt : 0.05f;
  float px = in.x, py = in.y, pt = 0;
  float vx = 0, vy = 0;
  for (int k = 0; k < in.ahead_n && k < kPathAhead; ++k) {
    const float kt = dt * static_cast<float>(k + 1);
    vx = (in.ahead_x[k] - px) / dt;
    vy = (in.ahead_y[k] - py) / dt;
    if (t <= kt) {
      const float w = (t - pt) / dt;
      x = px + (in.ahead_x[k] - px) * w;
      y = py + (in.ahead_y[k] - py) * w;
      return;
    }
    px = in.ahead_x[k];
    py = in.ahead_y[k];
    pt = kt;
  }
  const float rest = std::min(t - pt, 0.6f);
  x = px + vx * rest;
  y = py + vy * rest;
}

// The horizontal ease of a swing: still for its first few percent (the
// foot rises before it travels), then speeding up, cruising and slowing down
// to a stop over the last 40 % (it comes down with hardly any speed over the
// grass: the body catches up with it). A runner's foot gets going sooner,
// or the body would leave it far behind.
float swing_ease(float u, float run) {
  const float a = 0.08f - 0.04f * run, r1 = 0.2f - 0.1f * run, r2 = 0.4f;
  const float area = 1.0f - 0.5f * r1 - 0.5f * r2;
  const float w = clampf((u - a) / (1.0f - a), 0.0f, 1.0f);
  if (w < r1) return 0.5f * w * w / r1 / area;
  if (w < 1.0f - r2) return (0.5f * r1 + (w - r1)) / area;
  const float q = 1.0f - w;
  return 1.0f - 0.5f * q * q / r2 / area;
}

// The rise of a swing above its straight line, peak 1: symmetric when
// walking, earlier when running (the heel comes up behind first).
float swing_bump(float u, float run) {
  const float walk = 4.0f * u * (1.0f - u);
  const float sprint = 6.75f * u * (1.0f - u) * (1.0f - u);
  return walk + (sprint - walk) * run;
}

void to_target(const BodyFrame& body, float ax, float ay, float ah, float yaw, float pitch, FootTarget& t) {
  body.to_body(ax, ay, t.ankle_ms[0], t.ankle_ms[2]);
  t.ankle_ms[1] = ah;
  t.yaw_deg = -delta_deg(yaw, body.heading);
  t.pitch_deg = pitch;
}

// Lowest sole height of a foot whose ankle is at height `ah` with the sole pitched by `pitch`.
float sole_height(float ah, float pitch) {
  float s = 0, c = 1;
  sincos_deg(pitch, s, c);
  const float toe = dims::kFootFront * s - dims::kAnkleHeight * c;
  const float heel = -dims::kFootBack * s - dims::kAnkleHeight * c;
  return ah + std::min(toe, heel);
}

void rest_spot(const BodyFrame& body, int foot, float spacing, float& x, float& y) {
  body.to_field(kSoleCentre, kSide[foot] * spacing, x, y);
}

void plant(FootState& f, float x, float y, float yaw, float pitch) {
  f.planted = true;
  f.x = x; f.y = y; f.yaw = yaw; f.pitch = pitch;
  f.u = 0;
  f.stance_s = 0;
  f.release = false;
  f.leaving = false;
}

// Below this root speed (m/s) a body has no flight phase (human running
// starts near 2 m/s; gait_timing.hpp).
constexpr float kFlightMinSpeed = 2.0f;
// Both feet up below that speed: the landing foot's sole comes this low (m).
constexpr float kReachDownSoleM = 0.07f;

void lift(FootState& f, float phase_left, float lift_m) {
  float ax, ay, ah;
  planted_ankle(f.x, f.y, f.yaw, f.pitch, ax, ay, ah);
  f.planted = false;
  f.ax = ax; f.ay = ay; f.ah = ah;
  f.cx = ax; f.cy = ay;
  f.ayaw = f.yaw; f.apitch = f.pitch;
  f.bx = ax; f.by = ay; f.byaw = f.yaw; f.bpitch = 0;
  f.u = 0;
  f.extra = 0;
  f.phase_left = std::max(phase_left, 0.05f);
  f.lift = lift_m;
  f.release = false;
  f.leaving = false;
}

// Ankle of a swinging foot at its progress.
void swing_ankle(const FootState& f, float run, float& x, float& y, float& h, float& yaw, float& pitch) {
  const float v = smoothstep(f.u);
  float bh, bx, by;
  planted_ankle(f.bx, f.by, f.byaw, f.bpitch, bx, by, bh);
  x = f.cx;
  y = f.cy;
  h = f.ah + (bh - f.ah) * v + f.lift * swing_bump(f.u, run);
  // A steep approach: in the second half of the swing, the further it still
  // has to go, the higher it stays (up to the swing's own height), so that
  // it never travels low over the grass.
  if (f.u > 0.5f) h = std::max(h, bh + std::min(kApproachSlope * pm::hypot(bx - x, by - y), std::min(f.lift, 0.1f)));
  yaw = lerp_deg(f.ayaw, f.byaw, v);
  // The toes come level early in the swing and meet the landing's pitch at its end.
  pitch = f.apitch * (1.0f - smoothstep(f.u / 0.4f)) + f.bpitch * smoothstep((f.u - 0.6f) / 0.4f);
}

}  // namespace

void planted_ankle(float x, float y, float yaw_deg, float pitch_deg, float& ax, float& ay, float& ah) {
  // The edge it rolls over (heel for toes up, toes for heel up) stays on the
  // grass; the flat sole's centre is (x, y).
  const float e = pitch_deg > 0 ? -dims::kFootBack : dims::kFootFront;  // that edge, ahead of the ankle
  float s = 0, c = 1, ux = 1, uy = 0;
  sincos_deg(pitch_deg, s, c);
  sincos_deg(yaw_deg, uy, ux);
  const float along = (e - kSoleCentre) + (-e * c - dims::kAnkleHeight * s);
  ax = x + ux * along;
  ay = y + uy * along;
  ah = -e * s + dims::kAnkleHeight * c;
}

void take_over_foot(FootstepState& st, int foot, float x, float y, float h, float yaw, float pitch, bool planted) {
  FootState& f = st.feet[foot];
  if (planted) {
    if (!f.planted) f.since_landing = 0;
    plant(f, x, y, yaw, pitch);
  } else {
    f.planted = false;
    f.ax = f.bx = f.cx = x;
    f.ay = f.by = f.cy = y;
    f.ah = h;
    f.ayaw = f.byaw = yaw;
    f.apitch = pitch;
    f.bpitch = 0;
    f.u = 0.3f;
    f.phase_left = 0.25f;
    f.lift = 0.05f;
  }
}

void take_over_feet(FootstepState& st, const float ankle_x[2], const float ankle_y[2], const float yaw[2],
                    const bool planted[2], const bool take[2]) {
  for (int i = 0; i < 2; ++i) {
    if (!take[i]) continue;
    const float ux = pm::cos(yaw[i] * kDeg), uy = pm::sin(yaw[i] * kDeg);
    if (planted[i])
      take_over_foot(st, i, ankle_x[i] + ux * kSoleCentre, ankle_y[i] + uy * kSoleCentre, 0, yaw[i], 0, true);
    else
      take_over_foot(st, i, ankle_x[i], ankle_y[i], dims::kAnkleHeight, yaw[i], 0, false);
  }
}

void step_footsteps(FootstepState& s, const FootstepInput& in, const FootstepParams& prm, FootstepOutput& out) {
  const float dt = in.dt > 1e-4f ? in.dt : 0.05f;
  const BodyFrame body(in.x, in.y, in.heading);
  if (!s.initialized || in.reset) {
    s.initialized = true;
    s.x = in.x; s.y = in.y; s.heading = in.heading;
    s.vx = s.vy = s.speed = 0;
    s.moving = false;
    s.run = 0;
    s.pelvis_height = 0.975f;
    for (int i = 0; i < 2; ++i) {
      float x, y;
      rest_spot(body, i, prm.foot_spacing, x, y);
      plant(s.feet[i], x, y, in.heading, 0);
      s.feet[i].since_landing = 100;
      s.feet[i].stance_s = 1;
    }
    s.phase = 0.25f;
  }
  // Velocity along the path, centred on this frame where the look-ahead
  // allows, lightly smoothed; the gait follows a slower speed.
  float v_now;  // the same, unsmoothed: a stop shows in it a few frames sooner
  {
    float nx, ny;
    root_at(in, dt, nx, ny);
    const float vx = 0.5f * (nx - s.x) / dt, vy = 0.5f * (ny - s.y) / dt;
    v_now = pm::hypot(vx, vy);
    const float k = 1.0f - exp2_remembered(-dt / 0.08f);
    s.vx += (vx - s.vx) * k;
    s.vy += (vy - s.vy) * k;
  }
  const float v_path = pm::hypot(s.vx, s.vy);
  // Too slow for a flight phase: no foot leaves while the other is up, and
  // a body with both feet up comes down (below).
  const bool no_flight = std::min(v_path, v_now) < kFlightMinSpeed;
  // Players stop in a cycle or two: the gait slows down faster than it
  // speeds up, so that a stopped body does not keep running in the air.
  s.speed += (v_path - s.speed) * (1.0f - exp2_remembered(-dt / (v_path < s.speed ? 0.04f : 0.1f)));
  const GaitTiming gait = human_gait(s.speed, prm.cadence_cap, in.stamina);
  s.cycle_m = 2.0f * gait.step_length;
  s.run += (gait.run - s.run) * (1.0f - exp2_remembered(-dt / (gait.run < s.run ? 0.05f : 0.12f)));

  // Moving or standing. Standing players drift a little; the classifier's
  // stand/turn keeps them settling unless they clearly move.
  const bool want_move = (s.speed > prm.idle_speed && !in.rest) || s.speed > 1.0f;
  if (want_move && !s.moving) {
    // Start with the foot further behind (relative to the travel), which
    // will be the first to lift.
    float ux = s.vx, uy = s.vy;
    const float n = pm::hypot(ux, uy);
    if (n > 1e-4f) { ux /= n; uy /= n; }
    const float back0 = ux * (s.feet[0].x - in.x) + uy * (s.feet[0].y - in.y);
    const float back1 = ux * (s.feet[1].x - in.x) + uy * (s.feet[1].y - in.y);
    const bool right_first = !s.feet[0].planted ? true : (!s.feet[1].planted ? false : back0 <= back1);
    s.phase = right_first ? gait.duty : wrap01(gait.duty + 0.5f);
    s.moving = true;
  } else if (!want_move && s.moving && s.speed < prm.idle_speed * 0.8f) {
    s.moving = false;
  }
  const float dphase = s.moving ? 0.5f * gait.cadence * dt : 0.0f;
  s.phase = wrap01(s.phase + dphase);

  const int min_frames = static_cast<int>(std::ceil(2.0f / (prm.hard_cadence_cap * dt) - 1e-3f));
  float hip_nx, hip_ny;  // root at the next frame
  root_at(in, dt, hip_nx, hip_ny);
  const BodyFrame next_body(hip_nx, hip_ny, in.heading);

  // The pelvis a gait wants (before the legs' reach): lower when moving and
  // lower still when running.
  const float amp = s.moving ? clampf(s.speed / 1.5f, 0.0f, 1.0f) : 0.0f;
  const float stride_pelvis = 0.975f - 0.035f * amp * (1.0f - s.run) - 0.05f * s.run;

  // Where each planted foot's ankle stands as the frame starts: one that
  // lifts on this frame leaves from there, and the clients' blend with it.
  bool planted_before[2];
  float stood_x[2], stood_y[2];
  for (int i = 0; i < 2; ++i) {
    const FootState& f = s.feet[i];
    float h;
    planted_before[i] = f.planted;
    planted_ankle(f.x, f.y, f.yaw, f.pitch, stood_x[i], stood_y[i], h);
  }
  for (int i = 0; i < 2; ++i) {
    FootState& f = s.feet[i];
    FootState& o = s.feet[1 - i];
    ++f.since_landing;
    if (f.held) { f.release = f.leaving = false; continue; }
    if (f.planted) {
      f.stance_s += dt;
      // Pivot: a foot turned well away from the heading turns about its sole's centre.
      const float off = delta_deg(in.heading, f.yaw);
      if (std::fabs(off) > prm.pivot_deg && f.pitch == 0)
        f.yaw = wrap_deg(f.yaw + clampf(off - (off > 0 ? prm.pivot_deg : -prm.pivot_deg), -prm.pivot_rate_deg,
                                        prm.pivot_rate_deg));
      // Roll: heel strike levels off over 0.1 s; the heel rises through the
      // second half of a stride's stance (push-off).
      float progress = 0;
      if (s.moving) {
        const float fp = wrap01(s.phase - 0.5f * static_cast<float>(i));
        progress = fp < gait.duty ? fp / gait.duty : 1.0f;
      }
      if (f.pitch > 0) f.pitch = std::max(0.0f, f.pitch - 60.0f * dt);
      else if (s.moving) f.pitch = std::min(f.pitch, std::max(f.pitch - 240.0f * dt, -30.0f * smoothstep((progress - 0.55f) / 0.45f)));
      else f.pitch = std::min(0.0f, f.pitch + 60.0f * dt);
      // Lift off: the gait's phase, the caller's release, or the hip about to
      // leave the foot behind (pushing off from the toes).
      // The caller's release (the joint speed limit held the leg back)
      // lifts the foot only if the other one bears the body.
      bool go = f.release && (o.planted || s.run > 0.5f);
      float phase_left = 0.5f;
      if (s.moving) {
        const float fp = wrap01(s.phase - 0.5f * static_cast<float>(i));
        // A foot that landed late (its phase already past its stance) still
        // bears the body for half a stance: lifting it a frame after it
        // landed left both feet up through a stop (issue 23, floating).
        const bool due = fp >= gait.duty && f.stance_s > std::max(0.049f, 0.5f * gait.stance_s);
        // Walking: the other foot must be down first (double support).
        const bool support_ok = (s.run > 0.5f && !no_flight) || o.planted;
        phase_left = 1.0f - fp;
        float ax, ay, ah;
        planted_ankle(f.x, f.y, f.yaw, kMaxHeelRise, ax, ay, ah);
        const float hip_h = stride_pelvis - 0.03f - dims::kHipDrop;
        const float reach2 = std::max(prm.reach * prm.reach - (hip_h - ah) * (hip_h - ah), 0.0f);
        const auto beyond_reach = [&](const BodyFrame& hip) {
          float hx, hz;
          hip.to_body(ax, ay, hx, hz);
          hz -= kSide[i] * dims::kHipHalfWidth;
          return hx * hx + hz * hz > reach2;
        };
        // A foot the hip will have left out of reach at the next frame:
        // below kLeaveLateSpeed it lifts now; above, it still bears the body
        // on this frame (it is within reach) and lifts between the two. One
        // that landed on the last frame stays: its landing was within the
        // hip's reach of this frame (a foot that lifted again at once made a
        // step of 0.1 s, 8 steps/s).
        const bool late = s.speed > kLeaveLateSpeed;
        const bool out_of_reach =
            f.leaving || (late ? f.stance_s > 1.5f * dt && beyond_reach(body) : beyond_reach(next_body));
        f.leaving = late && !out_of_reach && beyond_reach(next_body);
        // Walking, a foot that is due waits for the other to land (that one
        // hurries, below) rather than leave the body in the air; one about to
        // be left out of reach goes anyway.
        if ((due && support_ok) || out_of_reach) go = true;
        if (due && !support_ok) o.hurry = true;
        if (out_of_reach && fp < gait.duty) phase_left = 1.0f - fp;  // leaves early: a longer swing
      } else {
        // Settling: the foot further from its resting spot steps, one at a
        // time, the other down for at least 0.15 s.
        f.leaving = false;
        float rx, ry;
        rest_spot(body, i, prm.foot_spacing, rx, ry);
        const float d = pm::hypot(f.x - rx, f.y - ry);
        const float dyaw = std::fabs(delta_deg(f.yaw, in.heading));
        float orx, ory;
        rest_spot(body, 1 - i, prm.foot_spacing, orx, ory);
        const float od = pm::hypot(o.x - orx, o.y - ory);
        const bool off_rest = d > prm.rest_tolerance || dyaw > prm.rest_yaw_tolerance;
        const bool my_turn = d >= od || !(od > prm.rest_tolerance);
        if (off_rest && my_turn && o.planted && o.stance_s >= 0.15f && f.stance_s >= 0.15f) go = true;
        phase_left = 0.5f;
      }
      if (go) {
        // Walking feet clear the grass; a sprinter's heel comes up behind to
        // half a metre (the swing's early peak, swing_bump).
        const float lift_m =
            s.moving ? 0.09f + 0.30f * s.run * clampf((std::min(s.speed, v_path) - 2.0f) / 6.0f, 0.0f, 1.0f) : 0.07f;
        lift(f, phase_left, lift_m);
        // This frame's share of the swing.
        f.u = 0;
      }
      if (f.planted) continue;
    }
    // In the air: progress, landing spot, touch-down.
    float du = s.moving ? dphase / f.phase_left : dt / kSettleSwingS;
    if (f.hurry) du = std::max(du, std::min(2.0f * du, 0.34f));  // the other foot waits for this one
    f.hurry = false;
    // A human cadence: the swing stretches so that the foot lands no sooner
    // than the cadence cap allows after its previous landing.
    {
      const int wait = min_frames - f.since_landing;
      if (wait > 0 && f.u + du * static_cast<float>(wait) >= 1.0f) du = (1.0f - f.u) / static_cast<float>(wait + 1);
    }
    // A body that has slowed below a run while both feet are up (a sprinter
    // stopping within a cycle or two) comes down: the foot further through
    // its swing covers at least half of what is left each frame instead of
    // finishing a flight that the speed no longer carries, cadence or not (a
    // stopping runner takes short quick steps). Forcing it down within two
    // frames measured worse: 15 % more ankle pops and a 60 Hz cadence p99 of
    // 5 steps/s, for 10 % fewer floating frames.
    const bool coming_down = s.moving && !o.planted && !o.held && no_flight && f.u >= o.u;
    if (coming_down) du = std::max(du, 0.5f * (1.0f - f.u) + 1e-3f);
    const float u0 = f.u;
    f.u = std::min(f.u + du, 1.0f);
    // Where it lands: under the hip at mid-stance (the root half a stance
    // after the touch-down), at most a comfortable reach ahead of the hip at
    // the touch-down, and on its own side of the other foot. Planned every
    // frame: the ankle only covers its share of what is left (below).
    {
      const float t_land = std::ceil(std::max(0.0f, (1.0f - f.u) / std::max(du, 1e-4f)) - 1e-3f) * dt;
      float mx, my, lx, ly;
      if (s.moving) {
        root_at(in, t_land + 0.5f * gait.stance_s, mx, my);
        root_at(in, t_land, lx, ly);
      } else {
        mx = lx = in.x;
        my = ly = in.y;
      }
      const BodyFrame land(lx, ly, in.heading);
      float bx, bz;
      land.to_body(mx, my, bx, bz);  // mid-stance root, seen from the landing root
      const float front = 0.30f + 0.05f * (1.0f - s.run);
      const float along = pm::hypot(bx, bz);
      if (along > front) { bx *= front / along; bz *= front / along; }
      bx += kSoleCentre;
      bz += kSide[i] * prm.foot_spacing;
      // The other foot, where it is or will be.
      float ox, oz;
      land.to_body(o.planted ? o.x : o.bx, o.planted ? o.y : o.by, ox, oz);
      if (kSide[i] * (bz - oz) < prm.min_gap) bz = oz + kSide[i] * prm.min_gap;
      // Nor do the soles cross at a toe or a heel when the other foot is
      // turned (it landed earlier in a turn: game 1 seq 2477). Measured only
      // when the other sole's ends, turned by its yaw, may come within
      // kSolesApartM sideways; on most frames they cannot.
      const float oyaw = (o.planted ? o.yaw : o.byaw) - in.heading;
      const float ends = kSoleHalf * std::fabs(pm::sin(oyaw * kDeg));
      for (int k = 0; k < 2 && kSide[i] * (bz - oz) - ends < kSolesApartM; ++k) {
        const float apart = soles_apart(bx, bz, 0.0f, ox, oz, oyaw);
        if (apart >= kSolesApartM) break;
        bz += kSide[i] * (kSolesApartM - apart + 0.005f);
      }
      float tx, ty;
      land.to_field(bx, bz, tx, ty);
      // Re-planned every frame: early in the swing the foot has barely left
      // (the ease is flat), late in it the look-ahead covers the landing.
      f.bx = tx;
      f.by = ty;
      f.byaw = in.heading;
      f.bpitch = s.moving ? 6.0f * (1.0f - s.run) : 0.0f;
    }
    // The ankle covers its share of what is left to the landing spot (so a
    // landing spot that moves never makes the foot jump), at most 0.85 m a
    // frame.
    {
      float tx, ty, th;
      planted_ankle(f.bx, f.by, f.byaw, f.bpitch, tx, ty, th);
      const float w0 = swing_ease(u0, s.run), w1 = swing_ease(f.u, s.run);
      const float frac = w0 < 0.9999f ? (w1 - w0) / (1.0f - w0) : 1.0f;
      float dx = (tx - f.cx) * frac, dy = (ty - f.cy) * frac;
      const float dn = pm::hypot(dx, dy);
      // Coming down early, the foot takes a shorter step rather than one
      // that jumps past the slowing body.
      const float max_step = coming_down ? 0.45f : 0.85f;
      if (dn > max_step) { dx *= max_step / dn; dy *= max_step / dn; }
      // Nor faster than a leg swings past the hip: at most kSwingPastHipM a
      // frame relative to the root. A landing spot re-planned far off in a
      // turn made the ankle jump 0.8 m past a pelvis that moved 0.2; the
      // foot now swings on to it (the extra frames below).
      const float pdx = in.x - s.x, pdy = in.y - s.y;
      const float rx = dx - pdx, ry = dy - pdy, rn = pm::hypot(rx, ry);
      const float past = f.u >= 1.0f && s.speed < kLandingBoundBelow ? kLandingPastHipM : kSwingPastHipM;
      if (rn > past) {
        dx = pdx + rx * past / rn;
        dy = pdy + ry * past / rn;
      }
      // It passes the other foot on its own side, a sole's width clear
      // (foot_passing.hpp).
      PassingStep pass;
      pass.side = kSide[i];
      pass.from_x = f.cx;
      pass.from_y = f.cy;
      float oh;
      if (o.planted) planted_ankle(o.x, o.y, o.yaw, o.pitch, pass.other_x, pass.other_y, oh);
      else { pass.other_x = o.cx; pass.other_y = o.cy; }
      pass.other_stood = planted_before[1 - i];
      pass.stood_x = stood_x[1 - i];
      pass.stood_y = stood_y[1 - i];
      pass.min_gap = prm.min_gap;
      pass.root_dx = pdx;
      pass.root_dy = pdy;
      pass.past_hip = past;
      f.cx += dx;
      f.cy += dy;
      pass_other_foot(body, pass, f.cx, f.cy);
    }
    // It lands on its spot, within reach of the hip at the next frame;
    // else it swings on for a frame (it stays up: swing_ankle's approach).
    if (f.u >= 1.0f) {
      float tx, ty, th;
      planted_ankle(f.bx, f.by, f.byaw, f.bpitch, tx, ty, th);
      float hx, hz;
      next_body.to_body(tx, ty, hx, hz);
      hz -= kSide[i] * dims::kHipHalfWidth;
      const float hip_h = stride_pelvis - 0.04f - dims::kHipDrop - th;
      const bool reachable = hx * hx + hz * hz + hip_h * hip_h <= prm.reach * prm.reach;
      const bool arrived = pm::hypot(tx - f.cx, ty - f.cy) <= 0.06f;
      if (!(reachable && arrived) && f.extra < 4) {
        f.u = 0.9f;
        ++f.extra;
      }
    }
    if (f.u >= 1.0f) {
      {
        // It lands where it is (the spot, unless the speed cap kept it short).
        const float ux = pm::cos(f.byaw * kDeg), uy = pm::sin(f.byaw * kDeg);
        float tx, ty, th;
        planted_ankle(f.bx, f.by, f.byaw, f.bpitch, tx, ty, th);
        f.bx += f.cx - tx;
        f.by += f.cy - ty;
        (void)ux; (void)uy;
        plant(f, f.bx, f.by, f.byaw, f.bpitch);
        f.since_landing = 0;
        ++s.steps;
      }
    }
  }

  // Output: the rhythm at the gait phase, the pelvis the gait wants, both
  // feet's ankles in body space.
  SampleGaitJob sample{gait_keys(), s.phase * kReferenceCycleM, &out.sample, nullptr, nullptr};
  sample.Run();
  const float pelvis = stride_pelvis +
                       amp * (0.012f * (1.0f - s.run) * out.sample.bob_walk + 0.025f * s.run * out.sample.bob_run);
  s.pelvis_height = pelvis;
  out.pelvis_height = pelvis;
  out.run = s.run;
  out.amplitude = amp;
  // Both feet up while the body is too slow for a flight (the gait's
  // smoothed speed, or the 2D body's own over this frame or the next:
  // RoboCup players' speed swings from cycle to cycle, a turn's cycle
  // slows them to a walk): the foot further through its swing reaches
  // down for the grass, its sole at most kReachDownSoleM up, rather than
  // leave the body hanging (issue 23, floating).
  const bool slow_frame = pm::hypot(in.x - s.x, in.y - s.y) < kFlightMinSpeed * dt ||
                          pm::hypot(hip_nx - in.x, hip_ny - in.y) < kFlightMinSpeed * dt;
  const bool both_up = !s.feet[0].planted && !s.feet[1].planted && !s.feet[0].held && !s.feet[1].held;
  const int reach_down = (no_flight || slow_frame) && both_up ? (s.feet[0].u >= s.feet[1].u ? 0 : 1) : -1;
  for (int i = 0; i < 2; ++i) {
    const FootState& f = s.feet[i];
    float ax, ay, ah, yaw, pitch;
    if (f.planted) {
      planted_ankle(f.x, f.y, f.yaw, f.pitch, ax, ay, ah);
      yaw = f.yaw;
      pitch = f.pitch;
    } else {
      swing_ankle(f, s.run, ax, ay, ah, yaw, pitch);
      if (i == reach_down) ah -= std::max(0.0f, sole_height(ah, pitch) - kReachDownSoleM);
    }
    to_target(body, ax, ay, ah, yaw, pitch, out.feet[i]);
    out.planted[i] = f.planted;
    out.reaching[i] = i == reach_down;
    out.sole_h[i] = f.planted ? 0.0f : std::max(0.0f, sole_height(ah, pitch));
  }
  s.x = in.x; s.y = in.y; s.heading = in.heading;
}

}  // namespace mc::anim
