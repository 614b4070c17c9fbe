// Fatigue on the body (issue 20; Seed 1, Virtual RoboCup, left it as future
// work). The stream's "stamina" message (once a second, SPEC.md 5.3) says
// how tired each player is; where the body is drawn, a tired player leans
// forward, swings his arms less, and at a stoppage, standing, puts his hands
// on his knees. The stream's angles stay as they are: this only changes how
// they are drawn, for anim's skeleton (matchcast-human-16; another skeleton
// is drawn as the stream says).
//
// Pure: no three.js (node tests it).

// How tired: 0 at 55 % of stamina_max and above, 1 at 20 % and below.
export function tiredness(stamina, staminaMax = 8000) {
  if (!Number.isFinite(stamina) || stamina < 0 || !(staminaMax > 0)) return 0;
  const s = stamina / staminaMax;
  return Math.max(0, Math.min(1, (0.55 - s) / 0.35));
}

// The hands-on-knees pose, absolute angles (degrees) by joint and axis:
// the trunk bent 60° (45° at the hips, 15° more in the torso), the thighs
// forward 35° and the shins back 35° (the feet flat), the arms down to the
// knees, the head up to watch the play. The pelvis drops by DROP metres so
// that the soles stay on the grass (anim/human_skeleton.hpp dimensions).
const BEND = 35 * Math.PI / 180, TILT = 45 * Math.PI / 180;
export const HANDS_ON_KNEES_DROP = 1.0 - (0.06 * Math.cos(TILT) + (0.44 + 0.42) * Math.cos(BEND) + 0.08);
const HANDS_ON_KNEES = {
  pelvis: { z: -45, y: 0, x: 0 }, torso: { z: -15, y: 0, x: 0 }, neck: { z: 25 }, head: { z: 12 },
  r_upper_arm: { z: 44, x: 6, y: 0 }, l_upper_arm: { z: 44, x: -6, y: 0 },
  r_lower_arm: { z: 8 }, l_lower_arm: { z: 8 },
  r_thigh: { z: 80, x: -5, y: 0 }, l_thigh: { z: 80, x: 5, y: 0 },
  r_shin: { z: -70 }, l_shin: { z: -70 }, r_foot: { z: 35, x: 0 }, l_foot: { z: 35, x: 0 },
};

export class FatiguePose {
  // skel: normalizeSkeleton() result.
  constructor(skel) {
    const at = (name, axis) => {
      const j = skel.joints.find((q) => q.name === name);
      const k = j ? j.dofs.indexOf(axis) : -1;
      return k < 0 ? -1 : j.angleIndex + k;
    };
    this.ok = skel.name === 'matchcast-human-16';
    this.torsoZ = at('torso', 'z');
    this.neckZ = at('neck', 'z');
    this.arms = [at('r_upper_arm', 'z'), at('l_upper_arm', 'z')];
    this.elbows = [at('r_lower_arm', 'z'), at('l_lower_arm', 'z')];
    this.pose = [];
    for (const [joint, axes] of Object.entries(HANDS_ON_KNEES))
      for (const [axis, deg] of Object.entries(axes)) {
        const i = at(joint, axis);
        if (i >= 0) this.pose.push([i, deg]);
      }
    this.state = new Map();   // key -> { x, y, speed, w }
  }

  // Changes `angles` (the drawn ones, in place) for player `p` ({x, y,
  // state, angles}) with tiredness `tired` (0..1), dt seconds after the
  // last picture; ctx: { stoppage (play is stopped), ball {x, y} }.
  // Returns how far the pelvis is lowered (metres, to subtract from p.z).
  apply(key, p, angles, tired, dt, ctx = {}) {
    if (!this.ok) return 0;
    let s = this.state.get(key);
    if (!s) { s = { x: p.x, y: p.y, speed: 0, w: 0 }; this.state.set(key, s); }
    if (dt > 0 && dt < 0.5) {
      const v = Math.hypot(p.x - s.x, p.y - s.y) / dt;
      s.speed += (v - s.speed) * Math.min(1, dt / 0.3);
    } else {
      s.speed = 0;
    }
    s.x = p.x; s.y = p.y;
    // Running tired: leaning forward, the head up, arms swinging less.
    if (tired > 0) {
      angles[this.torsoZ] -= 14 * tired;
      angles[this.neckZ] += 6 * tired;
      for (const i of this.arms) angles[i] = 5 + (angles[i] - 5) * (1 - 0.5 * tired);
      for (const i of this.elbows) angles[i] *= 1 - 0.35 * tired;
    }
    // At a stoppage, standing, away from the ball, and really tired: hands
    // on knees, eased in and out over half a second.
    const ball = ctx.ball;
    const nearBall = ball ? Math.hypot(p.x - ball.x, p.y - ball.y) < 4 : false;
    const goalie = (p.state & 0x8) !== 0;
    const want = ctx.stoppage && tired >= 0.5 && s.speed < 0.6 && !nearBall && !goalie ? 1 : 0;
    const step = dt > 0 && dt < 0.5 ? dt / 0.5 : 1;
    s.w = want > s.w ? Math.min(want, s.w + step) : Math.max(want, s.w - step);
    if (s.w <= 0) return 0;
    const w = s.w * s.w * (3 - 2 * s.w);   // smoothstep
    for (const [i, deg] of this.pose) angles[i] += (deg - angles[i]) * w;
    return HANDS_ON_KNEES_DROP * w;
  }
}
